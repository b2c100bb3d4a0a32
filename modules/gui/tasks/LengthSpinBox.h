// A spin box for a length the job holds in mm, shown in the display unit (gui/shell/Preferences.h)
// of when it was made: value(), setValue(), setRange(), singleStep() and valueChanged() stay in
// mm, so the panels bind it as any spin box; its text, suffix ("mm", "in") and what the user types
// are in the display unit. In mm it behaves exactly as a QDoubleSpinBox.
#pragma once

#include "gui/shell/Preferences.h"

#include <QDoubleSpinBox>

namespace camwb::gui {

class LengthSpinBox : public QDoubleSpinBox {
public:
    // `mmDecimals`: the resolution in mm (3: µm); in inch it shows one decimal more.
    explicit LengthSpinBox(QWidget* parent = nullptr, int mmDecimals = 3);

    LengthUnit unit() const { return m_unit; }

protected:
    QString textFromValue(double mm) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;

private:
    // The number the user typed (prefix, suffix and spaces taken off), in the display unit.
    QString number(const QString& text) const;

    LengthUnit m_unit;
    int m_shownDecimals;
};

}  // namespace camwb::gui
