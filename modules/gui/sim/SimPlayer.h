// The simulator's controller (no widgets): builds a simulation of the traced NC program on a
// worker thread (progress, cancel), then plays it: play, pause, block steps, jumps to a line or a
// picked segment, speed. It moves the tool, the travelled path and the cut stock in the 3D view,
// keeps the editor's cursor on the current block and follows the editor's and the view's picks
// back, shows the machine frame of a five-axis machine, colours the path and the stock for the results, and overlays a
// measured trace. The dock and the actions call it.
#pragma once

#include "base/Diagnostic.h"
#include "gui/sim/MachineFrame.h"
#include "gui/sim/MeasuredRun.h"
#include "gui/sim/SimRun.h"
#include "sim/Stock.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QStringList>

#include <atomic>
#include <memory>
#include <optional>

class QTimer;

namespace camwb::gui {

class NcEditor;
class SimChart;
class StockAnimation;
struct StockFrame;
class View3D;

struct PlaybackStats {
    double renderedFps = 0;      // frames the view drew per second while playing
    double stockFps = 0;         // stock meshes shown per second while playing
    double meanStockMeshMs = 0;  // the worker's remesh per stock frame
    double meanUpdateMs = 0;     // GUI thread per playback step and stock frame, rendering not included
    int frames = 0;
};

class SimPlayer : public QObject {
    Q_OBJECT
public:
    explicit SimPlayer(QObject* parent = nullptr);
    ~SimPlayer() override;

    void attach(NcEditor* editor, View3D* view, SimChart* chart);

    // Simulates what the request's trace says (on a worker); ready() or failed() follow.
    void start(SimRunRequest request);
    void cancel();
    bool isBuilding() const { return m_building; }
    // Drops the simulation and what it drew.
    void clear();

    std::shared_ptr<const SimRun> run() const { return m_run; }
    bool hasRun() const { return m_run != nullptr; }
    // The program was edited after it was simulated: what plays is not what the editor holds.
    bool isOutOfDate() const { return m_outOfDate; }
    void markOutOfDate();

    void play();
    void pause();
    bool isPlaying() const { return m_playing; }
    void stepForward();
    void stepBack();
    void jumpToLine(int line);
    void jumpToRecord(std::size_t record);
    void seek(double position);
    double position() const { return m_position; }
    bool atEnd() const;
    MovePoint point() const;
    int currentLine() const;
    // Playback speed: machine seconds per wall second (a multiple of the machine's speed).
    void setSpeed(double factor);
    double speed() const { return m_speed; }

    // A trace the control recorded (TNCscope CSV, read by sim::loadMeasuredTrace with `columns`),
    // carried through the simulation's machine onto the workpiece: the nominal trace drawn beside
    // the program, the actual one coloured by its deviation, which the chart plots. Needs a
    // simulation; returns the error (file:line where there is one) and then changes nothing.
    QString importMeasured(const QString& path, const sim::TraceColumns& columns, double spindleFaceToTipMm = 0);
    void clearMeasured();
    std::shared_ptr<const MeasuredRun> measured() const { return m_measured; }
    // The program was changed and simulated again after the trace was imported: the trace is of
    // the program as it was.
    bool isMeasuredOutOfDate() const { return m_measured && m_measuredOutOfDate; }

    // Results: the path coloured by an analysed quantity (empty id: by move kind; the measured
    // trace's: its actual path), within limits (none: its own range), and the stock by its
    // deviation (when the end has been cut).
    QStringList quantityIds() const;
    QString quantityLabel(const QString& id) const;
    void showQuantity(const QString& id, std::optional<std::pair<double, double>> limits = std::nullopt);
    QString quantity() const { return m_quantity; }
    std::pair<double, double> quantityRange() const { return m_range; }
    void setDeviationLimit(double mm);
    void setToolVisible(bool visible);
    double deviationLimit() const { return m_deviationLimit; }
    // The stock's deviation at the program's end: the animation's once it got there, else the
    // full run's (nullopt without a model to compare with).
    std::optional<sim::Deviation> deviation() const;
    // The stock animation has cut up to the playback position and the view shows that stock
    // (the frame is delivered through the event loop after the cut).
    bool stockCaughtUp() const;
    PlaybackStats stats() const { return m_stats; }

    // The machine frame (Cam.Sim.MachineFrame): the tool along the spindle, the workpiece side
    // (stock, model, path, rotary table) turned by the table's axes at the playback's point.
    // Shown while machineFrameSupport() is Available (the action turns it off for a run that is not).
    void setMachineFrame(bool on);
    bool machineFrame() const { return m_machineFrame; }
    bool showsMachineFrame() const;
    MachineFrameSupport machineFrameSupport() const;

signals:
    void buildStarted();
    void buildProgress(int percent);
    void ready();
    void cleared();
    void positionChanged();
    void playingChanged(bool playing);
    void outOfDateChanged(bool outOfDate);
    void deviationReady();
    void measuredChanged();
    void machineFrameChanged(bool on);
    void message(camwb::base::Severity severity, const QString& text);

private:
    void finishBuild(std::shared_ptr<SimRun> run, quint64 generation);
    // The quantity `id` of the run or the measured trace, and the tips its samples are at.
    const SampledQuantity* findQuantity(const QString& id, const std::vector<base::Vec3>** tips) const;
    void showMeasured();
    void reportChecks();
    void tick();
    void apply();
    void followEditor(int line);
    void showStockFrame();
    void countFrame();
    void countUpdate(const QElapsedTimer& started);

    NcEditor* m_editor = nullptr;
    View3D* m_view = nullptr;
    SimChart* m_chart = nullptr;
    QTimer* m_timer;
    QElapsedTimer m_clock;
    std::shared_ptr<const SimRun> m_run;
    std::unique_ptr<StockAnimation> m_stock;
    std::shared_ptr<const StockFrame> m_shownFrame;  // the animation's frame the view last took
    std::shared_ptr<std::atomic<bool>> m_cancel;
    quint64 m_generation = 0;
    bool m_building = false;
    bool m_playing = false;
    bool m_outOfDate = false;
    bool m_movingEditor = false;
    bool m_machineFrame = false;
    bool m_frameMoved = false;  // the view shows the workpiece side moved (undo it when leaving)
    double m_position = 0;
    double m_speed = 10;
    int m_shownLine = -1;
    QString m_quantity;
    std::pair<double, double> m_range{0, 1};
    double m_deviationLimit = 0.1;
    std::optional<sim::Deviation> m_deviation;
    std::shared_ptr<const MeasuredRun> m_measured;
    bool m_editedSinceMeasured = false;  // the program was changed after the trace was imported
    bool m_measuredOutOfDate = false;
    PlaybackStats m_stats;
    QElapsedTimer m_statsClock;
    int m_stockFrames = 0;
    int m_updates = 0;
    double m_updateSeconds = 0;
    double m_stockMeshSeconds = 0;
};

}  // namespace camwb::gui
