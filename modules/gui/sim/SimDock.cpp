#include "gui/sim/SimDock.h"

#include "gui/actions/ActionRegistry.h"
#include "gui/shell/Banner.h"
#include "gui/shell/Prompter.h"
#include "gui/sim/MeasuredImportDialog.h"
#include "gui/sim/SimChart.h"
#include "gui/sim/SimPlayer.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace camwb::gui {

namespace {

QString clock(double seconds)
{
    const int minutes = static_cast<int>(seconds / 60);
    return QStringLiteral("%1:%2").arg(minutes).arg(seconds - 60 * minutes, 4, 'f', 1, QLatin1Char('0'));
}

}  // namespace

SimDock::SimDock(SimPlayer* player, QWidget* parent) :
    QWidget(parent),
    m_player(player),
    m_buttons(new QToolBar(this)),
    m_speed(new QSlider(Qt::Horizontal, this)),
    m_speedLabel(new QLabel(this)),
    m_line(new QSpinBox(this)),
    m_readout(new QLabel(this)),
    m_cycle(new QLabel(this)),
    m_progress(new QProgressBar(this)),
    m_cancel(new QPushButton(tr("Cancel"), this)),
    m_banner(new Banner(QStringLiteral("simBanner"), this)),
    m_quantity(new QComboBox(this)),
    m_autoLimits(new QCheckBox(tr("Auto"), this)),
    m_low(new QDoubleSpinBox(this)),
    m_high(new QDoubleSpinBox(this)),
    m_deviationLimit(new QDoubleSpinBox(this)),
    m_resolution(new QDoubleSpinBox(this)),
    m_showTool(new QCheckBox(tr("Tool and holder"), this)),
    m_results(new QLabel(this)),
    m_measured(new QLabel(this)),
    m_chart(new SimChart(this))
{
    setObjectName(QStringLiteral("simDockContent"));
    m_buttons->setObjectName(QStringLiteral("simToolBar"));
    m_speed->setObjectName(QStringLiteral("simSpeed"));
    m_line->setObjectName(QStringLiteral("simLine"));
    m_readout->setObjectName(QStringLiteral("simReadout"));
    m_cycle->setObjectName(QStringLiteral("simCycleTime"));
    m_progress->setObjectName(QStringLiteral("simProgress"));
    m_cancel->setObjectName(QStringLiteral("simCancel"));
    m_chart->setObjectName(QStringLiteral("simChart"));
    m_results->setObjectName(QStringLiteral("simResults"));
    m_measured->setObjectName(QStringLiteral("simMeasured"));

    m_speed->setRange(0, 100);
    m_speed->setValue(50);  // 10x
    m_speed->setMaximumWidth(160);
    m_line->setRange(1, 99999999);
    m_line->setPrefix(tr("line "));
    m_progress->hide();
    m_cancel->hide();
    m_showTool->setObjectName(QStringLiteral("simShowTool"));
    m_showTool->setChecked(true);
    connect(m_showTool, &QCheckBox::toggled, m_player, &SimPlayer::setToolVisible);

    auto* top = new QHBoxLayout;
    top->addWidget(m_buttons);
    top->addWidget(m_line);
    top->addWidget(new QLabel(tr("Speed"), this));
    top->addWidget(m_speed);
    top->addWidget(m_speedLabel);
    top->addWidget(m_showTool);
    top->addStretch(1);
    auto* status = new QHBoxLayout;
    status->addWidget(m_readout, 1);
    status->addWidget(m_cycle);
    status->addWidget(m_progress);
    status->addWidget(m_cancel);
    auto* body = new QHBoxLayout;
    body->addWidget(makeResults());
    body->addWidget(m_chart, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addWidget(m_banner);
    layout->addLayout(top);
    layout->addLayout(status);
    layout->addLayout(body, 1);

    auto speed = [this](int value) {
        m_player->setSpeed(speedOfSlider(value));
        m_speedLabel->setText(tr("%1×").arg(speedOfSlider(value), 0, 'g', 3));
    };
    connect(m_speed, &QSlider::valueChanged, this, speed);
    speed(m_speed->value());
    connect(m_cancel, &QPushButton::clicked, m_player, &SimPlayer::cancel);
    connect(m_player, &SimPlayer::buildStarted, this, [this] {
        m_progress->setValue(0);
        m_progress->show();
        m_cancel->show();
    });
    connect(m_player, &SimPlayer::buildProgress, this, [this](int percent) {
        m_progress->setValue(percent);
        if (percent < 0) {  // cancelled
            m_progress->hide();
            m_cancel->hide();
        }
    });
    connect(m_player, &SimPlayer::ready, this, [this] {
        m_progress->hide();
        m_cancel->hide();
        updateQuantities();
        updateReadout();
        updateDeviation();
        updateBanner();
    });
    connect(m_player, &SimPlayer::cleared, this, [this] {
        updateQuantities();
        updateReadout();
        updateDeviation();
        updateBanner();
    });
    connect(m_player, &SimPlayer::positionChanged, this, &SimDock::updateReadout);
    connect(m_player, &SimPlayer::deviationReady, this, &SimDock::updateDeviation);
    connect(m_player, &SimPlayer::outOfDateChanged, this, &SimDock::updateBanner);
    connect(m_player, &SimPlayer::measuredChanged, this, [this] {
        updateMeasured();
        updateBanner();
    });
    updateReadout();
}

QWidget* SimDock::makeResults()
{
    auto* box = new QWidget(this);
    auto* form = new QFormLayout(box);
    form->setContentsMargins(0, 0, 0, 0);
    m_quantity->setObjectName(QStringLiteral("simQuantity"));
    m_autoLimits->setObjectName(QStringLiteral("simAutoLimits"));
    m_low->setObjectName(QStringLiteral("simLow"));
    m_high->setObjectName(QStringLiteral("simHigh"));
    m_deviationLimit->setObjectName(QStringLiteral("simDeviationLimit"));
    m_autoLimits->setChecked(true);
    for (QDoubleSpinBox* box : {m_low, m_high}) {
        box->setRange(-1e9, 1e9);
        box->setDecimals(3);
        box->setEnabled(false);
    }
    m_deviationLimit->setRange(0.001, 100);
    m_deviationLimit->setDecimals(3);
    m_deviationLimit->setSingleStep(0.05);
    m_deviationLimit->setValue(m_player->deviationLimit());
    m_deviationLimit->setSuffix(tr(" mm"));
    m_resolution->setObjectName(QStringLiteral("simResolution"));
    m_resolution->setRange(0.02, 5);
    m_resolution->setDecimals(2);
    m_resolution->setSingleStep(0.05);
    m_resolution->setValue(0.25);
    m_resolution->setSuffix(tr(" mm"));
    m_resolution->setToolTip(tr("The stock's cell size for the next simulation"));
    auto* limits = new QHBoxLayout;
    limits->addWidget(m_autoLimits);
    limits->addWidget(m_low);
    limits->addWidget(m_high);
    form->addRow(tr("Colour path by"), m_quantity);
    form->addRow(tr("Limits"), limits);
    form->addRow(tr("Deviation ±"), m_deviationLimit);
    form->addRow(tr("Stock resolution"), m_resolution);

    form->addRow(m_results);
    m_results->setWordWrap(true);
    form->addRow(m_measured);
    m_measured->setWordWrap(true);
    m_measured->hide();

    connect(m_quantity, &QComboBox::currentIndexChanged, this, &SimDock::applyQuantity);
    connect(m_autoLimits, &QCheckBox::toggled, this, [this](bool autoLimits) {
        m_low->setEnabled(!autoLimits);
        m_high->setEnabled(!autoLimits);
        applyQuantity();
    });
    for (QDoubleSpinBox* spin : {m_low, m_high})
        connect(spin, &QDoubleSpinBox::editingFinished, this, &SimDock::applyQuantity);
    connect(m_deviationLimit, &QDoubleSpinBox::valueChanged, m_player, &SimPlayer::setDeviationLimit);
    box->setMaximumWidth(440);
    return box;
}

void SimDock::addActions(const ActionRegistry& registry)
{
    for (const char* id :
         {"Cam.Sim.Start", "Cam.Sim.Play", "Cam.Sim.Pause", "Cam.Sim.StepBack", "Cam.Sim.StepForward",
          "Cam.Sim.JumpToLine", "Cam.Sim.MachineFrame", "Cam.Sim.ImportMeasured", "Cam.Sim.ClearMeasured"})
        if (QAction* action = registry.action(QLatin1String(id)))
            m_buttons->addAction(action);
}

int SimDock::lineToJumpTo() const { return m_line->value(); }

double SimDock::resolutionMm() const { return m_resolution->value(); }

double SimDock::speedOfSlider(int value) { return std::pow(10.0, -1.0 + 4.0 * value / 100.0); }

void SimDock::updateReadout()
{
    const auto run = m_player->run();
    if (!run) {
        m_readout->setText(m_player->isBuilding() ? tr("Simulating…") : tr("No simulation: press Simulate"));
        m_cycle->clear();
        return;
    }
    const Timeline& timeline = run->timeline;
    const MovePoint at = m_player->point();
    const int line = m_player->currentLine();
    const QString where = line > 0 ? tr("line %1").arg(line) : tr("no line");
    const QString moves = tr("move %1 of %2").arg(at.move + 1).arg(timeline.moveCount());
    m_readout->setText(tr("%1 / %2 · %3 · %4").arg(clock(m_player->position()), clock(timeline.total()), where, moves));
    m_cycle->setText(
        tr("Cycle time %1 (distance / feed estimate %2)").arg(clock(run->cycleSeconds), clock(run->simpleSeconds)));
}

void SimDock::updateQuantities()
{
    const QSignalBlocker block(m_quantity);
    m_quantity->clear();
    m_quantity->addItem(tr("Moves (rapid / feed)"), QString());
    for (const QString& id : m_player->quantityIds())
        m_quantity->addItem(m_player->quantityLabel(id), id);
    m_quantity->setEnabled(m_quantity->count() > 1);
}

void SimDock::applyQuantity()
{
    const QString id = m_quantity->currentData().toString();
    std::optional<std::pair<double, double>> limits;
    if (!m_autoLimits->isChecked())
        limits = std::make_pair(m_low->value(), m_high->value());
    m_player->showQuantity(id, limits);
    if (m_autoLimits->isChecked() && !m_player->quantity().isEmpty()) {
        const QSignalBlocker a(m_low), b(m_high);
        m_low->setValue(m_player->quantityRange().first);
        m_high->setValue(m_player->quantityRange().second);
    }
}

void SimDock::updateDeviation()
{
    const auto deviation = m_player->deviation();
    const auto run = m_player->run();
    if (!run || !run->stock) {
        m_results->setText(run ? tr("No stock: the tool plays over the path only.") : QString());
        return;
    }
    if (!deviation) {
        m_results->setText(run->hasDesign ? tr("The deviation map shows when the end of the program is cut.")
                                          : tr("No model to compare the stock with."));
        return;
    }
    auto place = [&run](double mm, std::int64_t move) {
        const int line = move >= 0 ? run->timeline.lineOf(static_cast<std::size_t>(move)) : -1;
        return line > 0 ? tr("%1 mm (line %2)").arg(mm, 0, 'f', 3).arg(line) : tr("%1 mm").arg(mm, 0, 'f', 3);
    };
    m_results->setText(tr("At the program's end: largest gouge %1 · largest leftover %2 · %3 mm beside the part")
                           .arg(place(deviation->maxGougeMm, deviation->gougeMove),
                                place(deviation->maxLeftoverMm, deviation->leftoverMove))
                           .arg(deviation->maxOutsideMm, 0, 'f', 3));
}

void SimDock::updateBanner()
{
    QStringList lines;
    // A stock too fine for this computer is the user's setting to change: said where it is seen.
    if (const auto run = m_player->run(); run && !run->stockError.empty())
        lines << QString::fromStdString(run->stockError);
    if (m_player->isOutOfDate())
        lines << tr("Out of date: the program was changed after it was simulated. Simulate again to see what it "
                    "does now.");
    if (m_player->isMeasuredOutOfDate())
        lines << tr("The measured trace was recorded for the program as it was before the change: import a trace "
                    "of this program, or clear it.");
    m_banner->setMessage(lines.join(QLatin1Char('\n')));
}

void SimDock::importMeasured(Prompter& prompter)
{
    const QString title = tr("Import a Measured Trace");
    if (!m_player->hasRun()) {
        prompter.showError(title, tr("Simulate the program first: a measured trace is carried onto the workpiece "
                                     "through the simulation's machine and compared with its path."));
        return;
    }
    const QString file = prompter.openFileName(title, tr("Measured traces (*.csv *.txt);;All files (*)"));
    if (file.isEmpty())
        return;
    auto* dialog = new MeasuredImportDialog(file, m_measuredColumns, m_measuredZOffsetMm, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, &prompter, title] {
        const QString error = m_player->importMeasured(dialog->file(), dialog->columns(), dialog->spindleFaceToTipMm());
        if (!error.isEmpty()) {
            prompter.showError(title, error);
            return;
        }
        m_measuredColumns = dialog->columns();
        m_measuredZOffsetMm = dialog->spindleFaceToTipMm();
        // Show what was imported: the actual path coloured by how far it followed the nominal one.
        // (Already chosen, for an earlier trace: coloured again by the new one.)
        const int index = m_quantity->findData(QString::fromLatin1(kMeasuredFollowingId));
        if (index >= 0 && index == m_quantity->currentIndex())
            applyQuantity();
        else if (index >= 0)
            m_quantity->setCurrentIndex(index);
    });
    dialog->open();
}

void SimDock::updateMeasured()
{
    const auto measured = m_player->measured();
    const QString current = m_quantity->currentData().toString();
    updateQuantities();
    const int index = m_quantity->findData(current);
    if (index >= 0 && index != m_quantity->currentIndex())
        m_quantity->setCurrentIndex(index);
    m_measured->setVisible(measured != nullptr);
    if (!measured)
        return;
    double following = 0, toProgram = -1;
    for (const SampledQuantity& q : measured->quantities) {
        const double top = q.values.empty() ? 0 : *std::max_element(q.values.begin(), q.values.end());
        (q.id == kMeasuredFollowingId ? following : toProgram) = top;
    }
    QString text = tr("Measured %1: %2 samples, %3 s; actual to nominal up to %4 mm")
                       .arg(QFileInfo(QString::fromStdString(measured->path)).fileName())
                       .arg(measured->trace.time.size())
                       .arg(measured->trace.time.back() - measured->trace.time.front(), 0, 'f', 2)
                       .arg(following, 0, 'f', 4);
    if (toProgram >= 0)
        text += tr(", to the program up to %1 mm").arg(toProgram, 0, 'f', 4);
    m_measured->setText(text);
}

}  // namespace camwb::gui
