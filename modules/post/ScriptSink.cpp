#include "post/detail/ScriptSink.h"

#include "post/ArcGeometry.h"
#include "toolpath/RecordNames.h"

#include <QStringList>

#include <filesystem>

namespace camwb::post {

using namespace toolpath;

namespace {

// Evaluated before the post: variadic writeBlock and the handler trampoline. The trampoline
// catches what a handler throws, so that a thrown non-Error value is still seen as a failure.
const char* kPrelude = R"JS(
var writeBlock = (function (kernel) {
    return function writeBlock() { kernel.writeBlockWords(Array.prototype.slice.call(arguments)); };
})(__camwbKernel);
(function (f, self, args) {
    try { f.apply(self, args); return undefined; } catch (e) { return { thrown: e }; }
})
)JS";

const char* kHandlerNames[] = {"onOpen",       "onSection",    "onToolChange",  "onSpindle",    "onCoolant",
                               "onFeedMode",   "onWorkOffset", "onRapid",       "onLinear",     "onCircular",
                               "onLinear5D",   "onCycle",      "onComment",     "onCutterComp", "onDwell",
                               "onSectionEnd", "onStop",       "onPassThrough", "onClose"};

QString qs(const std::string& text) { return QString::fromStdString(text); }

}  // namespace

// Turns each CL record into a handler call; records without a handler give one warning per kind.
class ScriptSink : public MachineSink {
public:
    explicit ScriptSink(ScriptRun& run) : m_run(run) {}

    bool failed() const { return m_run.m_failure.has_value(); }
    const std::map<std::string, int>& unhandled() const { return m_unhandled; }

    void rapid(const Rapid& r) override { move("onRapid", {r.to.x, r.to.y, r.to.z}, r.to); }
    void linear(const Linear& r) override { move("onLinear", {r.to.x, r.to.y, r.to.z, r.feedMmPerMin}, r.to); }
    void arc(const Arc& r) override;
    void toolChange(const ToolChange& r) override
    {
        const Tool& t = r.tool;
        QJSValue tool = engine().newObject();
        tool.setProperty("number", t.number);
        tool.setProperty("name", qs(t.name));
        tool.setProperty("kind", qs(t.kind));
        tool.setProperty("diameter", t.diameterMm);
        tool.setProperty("cornerRadius", t.cornerRadiusMm);
        tool.setProperty("fluteLength", t.fluteLengthMm);
        tool.setProperty("length", t.lengthMm);
        tool.setProperty("flutes", t.flutes);
        handle("onToolChange", {tool});
    }
    void spindle(const Spindle& r) override { handle("onSpindle", {r.rpm, r.clockwise}); }
    void coolant(const Coolant& r) override { handle("onCoolant", {QString(toolpath::name(r.mode))}); }
    void feedMode(const FeedModeChange& r) override { handle("onFeedMode", {QString(toolpath::name(r.mode))}); }
    void workOffset(const WorkOffset& r) override { handle("onWorkOffset", {r.index}); }
    void dwell(const Dwell& r) override { handle("onDwell", {r.seconds}); }
    void cycle(const Cycle& r) override;
    void toolAxisMove(const ToolAxisMove& r) override
    {
        move("onLinear5D", {r.tip.x, r.tip.y, r.tip.z, r.axis.x, r.axis.y, r.axis.z, r.feedMmPerMin}, r.tip);
    }
    void cutterComp(const CutterComp& r) override
    {
        const char* side = toolpath::name(r.side);
        handle("onCutterComp", {QString(side)});
    }
    void comment(const Comment& r) override { handle("onComment", {qs(r.text)}); }
    void sectionBegin(const SectionBegin& r) override
    {
        QJSValue section = engine().newObject();
        section.setProperty("operationName", qs(r.operationName));
        section.setProperty("strategy", qs(r.strategy));
        section.setProperty("toolNumber", r.toolNumber);
        section.setProperty("operationIndex", m_operation);
        QJSValue feeds = engine().newObject();
        feeds.setProperty("cutting", r.feeds.cuttingMmPerMin);
        feeds.setProperty("plunge", r.feeds.plungeMmPerMin);
        feeds.setProperty("entry", r.feeds.entryMmPerMin);
        feeds.setProperty("exit", r.feeds.exitMmPerMin);
        feeds.setProperty("finishing", r.feeds.finishingMmPerMin);
        section.setProperty("feeds", feeds);
        handle("onSection", {section});
    }
    void sectionEnd(const SectionEnd&) override { handle("onSectionEnd", {}); }
    void programStop(const ProgramStop& r) override { handle("onStop", {r.optional}); }
    void passThrough(const PassThrough& r) override { handle("onPassThrough", {qs(r.text)}); }
    void setSource(const SourceRef& source) override
    {
        m_operation = source.operationIndex;
        m_run.m_kernel->writer().setOperation(source.operationIndex);
    }

    void setRecord(std::size_t index, const char* name)
    {
        m_recordName = name;
        m_run.m_where = "CL record " + std::to_string(index) + " " + name;
    }

private:
    QJSEngine& engine() { return m_run.m_engine; }

    bool handle(const char* handler, const QJSValueList& args)
    {
        bool handled = false;
        const bool ok = m_run.call(handler, args, handled);
        if (!handled)
            ++m_unhandled[std::string(m_recordName) + " (" + handler + ")"];
        return ok && handled;
    }
    void move(const char* handler, const QJSValueList& args, const Vec3& to)
    {
        handle(handler, args);
        m_run.m_kernel->setPosition(to);  // getCurrentPosition() is the start point inside a handler
    }
    void fail(const std::string& message)
    {
        m_run.m_failure = base::makeError(message + " (" + m_run.m_where + ")", m_run.m_postFile);
    }

    ScriptRun& m_run;
    std::map<std::string, int> m_unhandled;
    const char* m_recordName = "";
    int m_operation = -1;
};

void ScriptSink::arc(const Arc& r)
{
    const auto& start = m_run.m_kernel->position();
    if (!start) {
        fail("arc with an unknown start point: no motion before it");
        return;
    }
    const std::vector<ArcPiece> pieces = splitArc(*start, r, m_run.m_maxArcSweepDeg);
    if (pieces.empty()) {
        fail("degenerate arc: zero radius");
        return;
    }
    const std::string plane = arcPlane(r.normal);
    for (std::size_t i = 0; i < pieces.size() && !failed(); ++i) {
        const ArcPiece& p = pieces[i];
        m_run.m_kernel->setPosition(p.start);
        QJSValue info = engine().newObject();
        auto point = [this](const Vec3& v) {
            QJSValue o = engine().newObject();
            o.setProperty("x", v.x);
            o.setProperty("y", v.y);
            o.setProperty("z", v.z);
            return o;
        };
        info.setProperty("plane", qs(plane));
        info.setProperty("normal", point(p.normal));
        info.setProperty("helical", p.helical);
        info.setProperty("sweep", p.sweepDeg);
        info.setProperty("start", point(p.start));
        info.setProperty("turns", r.turns);
        info.setProperty("piece", static_cast<int>(i));
        info.setProperty("pieces", static_cast<int>(pieces.size()));
        handle("onCircular",
               {p.clockwise, p.center.x, p.center.y, p.center.z, p.end.x, p.end.y, p.end.z, r.feedMmPerMin, info});
        if (!m_run.m_handlers.count("onCircular"))
            break;  // one warning, not one per piece
    }
    m_run.m_kernel->setPosition(r.to);
}

void ScriptSink::cycle(const Cycle& r)
{
    QJSValue cycle = engine().newObject();
    cycle.setProperty("kind", QString(toolpath::name(r.kind)));
    cycle.setProperty("clearanceZ", r.clearanceZ);
    cycle.setProperty("retractZ", r.retractZ);
    cycle.setProperty("topZ", r.topZ);
    cycle.setProperty("bottomZ", r.bottomZ);
    cycle.setProperty("peck", r.peckMm);
    cycle.setProperty("dwell", r.dwellSeconds);
    cycle.setProperty("feed", r.feedMmPerMin);
    QJSValue holes = engine().newArray(static_cast<uint>(r.holes.size()));
    for (std::size_t i = 0; i < r.holes.size(); ++i) {
        QJSValue hole = engine().newObject();
        hole.setProperty("x", r.holes[i].x);
        hole.setProperty("y", r.holes[i].y);
        hole.setProperty("z", r.holes[i].z);
        holes.setProperty(static_cast<quint32>(i), hole);
    }
    cycle.setProperty("holes", holes);
    handle("onCycle", {cycle});
    // After a cycle the tool stands over the last hole at the clearance plane.
    if (!r.holes.empty())
        m_run.m_kernel->setPosition(Vec3{r.holes.back().x, r.holes.back().y, r.clearanceZ});
}

ScriptRun::ScriptRun(std::string postFile, const PostContext& context) :
    m_postFile(std::move(postFile)),
    m_kernel(std::make_unique<ScriptKernel>(&m_engine, m_postFile))
{
    // Only the ECMAScript built-ins plus the kernel: no console, no file or network access.
    QJSEngine::setObjectOwnership(m_kernel.get(), QJSEngine::CppOwnership);
    QJSValue global = m_engine.globalObject();
    QJSValue kernel = m_engine.newQObject(m_kernel.get());
    global.setProperty("__camwbKernel", kernel);
    for (const char* name : {"createFormat", "createVariable", "createModal", "writeComment", "writeln", "warning",
                             "error", "setBlockNumbering", "getCurrentPosition"})
        global.setProperty(name, kernel.property(name));  // QObject methods stay bound to the kernel
    global.setProperty("programName", qs(context.programName));
    global.setProperty("dateString", qs(formatDateUtc(context.dateEpochSeconds)));
    global.setProperty("user", qs(context.user));
    global.setProperty("version", qs(context.version));
    m_trampoline = m_engine.evaluate(QString::fromUtf8(kPrelude), QStringLiteral("<camwb-kernel>"));
}

ScriptRun::~ScriptRun() = default;

base::Error ScriptRun::scriptError(const QJSValue& thrown, const std::string& where)
{
    std::string message;
    int line = 0;
    if (thrown.isError()) {
        line = thrown.property("lineNumber").toInt();
        const std::string text = thrown.property("message").toString().toStdString();
        const std::optional<std::string> postError = m_kernel->takePostError();
        message = postError && *postError == text ? text : thrown.toString().toStdString();
    } else {
        message = "uncaught exception: " + wordText(thrown);
    }
    if (!where.empty())
        message += " (" + where + ")";
    return base::makeError(message, m_postFile, line);
}

base::Status ScriptRun::evaluate(const std::string& source, PostInfo& info)
{
    QStringList stack;
    const QJSValue result = m_engine.evaluate(qs(source), qs(m_postFile), 1, &stack);
    if (result.isError())
        return scriptError(result, {});
    if (!stack.isEmpty()) {  // a thrown non-Error value: the stack's first frame is "function:line:column:file"
        const QStringList parts = stack.first().split(QLatin1Char(':'));
        return base::makeError("uncaught exception: " + wordText(result), m_postFile,
                               parts.size() > 1 ? parts[1].toInt() : 0);
    }
    m_post = m_engine.globalObject().property("post");
    if (!m_post.isObject())
        return base::makeError("the post script defines no `post` object", m_postFile);
    auto text = [this](const char* name) {
        const QJSValue value = m_post.property(name);
        return value.isUndefined() || value.isNull() ? std::string() : value.toString().toStdString();
    };
    info.filePath = m_postFile;
    info.id = text("id");
    if (info.id.empty())
        info.id = std::filesystem::path(m_postFile).stem().string();
    info.description = text("description");
    info.vendor = text("vendor");
    info.extension = text("extension");
    if (info.extension.empty())
        info.extension = "nc";
    if (!info.extension.empty() && info.extension.front() == '.')
        info.extension.erase(0, 1);
    m_postId = info.id;
    const QJSValue sweep = m_post.property("maxArcSweep");
    if (sweep.isNumber()) {
        if (!(sweep.toNumber() >= 1 && sweep.toNumber() <= 360))
            return base::makeError("post.maxArcSweep must be 1..360 degrees", m_postFile);
        m_maxArcSweepDeg = sweep.toNumber();
    }
    for (const char* name : kHandlerNames) {
        QJSValue handler = m_post.property(name);
        if (!handler.isCallable())
            handler = m_engine.globalObject().property(name);
        if (handler.isCallable())
            m_handlers.emplace(name, handler);
    }
    return {};
}

bool ScriptRun::call(const char* name, const QJSValueList& args, bool& handled)
{
    handled = false;
    if (m_failure)
        return false;
    const auto it = m_handlers.find(name);
    if (it == m_handlers.end())
        return true;
    handled = true;
    QJSValue argArray = m_engine.newArray(static_cast<uint>(args.size()));
    for (int i = 0; i < args.size(); ++i)
        argArray.setProperty(static_cast<quint32>(i), args[i]);
    const QJSValue result = m_trampoline.call({it->second, m_post, argArray});
    if (result.isError()) {  // the trampoline itself failed (should not happen)
        m_failure = scriptError(result, std::string("in ") + name);
        return false;
    }
    if (result.isObject() && result.hasOwnProperty("thrown")) {
        m_failure =
            scriptError(result.property("thrown"), std::string("in ") + name + (m_where.empty() ? "" : ", " + m_where));
        return false;
    }
    return true;
}

base::Result<PostOutput> ScriptRun::play(const Toolpath& toolpath)
{
    ScriptSink sink(*this);
    bool unused = false;
    m_where.clear();
    call("onOpen", {}, unused);
    for (std::size_t i = 0; i < toolpath.size() && !m_failure; ++i) {
        sink.setRecord(i, toolpath::recordName(toolpath.record(i)));
        sink.setSource(toolpath.source(i));
        dispatch(toolpath.record(i), sink);
    }
    m_where.clear();
    m_kernel->writer().setOperation(-1);
    if (!m_failure)
        call("onClose", {}, unused);
    if (m_failure)
        return *m_failure;

    PostOutput output;
    output.text = m_kernel->writer().text();
    output.lineOperation = m_kernel->writer().lineOperation();
    output.messages = m_kernel->messages();
    for (const auto& [what, count] : sink.unhandled())
        output.messages.push_back({PostMessage::Severity::Warning,
                                   "post " + m_postId + " has no handler for " + what + "; " + std::to_string(count) +
                                       (count == 1 ? " record" : " records") + " not output",
                                   m_postFile, 0});
    return output;
}

}  // namespace camwb::post
