// Rows of a task panel bound to the fields of an operation's parameters: each widget writes its
// field and calls `changed` (the panel restarts the preview). Enums are combos, flags check
// boxes, lengths spin boxes in the display unit (LengthSpinBox: the field stays in mm). Rows
// can depend on others (enabled only when they apply).
#pragma once

#include <QComboBox>
#include <QString>

#include <functional>
#include <utility>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QFormLayout;
class QSpinBox;
class QWidget;

namespace camwb::gui {

class ParamForm {
public:
    ParamForm(QFormLayout* layout, std::function<void()> changed);

    QDoubleSpinBox* number(const QString& label, const char* objectName, double& field, double min, double max,
                           const QString& suffix, int decimals = 3);
    // A length: `field`, `min` and `max` in mm; shown in the display unit.
    QDoubleSpinBox* length(const QString& label, const char* objectName, double& field, double min, double max,
                           int mmDecimals = 3);
    QDoubleSpinBox* length(const QString& label, const char* objectName, double& field, double max = 1000)
    {
        return length(label, objectName, field, 0, max);
    }
    QSpinBox* count(const QString& label, const char* objectName, int& field, int min, int max);
    QCheckBox* flag(const QString& label, const char* objectName, bool& field, const QString& toolTip = {});
    // A row the panel keeps itself (not bound to a field: a value shown from elsewhere).
    void row(const QString& label, QWidget* widget);

    template <class Enum>
    QComboBox* choice(const QString& label, const char* objectName, Enum& field,
                      const std::vector<std::pair<QString, Enum>>& items)
    {
        QComboBox* box = addCombo(label, objectName);
        for (const auto& [text, value] : items) {
            box->addItem(text, static_cast<int>(value));
            if (value == field)
                box->setCurrentIndex(box->count() - 1);
        }
        bindCombo(box, [&field](int value) { field = static_cast<Enum>(value); });
        return box;
    }

    // `widget` is enabled only while `applies()` holds (re-checked after every change).
    void enableWhen(QWidget* widget, std::function<bool()> applies);
    void refresh();  // re-evaluates enableWhen

private:
    QDoubleSpinBox* bind(QDoubleSpinBox* box, const QString& label, const char* objectName, double& field, double min,
                         double max);
    QComboBox* addCombo(const QString& label, const char* objectName);
    void bindCombo(QComboBox* box, std::function<void(int)> write);
    void edited();

    QFormLayout* m_layout;
    std::function<void()> m_changed;
    std::vector<std::pair<QWidget*, std::function<bool()>>> m_conditions;
};

}  // namespace camwb::gui
