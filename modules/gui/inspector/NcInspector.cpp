#include "gui/inspector/NcInspector.h"

#include "gui/editor/NcEditor.h"
#include "gui/inspector/ModalStatePanel.h"
#include "gui/view3d/View3D.h"
#include "sim/TurningCheck.h"
#include "toolpath/ToolpathPolylines.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <chrono>

namespace camwb::gui {

namespace {

// Diagnostics beyond this many go to the report as a count: a broken million-line program must
// not bury the report (the editor's margin shows them all).
constexpr int kReportedDiagnostics = 50;

}  // namespace

struct NcInspector::Result {
    quint64 generation = 0;
    document::NcTrace trace;
    std::shared_ptr<const ToolpathScene> scene;
    double sceneSeconds = 0;
    QElapsedTimer requested;
};

NcInspector::NcInspector(QObject* parent) : QObject(parent), m_debounce(new QTimer(this))
{
    m_debounce->setSingleShot(true);
    m_debounce->setInterval(400);
    connect(m_debounce, &QTimer::timeout, this, &NcInspector::traceNow);
}

NcInspector::~NcInspector()
{
    if (m_cancelCurrent)
        m_cancelCurrent->store(true);
}

void NcInspector::attach(NcEditor* editor, View3D* view, ModalStatePanel* panel)
{
    m_editor = editor;
    m_view = view;
    m_panel = panel;
    if (m_editor != nullptr) {
        connect(m_editor, &NcEditor::cursorLineChanged, this, &NcInspector::onCursorLine);
        connect(m_editor, &NcEditor::textChanged, this, &NcInspector::scheduleTrace);
    }
    if (m_view != nullptr)
        connect(m_view, &View3D::segmentPicked, this, &NcInspector::onSegmentPicked);
}

void NcInspector::setDialect(std::optional<nc::Dialect> dialect)
{
    if (m_dialect == dialect)
        return;
    m_dialect = dialect;
    traceNow();
}

void NcInspector::setFilePath(const QString& path) { m_path = path; }

void NcInspector::setDebounceMs(int milliseconds) { m_debounce->setInterval(milliseconds); }

void NcInspector::loadProgram(const QString& text, const QString& path)
{
    m_path = path;
    if (m_editor == nullptr)
        return;
    // The dialect shows in the first lines; a guess over a megabyte of text would only cost time.
    constexpr int kGuessChars = 64 * 1024;
    const nc::Dialect dialect =
        m_dialect ? *m_dialect : nc::guessDialect(text.left(kGuessChars).toStdString(), path.toStdString());
    if (m_editor->dialect() != dialect)
        m_editor->setDialect(dialect);
    m_editor->setClFormat(document::clFormatToRead(path.toStdString(), m_dialect));
    m_editor->setText(text);         // a new document: no diagnostics in the margin
    m_editor->setProgramPath(path);  // program info finds subprograms beside it, dialogs name it
    m_editorHasDiagnostics = false;
    traceNow();
}

void NcInspector::setShowInView(bool show)
{
    m_showInView = show;
    if (show && m_view != nullptr && m_scene) {
        m_view->setPreparedToolpath(m_scene);
        if (m_editor != nullptr)
            showLine(m_editor->currentLine());
    }
}

void NcInspector::scheduleTrace() { m_debounce->start(); }

void NcInspector::setMachine(std::shared_ptr<const kinematics::Machine> machine) { m_machine = std::move(machine); }

void NcInspector::traceNow()
{
    m_debounce->stop();
    if (m_editor == nullptr)
        return;
    // The run before this one is now stale: it stops recording and its result is dropped.
    if (m_cancelCurrent)
        m_cancelCurrent->store(true);
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    m_cancelCurrent = cancel;
    const quint64 generation = ++m_generation;

    auto result = std::make_shared<Result>();
    result->generation = generation;
    result->requested.start();
    const QString text = m_editor->text();  // implicitly shared: the worker converts it
    const std::string path = m_path.toStdString();
    const std::optional<nc::Dialect> dialect = m_dialect;
    std::shared_ptr<const kinematics::Machine> machine = m_machine;
    std::shared_ptr<const nc::ToolTable> tools = m_tools;
    const bool turningPlane = m_turningPlane;

    if (m_running++ == 0)
        emit busyChanged(true);
    emit traceStarted();
    if (m_panel != nullptr && !m_trace)
        m_panel->showMessage(tr("Tracing the NC program…"));

    auto* watcher = new QFutureWatcher<void>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, result] {
        watcher->deleteLater();
        finish(result);
    });
    watcher->setFuture(QtConcurrent::run([result, text, path, dialect, machine, tools, cancel, turningPlane] {
        document::NcTraceRequest request;
        request.text = text.toStdString();
        request.path = path;
        request.dialect = dialect;
        request.machine = machine;
        request.tools = tools;
        request.cancel = cancel.get();
        result->trace = document::traceNc(request);
        if (result->trace.cancelled || cancel->load())
            return;
        const auto start = std::chrono::steady_clock::now();
        // Record for record (the same indices), so picking still finds the program's lines.
        result->scene =
            View3D::prepareToolpath(turningPlane ? sim::inTurningPlane(result->trace.program) : result->trace.program,
                                    result->trace.recordsInError);
        result->sceneSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }));
}

void NcInspector::finish(const std::shared_ptr<Result>& result)
{
    if (--m_running == 0)
        emit busyChanged(false);
    if (result->generation != m_generation || result->trace.cancelled)
        return;  // superseded by a newer trace
    m_cancelCurrent = nullptr;
    m_trace = std::make_shared<const document::NcTrace>(std::move(result->trace));
    m_scene = result->scene;

    QElapsedTimer show;
    show.start();
    if (m_showInView && m_view != nullptr)
        m_view->setPreparedToolpath(m_scene);
    m_timings.interpret = m_trace->interpretSeconds;
    m_timings.index = m_trace->indexSeconds;
    m_timings.scene = result->sceneSeconds;
    m_timings.show = show.nsecsElapsed() * 1e-9;
    m_timings.total = result->requested.nsecsElapsed() * 1e-9;

    // No program (a job whose post failed or whose model is missing) has nothing to report; its
    // empty trace only clears the view.
    const bool noProgram = m_editor != nullptr && m_editor->text().isEmpty();
    if (!noProgram)
        reportDiagnostics(*m_trace);
    if (m_editor != nullptr && !noProgram)
        showInEditor(*m_trace);
    m_highlighted.clear();
    if (m_editor != nullptr)
        showLine(m_editor->currentLine());
    emit traceFinished();
}

// The editor highlights in the traced dialect and marks the main program's diagnostics. A margin
// that is clear already is not cleared again: on a million-line document that costs the editor
// most of a second.
void NcInspector::showInEditor(const document::NcTrace& trace)
{
    if (m_editor->dialect() != trace.dialect)
        m_editor->setDialect(trace.dialect);
    m_editor->setClFormat(trace.clFormat);  // as read: the dock's dialect choice reads a .cls as NC
    const std::string program = trace.result.files.empty() ? std::string() : trace.result.files.front();
    const QList<NcEditorDiagnostic> diagnostics = NcEditor::diagnosticsFor(trace.result.diagnostics, program);
    if (!diagnostics.isEmpty() || m_editorHasDiagnostics)
        m_editor->setDiagnostics(diagnostics);
    m_editorHasDiagnostics = !diagnostics.isEmpty();
}

void NcInspector::reportDiagnostics(const document::NcTrace& trace)
{
    const auto& diagnostics = trace.result.diagnostics;
    const QString name = m_path.isEmpty() ? tr("NC program") : QFileInfo(m_path).fileName();
    int reported = 0;
    for (const nc::Diagnostic& diagnostic : diagnostics) {
        if (reported++ == kReportedDiagnostics)
            break;
        emit message(diagnostic.severity, QString::fromStdString(nc::formatDiagnostic(diagnostic)));
    }
    const std::size_t more = diagnostics.size() + trace.result.diagnosticsDropped -
                             std::min<std::size_t>(diagnostics.size(), kReportedDiagnostics);
    if (more > 0)
        emit message(Workbench::Severity::Warning, tr("%1: %2 more diagnostics not listed").arg(name).arg(more));
    const toolpath::ToolpathStats stats = toolpath::statistics(trace.program);
    const QString fiveAxis = stats.fiveAxis > 0 ? tr(", %1 five-axis moves").arg(stats.fiveAxis) : QString();
    emit message(Workbench::Severity::Note,
                 tr("Traced %1 as %2%3: %4 blocks, %5 lines, %6 arcs, %7 rapids, %8 cycles%9 in %10 ms")
                     .arg(name,
                          trace.clFormat
                              ? tr("a CL file (%1)").arg(QString::fromLatin1(toolpath::clFormatName(*trace.clFormat)))
                              : QString::fromLatin1(nc::dialectName(trace.dialect)),
                          trace.dialectGuessed && !trace.clFormat ? tr(" (guessed)") : QString())
                     .arg(trace.result.blocksExecuted)
                     .arg(stats.lines)
                     .arg(stats.arcs + stats.helices)
                     .arg(stats.rapids)
                     .arg(stats.cycles)
                     .arg(fiveAxis)
                     .arg(trace.interpretSeconds * 1e3, 0, 'f', trace.interpretSeconds < 0.01 ? 2 : 0));
}

void NcInspector::onCursorLine(int line) { showLine(line); }

void NcInspector::showLine(int line)
{
    if (!m_trace)
        return;
    m_highlighted = m_trace->recordsOfLine(line);
    if (m_showInView && m_view != nullptr)
        m_view->setHighlightedRecords(m_highlighted);
    if (m_panel != nullptr)
        m_panel->showState(m_trace->lineState(line), *m_trace);
}

void NcInspector::onSegmentPicked(int /*segment*/, int record)
{
    if (!m_trace || !m_showInView || m_editor == nullptr || record < 0)
        return;
    const auto index = static_cast<std::size_t>(record);
    if (m_trace->isInSubprogram(index))
        emit pickedInSubprogram(QString::fromStdString(m_trace->whereOf(index)));
    const int line = m_trace->lineOfRecord(index);
    if (line > 0)
        m_editor->gotoLine(line);
}

}  // namespace camwb::gui
