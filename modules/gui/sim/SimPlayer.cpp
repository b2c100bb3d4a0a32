#include "gui/sim/SimPlayer.h"

#include "document/Simulate.h"
#include "gui/editor/NcEditor.h"
#include "gui/sim/SimChart.h"
#include "gui/sim/SimOverlay.h"
#include "gui/sim/StockAnimation.h"
#include "gui/view3d/View3D.h"

#include <QFutureWatcher>
#include <QPointer>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace camwb::gui {

namespace {

constexpr int kTickMs = 15;  // up to ~60 playback steps a second; the view coalesces repaints

}  // namespace

SimPlayer::SimPlayer(QObject* parent) : QObject(parent), m_timer(new QTimer(this))
{
    m_timer->setInterval(kTickMs);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &SimPlayer::tick);
}

SimPlayer::~SimPlayer()
{
    if (m_cancel)
        m_cancel->store(true);
}

void SimPlayer::attach(NcEditor* editor, View3D* view, SimChart* chart)
{
    m_editor = editor;
    m_view = view;
    m_chart = chart;
    if (m_editor != nullptr) {
        // The editor may report the line the playback moved it to later (Scintilla's update
        // notification): that line is where the playback is already, not a jump.
        connect(m_editor, &NcEditor::cursorLineChanged, this, [this](int line) {
            if (!m_movingEditor && m_run && !m_outOfDate && line != m_shownLine)
                jumpToLine(line);
        });
        connect(m_editor, &NcEditor::textChanged, this, [this] {
            if (m_run)
                markOutOfDate();
            if (m_measured)
                m_editedSinceMeasured = true;
        });
    }
    if (m_view != nullptr) {
        connect(m_view, &View3D::segmentPicked, this, [this](int, int record) {
            if (m_run && !m_outOfDate && record >= 0)
                jumpToRecord(static_cast<std::size_t>(record));
        });
        connect(m_view, &View3D::frameRendered, this, &SimPlayer::countFrame);
    }
    if (m_chart != nullptr)
        connect(m_chart, &SimChart::timeClicked, this, &SimPlayer::seek);
}

void SimPlayer::start(SimRunRequest request)
{
    if (m_cancel)
        m_cancel->store(true);
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    m_cancel = cancel;
    const quint64 generation = ++m_generation;
    m_building = true;
    emit buildStarted();
    request.cancel = cancel.get();
    QPointer<SimPlayer> self(this);
    request.progress = [self, generation](int percent) {
        QMetaObject::invokeMethod(
            self,
            [self, generation, percent] {
                if (self && self->m_generation == generation)
                    emit self->buildProgress(percent);
            },
            Qt::QueuedConnection);
    };
    auto* watcher = new QFutureWatcher<std::shared_ptr<SimRun>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation] {
        watcher->deleteLater();
        finishBuild(watcher->result(), generation);
    });
    // The cancel flag lives as long as the worker (the request points at it).
    watcher->setFuture(QtConcurrent::run([request, cancel] { return buildSimRun(request); }));
}

void SimPlayer::cancel()
{
    if (m_cancel)
        m_cancel->store(true);
}

void SimPlayer::finishBuild(std::shared_ptr<SimRun> run, quint64 generation)
{
    if (generation != m_generation)
        return;  // a newer simulation was asked for
    m_building = false;
    m_cancel = nullptr;
    if (!run) {
        emit message(base::Severity::Note, tr("Simulation cancelled"));
        emit buildProgress(-1);
        return;
    }
    // A measured trace stays over a new simulation, carried through its machine again; if the
    // program was changed in between, it is of the program as it was.
    std::shared_ptr<const MeasuredRun> measured = m_measured;
    const bool measuredOutOfDate = m_measuredOutOfDate || m_editedSinceMeasured;
    clear();
    m_run = std::move(run);
    for (const std::string& note : m_run->notes)
        emit message(base::Severity::Warning, QString::fromStdString(note));
    if (m_view != nullptr) {
        SimOverlay& overlay = m_view->simulation();
        overlay.setPath(&m_run->moves);
        overlay.setTools(m_run->toolParts);
        overlay.setTable(rotaryTableOf(*m_run));
        m_view->setSimulationShown(m_run->stock != nullptr);
    }
    if (m_run->stock) {
        m_stock = std::make_unique<StockAnimation>(m_run);
        m_shownFrame = nullptr;
        connect(m_stock.get(), &StockAnimation::frameReady, this, &SimPlayer::showStockFrame);
    }
    reportChecks();
    if (measured) {
        m_measured = std::make_shared<const MeasuredRun>(
            carryMeasured(measured->trace, measured->path, measured->columns, measured->spindleFaceToTipMm, *m_run));
        m_measuredOutOfDate = measuredOutOfDate;
        showMeasured();
    }
    m_position = 0;
    apply();
    emit ready();
    if (measured)
        emit measuredChanged();
}

// The checks into the report as file:line findings (the first 50; air cutting is counted only),
// and their errors as markers in the view.
void SimPlayer::reportChecks()
{
    constexpr int kReported = 50;
    int reported = 0, errors = 0, warnings = 0;
    std::vector<base::Vec3> markers;
    for (const sim::Check& check : m_run->checks) {
        errors += check.severity == base::Severity::Error ? 1 : 0;
        warnings += check.severity == base::Severity::Warning ? 1 : 0;
        if (check.severity == base::Severity::Error && check.move >= 0)
            markers.push_back(check.at);
        if (check.kind == sim::CheckKind::AirCutting || reported++ >= kReported)
            continue;
        const document::RecordPlace place = document::placeOfRecord(*m_run->trace, check.record);
        emit message(check.severity, QString::fromStdString(base::formatDiagnostic(
                                         {check.severity, place.file, place.line, 0, check.message})));
    }
    if (m_view != nullptr)
        m_view->simulation().showFindings(markers);
    emit message(errors > 0 ? base::Severity::Error : base::Severity::Note,
                 tr("Simulated %1: cycle time %2 s, errors: %3, warnings: %4")
                     .arg(QString::fromStdString(m_run->programName))
                     .arg(m_run->cycleSeconds, 0, 'f', 1)
                     .arg(errors)
                     .arg(warnings));
}

std::optional<sim::Deviation> SimPlayer::deviation() const
{
    if (m_deviation)
        return m_deviation;
    return m_run ? m_run->deviation : std::nullopt;
}

void SimPlayer::clear()
{
    pause();
    m_stock.reset();
    m_shownFrame = nullptr;
    m_run = nullptr;
    m_deviation.reset();
    m_measured = nullptr;
    m_editedSinceMeasured = m_measuredOutOfDate = false;
    m_quantity.clear();
    m_shownLine = -1;
    m_position = 0;
    if (m_outOfDate) {
        m_outOfDate = false;
        emit outOfDateChanged(false);
    }
    if (m_view != nullptr) {
        m_view->simulation().clear();
        m_view->setWorkpieceMotion({});
        m_view->setSimulationShown(false);
    }
    m_frameMoved = false;
    if (m_chart != nullptr)
        m_chart->setSeries({}, {}, {});
    emit cleared();
    emit measuredChanged();
}

void SimPlayer::markOutOfDate()
{
    if (m_outOfDate)
        return;
    m_outOfDate = true;
    emit outOfDateChanged(true);
}

void SimPlayer::play()
{
    if (!m_run || m_playing)
        return;
    if (atEnd())
        seek(0);
    m_playing = true;
    m_clock.start();
    m_statsClock.start();
    m_stats = {};
    m_stockFrames = 0;
    m_stockMeshSeconds = 0;
    m_updates = 0;
    m_updateSeconds = 0;
    m_timer->start();
    emit playingChanged(true);
}

void SimPlayer::pause()
{
    if (!m_playing)
        return;
    m_playing = false;
    m_timer->stop();
    emit playingChanged(false);
}

void SimPlayer::tick()
{
    QElapsedTimer started;
    started.start();
    const double elapsed = m_clock.nsecsElapsed() * 1e-9;
    m_clock.restart();
    m_position = std::min(m_position + elapsed * m_speed, m_run->timeline.total());
    apply();
    countUpdate(started);
    if (atEnd())
        pause();
}

void SimPlayer::stepForward()
{
    if (m_run)
        seek(m_run->timeline.nextBlock(m_position));
}

void SimPlayer::stepBack()
{
    if (m_run)
        seek(m_run->timeline.previousBlock(m_position));
}

// The first run of the line, or of the next line that moves the machine.
void SimPlayer::jumpToLine(int line)
{
    if (!m_run || !m_run->trace)
        return;
    const auto& lineRecords = m_run->trace->lineRecords;
    auto it = std::lower_bound(lineRecords.begin(), lineRecords.end(), std::make_pair(line, std::uint32_t{0}));
    if (it != lineRecords.end())
        jumpToRecord(it->second);
}

void SimPlayer::jumpToRecord(std::size_t record)
{
    if (!m_run)
        return;
    const std::size_t move = m_run->timeline.firstMoveOfRecord(record);
    seek(move < m_run->timeline.moveCount() ? m_run->timeline.start(move) : m_run->timeline.total());
}

void SimPlayer::seek(double position)
{
    if (!m_run)
        return;
    m_position = std::clamp(position, 0.0, m_run->timeline.total());
    apply();
}

bool SimPlayer::atEnd() const { return m_run && m_position >= m_run->timeline.total(); }

MovePoint SimPlayer::point() const { return m_run ? m_run->timeline.pointAt(m_position) : MovePoint{}; }

int SimPlayer::currentLine() const { return m_run ? m_run->timeline.lineOf(point().move) : -1; }

void SimPlayer::setSpeed(double factor) { m_speed = std::max(factor, 1e-3); }

// Everything that follows the position: tool, path, stock, editor, chart.
void SimPlayer::apply()
{
    const MovePoint at = point();
    const ToolPose pose = m_run->timeline.poseAt(at);
    if (m_view != nullptr) {
        // The machine frame moves the workpiece side by the table's pose; the tool's pose is
        // given in the frame shown (the path is drawn in work coordinates, its actors moved).
        ToolPose shown = pose;
        if (showsMachineFrame()) {
            const kinematics::RigidMotion motion = machineFrameAt(*m_run, at);
            m_view->setWorkpieceMotion(motion);
            shown.tip = motion.apply(pose.tip);
            shown.axis = motion.turn(pose.axis);
            m_frameMoved = true;
        } else if (m_frameMoved) {
            m_view->setWorkpieceMotion({});
            m_frameMoved = false;
        }
        m_view->simulation().showTool(shown);
        m_view->simulation().showPathUpTo(at, pose.tip);
    }
    if (m_stock)
        m_stock->setTarget(at);
    followEditor(m_run->timeline.lineOf(at.move));
    if (m_chart != nullptr)
        m_chart->setCursorTime(m_position);
    emit positionChanged();
}

void SimPlayer::setMachineFrame(bool on)
{
    if (on == m_machineFrame)
        return;
    m_machineFrame = on;
    if (m_run)
        apply();
    emit machineFrameChanged(on);
}

bool SimPlayer::showsMachineFrame() const
{
    return m_machineFrame && machineFrameSupport() == MachineFrameSupport::Available;
}

MachineFrameSupport SimPlayer::machineFrameSupport() const { return gui::machineFrameSupport(m_run.get()); }

void SimPlayer::followEditor(int line)
{
    if (m_editor == nullptr || m_outOfDate || line <= 0 || line == m_shownLine)
        return;
    m_shownLine = line;
    m_movingEditor = true;
    m_editor->gotoLine(line);
    m_movingEditor = false;
}

void SimPlayer::showStockFrame()
{
    if (!m_stock || m_view == nullptr)
        return;
    QElapsedTimer started;
    started.start();
    const std::shared_ptr<const StockFrame> frame = m_stock->frame();
    if (!frame)
        return;
    m_shownFrame = frame;
    if (!frame->positions)
        return;
    if (frame->deviation) {
        m_deviation = frame->deviation;
        emit deviationReady();
    }
    const bool atEnd = frame->deviation.has_value();
    m_view->simulation().showStock(frame->positions, frame->triangles, atEnd ? &frame->deviation->perVertex : nullptr,
                                   m_deviationLimit);
    if (m_playing) {
        ++m_stockFrames;
        m_stockMeshSeconds += frame->meshSeconds;
        countUpdate(started);
    }
}

void SimPlayer::countUpdate(const QElapsedTimer& started)
{
    ++m_updates;
    m_updateSeconds += started.nsecsElapsed() * 1e-9;
    m_stats.meanUpdateMs = 1e3 * m_updateSeconds / m_updates;
}

// Caught up, the worker waits for a new target, so the frame it left is the one that got there.
bool SimPlayer::stockCaughtUp() const
{
    return !m_stock || (m_stock->isCaughtUp() && m_stock->frame() == m_shownFrame);
}

void SimPlayer::countFrame()
{
    if (!m_playing)
        return;
    ++m_stats.frames;
    const double seconds = m_statsClock.nsecsElapsed() * 1e-9;
    if (seconds > 0) {
        m_stats.renderedFps = m_stats.frames / seconds;
        m_stats.stockFps = m_stockFrames / seconds;
        m_stats.meanStockMeshMs = m_stockFrames > 0 ? 1e3 * m_stockMeshSeconds / m_stockFrames : 0;
    }
}

QStringList SimPlayer::quantityIds() const
{
    QStringList ids;
    if (m_run)
        for (const SampledQuantity& q : m_run->analysis.quantities)
            ids << QString::fromStdString(q.id);
    if (m_measured)
        for (const SampledQuantity& q : m_measured->quantities)
            ids << QString::fromStdString(q.id);
    return ids;
}

const SampledQuantity* SimPlayer::findQuantity(const QString& id, const std::vector<base::Vec3>** tips) const
{
    const std::string wanted = id.toStdString();
    if (m_run)
        for (const SampledQuantity& q : m_run->analysis.quantities)
            if (q.id == wanted) {
                *tips = &m_run->analysis.tip;
                return &q;
            }
    if (m_measured)
        for (const SampledQuantity& q : m_measured->quantities)
            if (q.id == wanted) {
                *tips = &m_measured->actualTip;
                return &q;
            }
    return nullptr;
}

QString SimPlayer::quantityLabel(const QString& id) const
{
    const std::vector<base::Vec3>* tips = nullptr;
    const SampledQuantity* q = findQuantity(id, &tips);
    return q != nullptr ? QString::fromStdString(q->label) : QString();
}

QString SimPlayer::importMeasured(const QString& path, const sim::TraceColumns& columns, double spindleFaceToTipMm)
{
    if (!m_run)
        return tr("Simulate the program first: a measured trace is carried onto the workpiece through the "
                  "simulation's machine and compared with its path.");
    auto read = sim::loadMeasuredTrace(path.toStdString(), columns);
    if (!read)
        return QString::fromStdString(read.error().toString());
    m_measured = std::make_shared<const MeasuredRun>(
        carryMeasured(std::move(read).value(), path.toStdString(), columns, spindleFaceToTipMm, *m_run));
    m_editedSinceMeasured = m_measuredOutOfDate = false;
    showMeasured();
    emit measuredChanged();
    emit message(base::Severity::Note,
                 tr("Measured trace %1: %2 samples").arg(path).arg(m_measured->trace.time.size()));
    return {};
}

void SimPlayer::clearMeasured()
{
    if (!m_measured)
        return;
    const bool colouredByIt = m_quantity.startsWith(QLatin1String("measured"));
    m_measured = nullptr;
    m_editedSinceMeasured = m_measuredOutOfDate = false;
    showMeasured();
    if (colouredByIt)
        showQuantity({});
    emit measuredChanged();
}

// The programmed moves and the nominal trace; the actual trace is coloured by showQuantity.
void SimPlayer::showMeasured()
{
    if (m_view == nullptr)
        return;
    std::vector<base::Vec3> programmed, nominal;
    if (m_measured && m_run) {
        for (const sim::Move& move : m_run->moves.moves)
            if (move.moves() && move.positionKnown) {
                programmed.push_back(move.from);
                programmed.push_back(move.to);
            }
        nominal = m_measured->nominalTip;
    }
    m_view->simulation().showMeasured(programmed, nominal);
}

void SimPlayer::showQuantity(const QString& id, std::optional<std::pair<double, double>> limits)
{
    m_quantity.clear();
    const std::vector<base::Vec3>* tips = nullptr;
    const SampledQuantity* found = findQuantity(id, &tips);
    if (found == nullptr || found->values.empty() || m_view == nullptr) {
        if (m_view != nullptr)
            m_view->simulation().showColouredPath({}, {}, 0, 1, {}, {});
        if (m_chart != nullptr)
            m_chart->setSeries({}, {}, {});
        return;
    }
    m_quantity = id;
    const std::vector<base::Vec3>& tip = *tips;
    const auto [lo, hi] = std::minmax_element(found->values.begin(), found->values.end());
    m_range = limits ? *limits : std::make_pair(*lo, *hi);
    // Value k belongs to sample firstSample + k: the path drawn through those samples' tips.
    const std::size_t first = found->firstSample;
    const std::size_t count = std::min(found->values.size(), tip.size() - std::min(first, tip.size()));
    const auto from = tip.begin() + static_cast<std::ptrdiff_t>(std::min(first, tip.size()));
    const std::vector<base::Vec3> points(from, from + static_cast<std::ptrdiff_t>(count));
    const std::vector<double> values(found->values.begin(), found->values.begin() + count);
    std::vector<base::Vec3> markers;
    for (std::size_t sample : found->reversals)
        if (sample < tip.size())
            markers.push_back(tip[sample]);
    const QString label = QString::fromStdString(found->label);
    m_view->simulation().showColouredPath(points, values, m_range.first, m_range.second, label, markers);
    if (m_chart != nullptr) {
        m_chart->setSeries(found->time, found->values, label);
        m_chart->setValueLimits(limits ? m_range.first : 0, limits ? m_range.second : 0);
        m_chart->setCursorTime(m_position);
    }
}

void SimPlayer::setToolVisible(bool visible)
{
    if (m_view != nullptr)
        m_view->simulation().setToolVisible(visible);
}

void SimPlayer::setDeviationLimit(double mm)
{
    m_deviationLimit = std::max(mm, 1e-4);
    showStockFrame();
}

}  // namespace camwb::gui
