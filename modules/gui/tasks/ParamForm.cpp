#include "gui/tasks/ParamForm.h"

#include "gui/tasks/LengthSpinBox.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

namespace camwb::gui {

ParamForm::ParamForm(QFormLayout* layout, std::function<void()> changed) :
    m_layout(layout),
    m_changed(std::move(changed))
{
}

QDoubleSpinBox* ParamForm::number(const QString& label, const char* objectName, double& field, double min, double max,
                                  const QString& suffix, int decimals)
{
    auto* box = new QDoubleSpinBox;
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    return bind(box, label, objectName, field, min, max);
}

QDoubleSpinBox* ParamForm::length(const QString& label, const char* objectName, double& field, double min, double max,
                                  int mmDecimals)
{
    return bind(new LengthSpinBox(nullptr, mmDecimals), label, objectName, field, min, max);
}

QDoubleSpinBox* ParamForm::bind(QDoubleSpinBox* box, const QString& label, const char* objectName, double& field,
                                double min, double max)
{
    box->setObjectName(QLatin1String(objectName));
    box->setRange(min, max);
    box->setValue(field);
    box->setKeyboardTracking(false);  // one preview per finished number, not per digit
    QObject::connect(box, &QDoubleSpinBox::valueChanged, box, [this, &field](double value) {
        field = value;
        edited();
    });
    m_layout->addRow(label, box);
    return box;
}

QSpinBox* ParamForm::count(const QString& label, const char* objectName, int& field, int min, int max)
{
    auto* box = new QSpinBox;
    box->setObjectName(QLatin1String(objectName));
    box->setRange(min, max);
    box->setValue(field);
    box->setKeyboardTracking(false);
    QObject::connect(box, &QSpinBox::valueChanged, box, [this, &field](int value) {
        field = value;
        edited();
    });
    m_layout->addRow(label, box);
    return box;
}

QCheckBox* ParamForm::flag(const QString& label, const char* objectName, bool& field, const QString& toolTip)
{
    auto* box = new QCheckBox(label);
    box->setObjectName(QLatin1String(objectName));
    box->setChecked(field);
    box->setToolTip(toolTip);
    QObject::connect(box, &QCheckBox::toggled, box, [this, &field](bool on) {
        field = on;
        edited();
    });
    m_layout->addRow(QString(), box);
    return box;
}

void ParamForm::row(const QString& label, QWidget* widget) { m_layout->addRow(label, widget); }

QComboBox* ParamForm::addCombo(const QString& label, const char* objectName)
{
    auto* box = new QComboBox;
    box->setObjectName(QLatin1String(objectName));
    m_layout->addRow(label, box);
    return box;
}

void ParamForm::bindCombo(QComboBox* box, std::function<void(int)> write)
{
    QObject::connect(box, &QComboBox::currentIndexChanged, box, [this, box, write = std::move(write)] {
        write(box->currentData().toInt());
        edited();
    });
}

void ParamForm::enableWhen(QWidget* widget, std::function<bool()> applies)
{
    m_conditions.emplace_back(widget, std::move(applies));
    widget->setEnabled(m_conditions.back().second());
}

void ParamForm::refresh()
{
    for (const auto& [widget, applies] : m_conditions)
        widget->setEnabled(applies());
}

void ParamForm::edited()
{
    refresh();
    m_changed();
}

}  // namespace camwb::gui
