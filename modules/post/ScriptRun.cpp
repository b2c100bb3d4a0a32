#include "post/detail/ScriptRun.h"

#include "base/NumberFormat.h"
#include "toolpath/RecordNames.h"

#include <QJSValueIterator>
#include <QStringList>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace camwb::post {

namespace {

// Evaluated before the post: a clock and a random generator that repeat, variadic writeBlock, and
// the handler trampoline. Date answers the run's injected time (SOURCE_DATE_EPOCH) and Math.random
// a fixed-seed sequence, so that the same input gives the same bytes whatever a post reads. The
// trampoline catches what a handler throws, so that a thrown non-Error value is still a failure.
const char* kPrelude = R"JS(
(function (global, epochMs) {
    var RealDate = global.Date;
    function InjectedDate() {
        if (!(this instanceof InjectedDate))
            return new RealDate(epochMs).toString();
        var args = arguments.length ? Array.prototype.slice.call(arguments) : [epochMs];
        return new (Function.prototype.bind.apply(RealDate, [null].concat(args)))();
    }
    InjectedDate.prototype = RealDate.prototype;
    InjectedDate.now = function () { return epochMs; };
    InjectedDate.UTC = RealDate.UTC;
    InjectedDate.parse = RealDate.parse;
    global.Date = InjectedDate;
    var state = 0x9e3779b9;
    Math.random = function () {  // mulberry32
        state = (state + 0x6d2b79f5) | 0;
        var t = Math.imul(state ^ (state >>> 15), 1 | state);
        t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
        return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
})(this, __camwbEpochMs);
var writeBlock = (function (kernel) {
    return function writeBlock() { kernel.writeBlockWords(Array.prototype.slice.call(arguments)); };
})(__camwbKernel);
var __camwbAnswer = function (f, self) {  // a post function asked for a value (post.fiveAxis.output())
    try { return { value: f.apply(self, []) }; } catch (e) { return { thrown: e }; }
};
(function (f, self, args) {
    try { f.apply(self, args); return undefined; } catch (e) { return { thrown: e }; }
})
)JS";

constexpr const char* kHandlerNames[] = {
    "onOpen",       "onSection",     "onToolChange",   "onSpindle",    "onCoolant",       "onFeedMode",
    "onWorkOffset", "onRapid",       "onLinear",       "onCircular",   "onLinear5D",      "onCycle",
    "onCyclePoint", "onCycleEnd",    "onComment",      "onCutterComp", "onDwell",         "onSectionEnd",
    "onStop",       "onPassThrough", "onWorkingPlane", "onClose",      "onFiveAxisBegin", "onFiveAxisEnd"};
static_assert(std::size(kHandlerNames) == static_cast<std::size_t>(Handler::Count), "a name for every handler");

QString qs(const std::string& text) { return QString::fromStdString(text); }
std::string str(const QJSValue& value) { return value.toString().toStdString(); }

std::string seconds(std::chrono::milliseconds budget)
{
    return base::NumberFormat{3, true}.format(static_cast<double>(budget.count()) / 1000.0);
}

}  // namespace

std::string counted(int count, const char* one, const char* many)
{
    return std::to_string(count) + " " + (count == 1 ? one : many);
}

const char* handlerName(Handler handler) { return kHandlerNames[static_cast<int>(handler)]; }

ScriptRun::ScriptRun(std::string postFile, const PostContext& context, std::chrono::milliseconds budget) :
    m_postFile(std::move(postFile)),
    m_kernel(std::make_unique<ScriptKernel>(&m_engine, m_postFile)),
    m_watchdog(m_engine, budget)
{
    // Only the ECMAScript built-ins plus the kernel: no console, no file, network or process access.
    QJSEngine::setObjectOwnership(m_kernel.get(), QJSEngine::CppOwnership);
    QJSValue global = m_engine.globalObject();
    QJSValue kernel = m_engine.newQObject(m_kernel.get());
    global.setProperty("__camwbKernel", kernel);
    for (const char* name : {"createFormat",      "createVariable",
                             "createModal",       "createPending",
                             "writeComment",      "writeln",
                             "warning",           "error",
                             "setBlockNumbering", "getCurrentPosition",
                             "getCurrentAxis",    "getProperty",
                             "expandCyclePoint",  "machiningSeconds",
                             "getFiveAxisTravel", "getMachinePose",
                             "include",           "readPostFile",
                             "openFile",          "closeFile"})
        global.setProperty(name, kernel.property(name));  // QObject methods stay bound to the kernel
    global.setProperty("programName", qs(context.programName));
    global.setProperty("dateString", qs(formatDateUtc(context.dateEpochSeconds)));
    global.setProperty("outputName", qs(context.outputName));
    global.setProperty("user", qs(context.user));
    global.setProperty("version", qs(context.version));
    global.setProperty("machine", QJSValue(QJSValue::NullValue));
    setJob({});
    global.setProperty("__camwbEpochMs", static_cast<double>(context.dateEpochSeconds) * 1000.0);
    m_trampoline = m_engine.evaluate(QString::fromUtf8(kPrelude), QStringLiteral("<camwb-kernel>"));
}

ScriptRun::~ScriptRun() = default;

void ScriptRun::setProperties(const std::map<std::string, PropertyValue>& values)
{
    QJSValue object = m_engine.newObject();
    for (const auto& [name, value] : values)
        object.setProperty(qs(name), scriptValue(value));
    m_kernel->setProperties(object);
}

QJSValue ScriptRun::scriptValue(const PropertyValue& value)
{
    switch (value.type) {
    case PropertyType::Bool:
        return value.boolean;
    case PropertyType::Integer:
    case PropertyType::Number:
        return value.number;
    case PropertyType::Enum:
    case PropertyType::String:
        break;
    }
    return qs(value.text);
}

bool ScriptRun::setSectionProperties(const std::vector<std::pair<std::string, std::string>>& values)
{
    if (values.empty()) {
        m_kernel->setSectionProperties(QJSValue());
        return true;
    }
    QJSValue object = m_engine.newObject();
    for (const auto& [name, text] : values) {
        const auto def = std::find_if(m_propertyDefs.begin(), m_propertyDefs.end(),
                                      [&](const PropertyDef& d) { return d.name == name; });
        if (def == m_propertyDefs.end()) {
            fail("the operation sets post property '" + name + "', which post " + m_postId + " does not declare");
            return false;
        }
        if (!def->perOperation) {
            fail("post property '" + name + "' applies to the whole program: post " + m_postId +
                 " does not take it per operation");
            return false;
        }
        auto parsed = parsePropertyValue(*def, text);
        if (!parsed) {
            fail("the operation's " + parsed.error().message);
            return false;
        }
        object.setProperty(qs(name), scriptValue(parsed.value()));
    }
    m_kernel->setSectionProperties(object);
    return true;
}

void ScriptRun::setMachine(const kinematics::Machine& machine)
{
    m_machine = machine;
    QJSValue m = m_engine.newObject();
    m.setProperty("id", qs(machine.id));
    m.setProperty("name", qs(machine.name));
    m.setProperty("control", qs(machine.control));
    QJSValue axes = m_engine.newArray(static_cast<uint>(machine.axes.size()));
    for (std::size_t i = 0; i < machine.axes.size(); ++i) {
        QJSValue axis = m_engine.newObject();
        axis.setProperty("name", qs(machine.axes[i].name));
        axis.setProperty("rotary", machine.axes[i].rotary);
        axis.setProperty("endless", machine.axes[i].endless);
        axis.setProperty("min",
                         machine.axes[i].endless ? QJSValue(QJSValue::NullValue) : QJSValue(machine.axes[i].min));
        axis.setProperty("max",
                         machine.axes[i].endless ? QJSValue(QJSValue::NullValue) : QJSValue(machine.axes[i].max));
        axes.setProperty(static_cast<quint32>(i), axis);
    }
    m.setProperty("axes", axes);
    m.setProperty("spindleMinRpm", machine.spindleMinRpm);
    m.setProperty("spindleMaxRpm", machine.spindleMaxRpm);
    m.setProperty("toolStations", machine.toolStations);
    m.setProperty("maxToolDiameter", machine.maxToolDiameterMm);
    m.setProperty("maxToolLength", machine.maxToolLengthMm);
    m.setProperty("manualToolChange", machine.manualToolChange);
    m.setProperty("minCuttingFeed", machine.minCuttingFeedMmPerMin);
    m.setProperty("maxCuttingFeed", machine.maxCuttingFeedMmPerMin);
    m.setProperty("rapid", machine.rapidMmPerMin);
    QJSValue coolants = m_engine.newArray(static_cast<uint>(machine.coolants.size()));
    for (std::size_t i = 0; i < machine.coolants.size(); ++i)
        coolants.setProperty(static_cast<quint32>(i), qs(machine.coolants[i]));
    m.setProperty("coolants", coolants);
    // The chain, so a five-axis post can refuse a machine without one: null for three axes, else
    // {type, rotaries: [{axis, table, direction: [x, y, z]}]} in the file's order.
    QJSValue chain(QJSValue::NullValue);
    if (machine.kinematics.fiveAxis()) {
        chain = m_engine.newObject();
        chain.setProperty("type", kinematics::name(machine.kinematics.type));
        QJSValue rotaries = m_engine.newArray(2);
        for (quint32 i = 0; i < 2; ++i) {
            const kinematics::RotaryJoint& j = machine.kinematics.joints[i];
            QJSValue joint = m_engine.newObject();
            joint.setProperty("axis", qs(j.axis));
            joint.setProperty("table", j.onTable);
            QJSValue direction = m_engine.newArray(3);
            direction.setProperty(0, j.direction.x);
            direction.setProperty(1, j.direction.y);
            direction.setProperty(2, j.direction.z);
            joint.setProperty("direction", direction);
            rotaries.setProperty(i, joint);
        }
        chain.setProperty("rotaries", rotaries);
    }
    m.setProperty("kinematics", chain);
    m_engine.globalObject().setProperty("machine", m);
}

void ScriptRun::setJob(const JobFacts& facts)
{
    QJSValue job = m_engine.newObject();
    job.setProperty("name", qs(facts.name));
    if (facts.stock) {
        QJSValue stock = m_engine.newObject();
        stock.setProperty("min", scriptPoint(m_engine, facts.stock->min));
        stock.setProperty("max", scriptPoint(m_engine, facts.stock->max));
        job.setProperty("stock", stock);
    } else {
        job.setProperty("stock", QJSValue(QJSValue::NullValue));
    }
    m_engine.globalObject().setProperty("job", job);
}

std::string ScriptRun::where() const
{
    if (m_recordIndex < 0)
        return {};
    return "CL record " + std::to_string(m_recordIndex) + " " + m_recordName;
}

void ScriptRun::fail(const std::string& message)
{
    const std::string at = where();
    m_failure = base::makeError(message + (at.empty() ? "" : " (" + at + ")"), m_postFile);
}

base::Error ScriptRun::scriptError(const QJSValue& thrown, const std::string& context)
{
    std::string message;
    std::string file = m_postFile;
    int line = 0;
    if (thrown.isError()) {
        line = thrown.property("lineNumber").toInt();
        file = errorFile(thrown, m_postFile);  // the post, or a file it included
        const std::string text = str(thrown.property("message"));
        const std::optional<std::string> postError = m_kernel->takePostError();
        message = postError && *postError == text ? text : str(thrown);
    } else {
        message = "uncaught exception: " + wordText(thrown);
    }
    if (!context.empty())
        message += " (" + context + ")";
    return base::makeError(message, file, line);
}

bool ScriptRun::call(Handler handler, const QJSValueList& args)
{
    if (m_failure)
        return false;
    const QJSValue& function = m_handlers[static_cast<int>(handler)];
    if (!function.isCallable())
        return true;
    QJSValue argArray = m_engine.newArray(static_cast<uint>(args.size()));
    for (int i = 0; i < args.size(); ++i)
        argArray.setProperty(static_cast<quint32>(i), args[i]);
    m_watchdog.enter();
    const QJSValue result = m_trampoline.call({function, m_post, argArray});
    const bool interrupted = m_watchdog.leave();
    auto context = [&] {  // only on failure: building it for every call would cost every move
        const std::string at = where();
        return std::string("in ") + handlerName(handler) + (at.empty() ? "" : ", " + at);
    };
    if (interrupted) {
        const QJSValue thrown = result.isObject() ? result.property("thrown") : QJSValue();
        m_failure = base::makeError("the post script ran longer than its budget of " + seconds(m_watchdog.budget()) +
                                        " s and was interrupted (" + context() + ")",
                                    m_postFile, thrown.isError() ? thrown.property("lineNumber").toInt() : 0);
        return false;
    }
    if (result.isError()) {  // the trampoline itself failed (should not happen)
        m_failure = scriptError(result, context());
        return false;
    }
    if (result.isObject() && result.hasOwnProperty("thrown")) {
        m_failure = scriptError(result.property("thrown"), context());
        return false;
    }
    return true;
}

std::optional<std::string> ScriptRun::answer(const QJSValue& function, const std::string& what)
{
    if (m_failure)
        return std::nullopt;
    m_watchdog.enter();
    const QJSValue result = m_engine.globalObject().property("__camwbAnswer").call({function, m_post});
    const bool interrupted = m_watchdog.leave();
    const std::string at = where();
    const std::string context = "in " + what + (at.empty() ? "" : ", " + at);
    if (interrupted) {
        m_failure = base::makeError("the post script ran longer than its budget of " + seconds(m_watchdog.budget()) +
                                        " s and was interrupted (" + context + ")",
                                    m_postFile);
        return std::nullopt;
    }
    if (result.isError() || !result.isObject()) {
        m_failure = scriptError(result, context);
        return std::nullopt;
    }
    if (result.hasOwnProperty("thrown")) {
        m_failure = scriptError(result.property("thrown"), context);
        return std::nullopt;
    }
    return str(result.property("value"));
}

base::Status ScriptRun::evaluate(const std::string& source, PostInfo& info)
{
    QStringList stack;
    m_watchdog.enter();
    const QJSValue result = m_engine.evaluate(qs(source), qs(m_postFile), 1, &stack);
    if (m_watchdog.leave())
        return base::makeError("the post script ran longer than its budget of " + seconds(m_watchdog.budget()) +
                                   " s while loading and was interrupted",
                               m_postFile, result.isError() ? result.property("lineNumber").toInt() : 0);
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
    return readDeclarations(source, info);
}

}  // namespace camwb::post
