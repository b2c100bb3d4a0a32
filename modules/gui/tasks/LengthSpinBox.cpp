#include "gui/tasks/LengthSpinBox.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace camwb::gui {

LengthSpinBox::LengthSpinBox(QWidget* parent, int mmDecimals) :
    QDoubleSpinBox(parent),
    m_unit(displayUnit()),
    m_shownDecimals(mmDecimals + (displayUnit() == LengthUnit::Inch ? 1 : 0))
{
    setSuffix(QLatin1Char(' ') + unitSymbol(m_unit));
    if (m_unit == LengthUnit::Inch) {
        // The value stays in mm: two more decimals keep what the user types in inch (0.0001 in
        // = 0.00254 mm) from being rounded by QDoubleSpinBox's own rounding to decimals().
        setDecimals(mmDecimals + 2);
        setSingleStep(fromDisplayUnit(0.1, m_unit));
    } else {
        setDecimals(mmDecimals);
    }
}

QString LengthSpinBox::textFromValue(double mm) const
{
    if (m_unit == LengthUnit::Millimetre)
        return QDoubleSpinBox::textFromValue(mm);
    QLocale shown = locale();
    shown.setNumberOptions(shown.numberOptions() | QLocale::OmitGroupSeparator);
    return shown.toString(toDisplayUnit(mm, m_unit), 'f', m_shownDecimals);
}

QString LengthSpinBox::number(const QString& text) const
{
    QString n = text.trimmed();
    if (!prefix().isEmpty() && n.startsWith(prefix()))
        n.remove(0, prefix().size());
    const QString unit = suffix().trimmed();
    if (n.endsWith(unit))
        n.chop(unit.size());
    return n.trimmed();
}

double LengthSpinBox::valueFromText(const QString& text) const
{
    if (m_unit == LengthUnit::Millimetre)
        return QDoubleSpinBox::valueFromText(text);
    bool ok = false;
    const double shown = locale().toDouble(number(text), &ok);
    return ok ? fromDisplayUnit(shown, m_unit) : value();
}

QValidator::State LengthSpinBox::validate(QString& text, int& pos) const
{
    if (m_unit == LengthUnit::Millimetre)
        return QDoubleSpinBox::validate(text, pos);
    const QString n = number(text);
    const QString point = locale().decimalPoint();
    if (n.isEmpty() || n == QLatin1String("-") || n == QLatin1String("+") || n == point ||
        n == QLatin1Char('-') + point)
        return QValidator::Intermediate;
    bool ok = false;
    const double shown = locale().toDouble(n, &ok);
    if (!ok)
        return QValidator::Invalid;
    if (const qsizetype at = n.indexOf(point); at >= 0 && n.size() - at - 1 > m_shownDecimals)
        return QValidator::Invalid;
    const double mm = fromDisplayUnit(shown, m_unit);
    // Out of range but on the way to a value in it (typing 0.5 when the minimum is 0.1).
    const double slack = 1e-9 * std::max(1.0, std::abs(mm));
    return mm >= minimum() - slack && mm <= maximum() + slack ? QValidator::Acceptable : QValidator::Intermediate;
}

}  // namespace camwb::gui
