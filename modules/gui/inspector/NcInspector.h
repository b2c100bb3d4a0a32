// The NC inspector's controller: interprets the editor's text in its dialect on a worker thread
// (debounced after edits, a newer trace supersedes an older one), shows the result in the 3D
// view and links both ways: a picked segment moves the editor to its block, the cursor's block
// is highlighted in 3D and its modal state goes to the panel. No widget logic lives here beyond
// the connections; the trace itself is plain C++ (NcTrace).
#pragma once

#include "document/NcTrace.h"
#include "gui/shell/Workbench.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>

class QTimer;

namespace camwb::gui {

class ModalStatePanel;
class NcEditor;
class ToolpathScene;
class View3D;

// Wall-clock figures of the last finished trace (seconds), for the report and the benchmark.
struct NcTraceTimings {
    double interpret = 0;  // worker: nc::interpret into the recorder
    double index = 0;      // worker: line index and modal checkpoints
    double scene = 0;      // worker: tessellation and VTK polydata
    double show = 0;       // GUI thread: actors into the view
    double total = 0;      // from the request to the view holding the result
};

class NcInspector : public QObject {
    Q_OBJECT
public:
    explicit NcInspector(QObject* parent = nullptr);
    ~NcInspector() override;

    // Connects the editor (edits, cursor), the view (picking) and the modal panel (may be null).
    void attach(NcEditor* editor, View3D* view, ModalStatePanel* panel);

    // nullopt = guess from the text and file name (nc::guessDialect).
    void setDialect(std::optional<nc::Dialect> dialect);
    std::optional<nc::Dialect> dialect() const { return m_dialect; }
    // The program's file: its name for diagnostics and the dialect guess, its folder for calls.
    void setFilePath(const QString& path);
    QString filePath() const { return m_path; }
    void setDebounceMs(int milliseconds);
    // The machine the program is checked against (the job's, as its post checks the CL) from the
    // next trace on: its limit warnings join the program's diagnostics. nullptr: no machine checks.
    void setMachine(std::shared_ptr<const kinematics::Machine> machine);
    const kinematics::Machine* machine() const { return m_machine.get(); }
    std::shared_ptr<const kinematics::Machine> sharedMachine() const { return m_machine; }
    // Tool sizes for cutter compensation where the program defines none (a posted program's D1
    // means the job's tool), from the next trace on; nullptr: none.
    void setToolTable(std::shared_ptr<const nc::ToolTable> tools) { m_tools = std::move(tools); }
    // A lathe's program gives no Y: from the next trace on, its moves are drawn in the turning
    // plane (Y = 0, sim::inTurningPlane) while set (the main window sets it for a turning job).
    void setTurningPlane(bool turning) { m_turningPlane = turning; }

    // A new program for the editor (opened or posted): the editor gets the dialect first (so a
    // huge text is highlighted once, not twice), then the text; the trace starts at once.
    void loadProgram(const QString& text, const QString& path);

    // Whether finished traces go to the 3D view; off while it shows the operations' toolpath.
    void setShowInView(bool show);
    bool showsInView() const { return m_showInView; }

    bool isTracing() const { return m_running > 0; }

    std::shared_ptr<const document::NcTrace> trace() const { return m_trace; }
    NcTraceTimings lastTimings() const { return m_timings; }
    // Records highlighted for the editor's current line (all runs of it).
    const std::vector<std::size_t>& highlightedRecords() const { return m_highlighted; }

public slots:
    void traceNow();       // interprets the editor's text now
    void scheduleTrace();  // after the debounce delay (edits call this)

signals:
    void traceStarted();
    void traceFinished();  // trace() holds the new result
    void busyChanged(bool busy);
    void message(camwb::gui::Workbench::Severity severity, const QString& text);
    // A picked record from a called program, which the editor does not show ("SUB.SPF:12").
    void pickedInSubprogram(const QString& where);

private:
    struct Result;
    void onCursorLine(int line);
    void onSegmentPicked(int segment, int record);
    void finish(const std::shared_ptr<Result>& result);
    void showLine(int line);
    void reportDiagnostics(const document::NcTrace& trace);
    void showInEditor(const document::NcTrace& trace);

    NcEditor* m_editor = nullptr;
    View3D* m_view = nullptr;
    ModalStatePanel* m_panel = nullptr;
    QTimer* m_debounce;
    std::optional<nc::Dialect> m_dialect;
    QString m_path;
    std::shared_ptr<const kinematics::Machine> m_machine;
    std::shared_ptr<const nc::ToolTable> m_tools;
    bool m_turningPlane = false;
    bool m_showInView = true;
    bool m_editorHasDiagnostics = false;
    int m_running = 0;
    quint64 m_generation = 0;
    std::shared_ptr<std::atomic<bool>> m_cancelCurrent;
    std::shared_ptr<const document::NcTrace> m_trace;
    std::shared_ptr<const ToolpathScene> m_scene;
    std::vector<std::size_t> m_highlighted;
    NcTraceTimings m_timings;
};

}  // namespace camwb::gui
