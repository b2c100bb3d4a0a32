// The small dialog the simulator dock asks before it imports a measured trace: which CSV column
// holds each channel (1-based as a spreadsheet counts; "none" for an absent one), the header lines,
// the units of time, linear and rotary values, the separator, and how far the recorded Z is above
// the tool tip. Prefilled with sim::TraceColumns' defaults (seed 003's order, as camwb-cli sim
// --measured reads), or with what was used last.
#pragma once

#include "sim/MeasuredTrace.h"

#include <QDialog>

#include <array>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace camwb::gui {

class MeasuredImportDialog : public QDialog {
    Q_OBJECT
public:
    MeasuredImportDialog(const QString& file, const sim::TraceColumns& columns, double spindleFaceToTipMm,
                         QWidget* parent = nullptr);

    QString file() const { return m_file; }
    sim::TraceColumns columns() const;
    double spindleFaceToTipMm() const;

private:
    QString m_file;
    QSpinBox* m_time;
    std::array<std::array<QSpinBox*, 3>, 5> m_channels{};  // per axis: nominal, actual, deviation
    QSpinBox* m_headerLines;
    QComboBox* m_timeUnit;
    QComboBox* m_linearUnit;
    QComboBox* m_rotaryUnit;
    QComboBox* m_separator;
    QDoubleSpinBox* m_zOffset;
};

}  // namespace camwb::gui
