#include "gui/editor/ProgramInfoDialog.h"

#include "kinematics/Machine.h"
#include "nc/Interpreter.h"
#include "nc/tools/ErrorRecords.h"
#include "sim/MotionPlan.h"
#include "sim/Moves.h"
#include "toolpath/ToolpathRecorder.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QPointer>
#include <QSignalBlocker>
#include <QTextBrowser>
#include <QThread>
#include <QVBoxLayout>

#include <cmath>

namespace camwb::gui {

struct ProgramInfoDialog::Result {
    toolpath::Toolpath program;
    nc::InterpretResult interpretation;
    std::vector<bool> recordsInError;  // left out of the figures
    toolpath::ProgramStats stats;
    sim::CycleTimes planned;  // on the machine's limits
    QString machineName;      // empty: the default limits
};

QString formatDuration(double seconds)
{
    if (seconds < 60)
        return ProgramInfoDialog::tr("%1 s").arg(seconds, 0, 'f', 1);
    const auto total = static_cast<long long>(std::llround(seconds));
    const long long h = total / 3600;
    const long long m = (total / 60) % 60;
    const long long s = total % 60;
    if (h > 0)
        return QStringLiteral("%1:%2:%3").arg(h).arg(m, 2, 10, QLatin1Char('0')).arg(s, 2, 10, QLatin1Char('0'));
    return QStringLiteral("%1:%2").arg(m).arg(s, 2, 10, QLatin1Char('0'));
}

namespace {

QString mm(double value) { return QString::number(value, 'f', 3); }

QString extentsRows(const QString& what, const toolpath::Extents& e)
{
    if (e.empty)
        return QStringLiteral("<tr><td>%1</td><td colspan=6>—</td></tr>").arg(what);
    return QStringLiteral("<tr><td>%1</td><td align=right>%2</td><td align=right>%3</td><td align=right>%4</td>"
                          "<td align=right>%5</td><td align=right>%6</td><td align=right>%7</td></tr>")
        .arg(what, mm(e.min.x), mm(e.max.x), mm(e.min.y), mm(e.max.y), mm(e.min.z), mm(e.max.z));
}

}  // namespace

ProgramInfoDialog::ProgramInfoDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("programInfoDialog"));
    setWindowTitle(tr("Program Information"));
    resize(760, 620);
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_rapid = new QDoubleSpinBox(this);
    m_rapid->setObjectName(QStringLiteral("programInfoRapid"));
    m_rapid->setRange(100, 200'000);
    m_rapid->setDecimals(0);
    m_rapid->setSingleStep(1000);
    m_rapid->setSuffix(tr(" mm/min"));
    m_rapid->setValue(toolpath::kDefaultRapidMmPerMin);
    m_rapid->setToolTip(tr("Rapid rate the time estimate assumes (the machine's, when it says)"));
    form->addRow(tr("Rapid rate:"), m_rapid);
    layout->addLayout(form);
    m_status = new QLabel(this);
    layout->addWidget(m_status);
    m_view = new QTextBrowser(this);
    m_view->setObjectName(QStringLiteral("programInfoText"));
    layout->addWidget(m_view, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    // Statistics are cheap once the program is interpreted: recompute them for another rate.
    connect(m_rapid, &QDoubleSpinBox::valueChanged, this, [this] {
        if (m_result && !isBusy()) {
            toolpath::StatsOptions options;
            options.rapidMmPerMin = m_rapid->value();
            options.recordsInError = &m_result->recordsInError;
            m_result->stats = toolpath::programStats(m_result->program, options);
            render();
        }
    });
}

ProgramInfoDialog::~ProgramInfoDialog()
{
    if (m_thread != nullptr)
        m_thread->wait();  // the interpreter cannot be interrupted; it owns nothing of ours
}

void ProgramInfoDialog::analyze(const QString& text, nc::Dialect dialect, const QString& fileName,
                                std::shared_ptr<const kinematics::Machine> machine,
                                std::optional<toolpath::ClFormat> clFormat)
{
    if (isBusy())
        return;
    if (machine && machine->rapidMmPerMin > 0) {
        const QSignalBlocker quiet(m_rapid);  // not a second analysis for the same program
        m_rapid->setValue(machine->rapidMmPerMin);
    }
    m_status->setText(tr("Interpreting the program…"));
    m_view->clear();
    auto result = std::make_shared<Result>();
    std::string source = text.toStdString();
    nc::InterpretOptions options;
    options.dialect = dialect;
    options.clFormat = clFormat;
    options.fileName = fileName.toStdString();
    if (!fileName.isEmpty() && QFileInfo(fileName).isAbsolute())
        options.resolveProgram = nc::resolverBeside(fileName.toStdString(), dialect);
    const double rapid = m_rapid->value();
    if (machine)
        result->machineName = QString::fromStdString(machine->name.empty() ? machine->id : machine->name);
    m_thread = QThread::create([result, source = std::move(source), options, rapid, machine] {
        toolpath::ToolpathRecorder recorder;
        result->interpretation = nc::interpret(source, options, recorder);
        result->program = recorder.take();
        result->recordsInError = nc::recordsInError(result->program, result->interpretation);
        toolpath::StatsOptions statsOptions;
        statsOptions.rapidMmPerMin = rapid;
        statsOptions.recordsInError = &result->recordsInError;
        result->stats = toolpath::programStats(result->program, statsOptions);
        const kinematics::Machine limits = machine ? *machine : kinematics::defaultLimitsMachine();
        sim::MoveOptions moveOptions;
        if (limits.kinematics.fiveAxis())
            moveOptions.chain = &limits.kinematics;
        const sim::MoveList moves = sim::buildMoves(result->program, moveOptions, result->recordsInError);
        result->planned = sim::cycleTimes(moves, sim::planMotion(moves, limits), result->stats);
    });
    QThread* thread = m_thread;
    connect(thread, &QThread::finished, this, [this, thread, result] {
        thread->deleteLater();
        if (m_thread == thread)
            m_thread = nullptr;
        finish(result);
    });
    thread->start(QThread::LowPriority);
}

bool ProgramInfoDialog::isBusy() const { return m_thread != nullptr; }

bool ProgramInfoDialog::hasStats() const { return m_result != nullptr; }

const toolpath::ProgramStats& ProgramInfoDialog::stats() const { return m_result->stats; }

double ProgramInfoDialog::plannedSeconds() const { return m_result->planned.planned.totalSeconds(); }

int ProgramInfoDialog::errorCount() const
{
    if (!m_result)
        return 0;
    int errors = 0;
    for (const nc::Diagnostic& d : m_result->interpretation.diagnostics)
        errors += d.severity == nc::Severity::Error ? 1 : 0;
    return errors;
}

QString ProgramInfoDialog::reportText() const { return m_view->toPlainText(); }

void ProgramInfoDialog::finish(std::shared_ptr<Result> result)
{
    m_result = std::move(result);
    render();
    emit analysisFinished();
}

void ProgramInfoDialog::render()
{
    const toolpath::ProgramStats& s = m_result->stats;
    const nc::InterpretResult& ir = m_result->interpretation;
    const int errors = errorCount();
    const int others = static_cast<int>(ir.diagnostics.size()) - errors;
    m_status->setText(errors > 0 ? tr("%1 blocks interpreted; %2 error(s), %3 other diagnostic(s): the figures "
                                      "cover what could be interpreted; %4 move(s) of blocks with an error are "
                                      "left out.")
                                       .arg(ir.blocksExecuted)
                                       .arg(errors)
                                       .arg(others)
                                       .arg(s.movesLeftOut)
                                 : tr("%1 blocks interpreted, %2 diagnostic(s).").arg(ir.blocksExecuted).arg(others));
    QString html;
    html += QStringLiteral("<h3>%1</h3>").arg(tr("Extents (mm)"));
    html += QStringLiteral("<table cellspacing=0 cellpadding=3 border=1><tr><th></th><th>X min</th><th>X max</th>"
                           "<th>Y min</th><th>Y max</th><th>Z min</th><th>Z max</th></tr>");
    html += extentsRows(tr("Cutting"), s.totals.cuttingExtents);
    html += extentsRows(tr("Rapid"), s.totals.rapidExtents);
    html += extentsRows(tr("All"), s.totals.allExtents);
    html += QStringLiteral("</table>");

    html += QStringLiteral("<h3>%1</h3><table cellspacing=0 cellpadding=3>").arg(tr("Motion"));
    auto row = [&html](const QString& label, const QString& value) {
        html += QStringLiteral("<tr><td>%1</td><td align=right>%2</td></tr>").arg(label, value);
    };
    row(tr("Feed length"), tr("%1 mm").arg(mm(s.totals.feedLengthMm)));
    row(tr("Rapid length"), tr("%1 mm").arg(mm(s.totals.rapidLengthMm)));
    row(tr("Feed time"), formatDuration(s.totals.feedSeconds));
    row(tr("Rapid time (at %1 mm/min)").arg(s.rapidMmPerMin, 0, 'f', 0), formatDuration(s.totals.rapidSeconds));
    row(tr("Dwell time"), formatDuration(s.totals.dwellSeconds));
    row(tr("Estimate from distance and feed"), formatDuration(s.totals.totalSeconds()));
    const sim::CycleTimes& planned = m_result->planned;
    row(m_result->machineName.isEmpty()
            ? tr("<b>Cycle time with accelerations</b> (no machine chosen: default limits)")
            : tr("<b>Cycle time with accelerations</b> (%1)").arg(m_result->machineName.toHtmlEscaped()),
        QStringLiteral("<b>%1</b>").arg(formatDuration(planned.planned.totalSeconds())));
    row(tr("Rapids / feed moves / arcs"), QStringLiteral("%1 / %2 / %3").arg(s.rapids).arg(s.feedMoves).arg(s.arcs));
    row(tr("Cycle holes"), QString::number(s.cycleHoles));
    row(tr("Tool changes"), QString::number(s.toolChanges));
    if (s.movesWithoutFeed > 0)
        row(tr("Feed moves without a usable feed (not timed)"), QString::number(s.movesWithoutFeed));
    html += QStringLiteral("</table>");

    html += QStringLiteral("<h3>%1</h3>").arg(tr("Per tool"));
    html += QStringLiteral("<table cellspacing=0 cellpadding=3 border=1><tr><th>%1</th><th>%2</th><th>%3</th>"
                           "<th>%4</th><th>%5</th><th>%6</th></tr>")
                .arg(tr("Tool"), tr("Feed length (mm)"), tr("Rapid length (mm)"), tr("Time (distance/feed)"),
                     tr("Time with accelerations"), tr("Z min (cutting)"));
    for (const toolpath::ToolStats& t : s.tools) {
        const auto plannedTool = planned.plannedPerTool.find(t.toolNumber);
        html +=
            QStringLiteral("<tr><td>%1</td><td align=right>%2</td><td align=right>%3</td><td align=right>%4</td>"
                           "<td align=right>%5</td><td align=right>%6</td></tr>")
                .arg(t.toolNumber == 0 ? tr("(none)") : QStringLiteral("T%1").arg(t.toolNumber),
                     mm(t.totals.feedLengthMm), mm(t.totals.rapidLengthMm), formatDuration(t.totals.totalSeconds()),
                     plannedTool == planned.plannedPerTool.end() ? QStringLiteral("—")
                                                                 : formatDuration(plannedTool->second.totalSeconds()),
                     t.totals.cuttingExtents.empty ? QStringLiteral("—") : mm(t.totals.cuttingExtents.min.z));
    }
    html += QStringLiteral("</table>");
    if (!ir.diagnostics.empty()) {
        html += QStringLiteral("<h3>%1</h3><ul>").arg(tr("Diagnostics"));
        const std::size_t shown = std::min<std::size_t>(ir.diagnostics.size(), 50);
        for (std::size_t k = 0; k < shown; ++k)
            html += QStringLiteral("<li>%1</li>")
                        .arg(QString::fromStdString(nc::formatDiagnostic(ir.diagnostics[k])).toHtmlEscaped());
        if (ir.diagnostics.size() > shown)
            html += QStringLiteral("<li>%1</li>").arg(tr("… and %1 more").arg(ir.diagnostics.size() - shown));
        html += QStringLiteral("</ul>");
    }
    m_view->setHtml(html);
}

}  // namespace camwb::gui
