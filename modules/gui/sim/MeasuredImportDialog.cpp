#include "gui/sim/MeasuredImportDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace camwb::gui {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A column as the user counts it: 1 the first, 0 "none" (sim::TraceColumns: 0-based, -1 none).
QSpinBox* columnBox(int column, QWidget* parent)
{
    auto* box = new QSpinBox(parent);
    box->setRange(0, 999);
    box->setSpecialValueText(MeasuredImportDialog::tr("none"));
    box->setValue(column + 1);
    return box;
}

// A unit choice whose data is the factor to the kernel's unit; the current one is `factor`'s.
QComboBox* unitBox(const std::vector<std::pair<QString, double>>& units, double factor, QWidget* parent)
{
    auto* box = new QComboBox(parent);
    for (const auto& [name, f] : units)
        box->addItem(name, f);
    for (int i = 0; i < box->count(); ++i)
        if (std::abs(box->itemData(i).toDouble() - factor) < 1e-12 * std::max(1.0, factor))
            box->setCurrentIndex(i);
    return box;
}

}  // namespace

MeasuredImportDialog::MeasuredImportDialog(const QString& file, const sim::TraceColumns& columns,
                                           double spindleFaceToTipMm, QWidget* parent) :
    QDialog(parent),
    m_file(file),
    m_time(columnBox(columns.time, this)),
    m_headerLines(new QSpinBox(this)),
    m_timeUnit(unitBox({{tr("s"), 1.0}, {tr("ms"), 0.001}}, columns.timeScale, this)),
    m_linearUnit(unitBox({{tr("mm"), 1.0}, {tr("µm"), 0.001}, {tr("inch"), 25.4}}, columns.linearScale, this)),
    m_rotaryUnit(unitBox({{tr("degrees"), 1.0}, {tr("radians"), 180 / kPi}}, columns.rotaryScale, this)),
    m_separator(new QComboBox(this)),
    m_zOffset(new QDoubleSpinBox(this))
{
    setObjectName(QStringLiteral("measuredImportDialog"));
    setWindowTitle(tr("Import a Measured Trace"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("%1: which column holds each channel (the first column is 1). The nominal and actual "
                                "positions are carried through the simulation's machine onto the workpiece.")
                                 .arg(QFileInfo(file).fileName()),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("Nominal"), this), 0, 1);
    grid->addWidget(new QLabel(tr("Actual"), this), 0, 2);
    grid->addWidget(new QLabel(tr("Deviation"), this), 0, 3);
    const QString axes[5]{tr("X"), tr("Y"), tr("Z"), tr("1st rotary (A/B)"), tr("2nd rotary (C)")};
    for (int c = 0; c < 5; ++c) {
        grid->addWidget(new QLabel(axes[c], this), c + 1, 0);
        const int source[3]{columns.nominal[c], columns.actual[c], columns.deviation[c]};
        for (int k = 0; k < 3; ++k) {
            m_channels[c][k] = columnBox(source[k], this);
            m_channels[c][k]->setObjectName(QStringLiteral("measuredColumn%1%2").arg(c).arg(k));
            grid->addWidget(m_channels[c][k], c + 1, k + 1);
        }
    }
    layout->addLayout(grid);

    auto* form = new QFormLayout;
    m_time->setObjectName(QStringLiteral("measuredTimeColumn"));
    form->addRow(tr("Time column"), m_time);
    m_headerLines->setRange(0, 1000);
    m_headerLines->setValue(columns.headerLines);
    m_headerLines->setObjectName(QStringLiteral("measuredHeaderLines"));
    form->addRow(tr("Header lines"), m_headerLines);
    form->addRow(tr("Time in"), m_timeUnit);
    form->addRow(tr("Linear axes in"), m_linearUnit);
    form->addRow(tr("Rotary axes in"), m_rotaryUnit);
    m_separator->addItem(tr("Automatic (; then tab then ,)"), 0);
    m_separator->addItem(tr("Semicolon (decimal comma allowed)"), int(';'));
    m_separator->addItem(tr("Tab (decimal comma allowed)"), int('\t'));
    m_separator->addItem(tr("Comma"), int(','));
    m_separator->setCurrentIndex(std::max(0, m_separator->findData(int(columns.separator))));
    form->addRow(tr("Separator"), m_separator);
    m_zOffset->setRange(-10000, 10000);
    m_zOffset->setDecimals(3);
    m_zOffset->setSuffix(tr(" mm"));
    m_zOffset->setValue(spindleFaceToTipMm);
    m_zOffset->setObjectName(QStringLiteral("measuredZOffset"));
    m_zOffset->setToolTip(tr("Subtracted from the recorded Z: the tool length where the control recorded the spindle "
                             "face, 0 where it recorded the tool tip"));
    form->addRow(tr("Z above the tool tip"), m_zOffset);
    layout->addLayout(form);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

sim::TraceColumns MeasuredImportDialog::columns() const
{
    sim::TraceColumns c;
    c.time = m_time->value() - 1;
    for (int a = 0; a < 5; ++a) {
        c.nominal[a] = m_channels[a][0]->value() - 1;
        c.actual[a] = m_channels[a][1]->value() - 1;
        c.deviation[a] = m_channels[a][2]->value() - 1;
    }
    c.headerLines = m_headerLines->value();
    c.timeScale = m_timeUnit->currentData().toDouble();
    c.linearScale = m_linearUnit->currentData().toDouble();
    c.rotaryScale = m_rotaryUnit->currentData().toDouble();
    c.separator = static_cast<char>(m_separator->currentData().toInt());
    return c;
}

double MeasuredImportDialog::spindleFaceToTipMm() const { return m_zOffset->value(); }

}  // namespace camwb::gui
