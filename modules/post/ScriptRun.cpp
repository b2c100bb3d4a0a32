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

constexpr const char* kCapabilityKeys[] = {"arcPlanes",    "helicalArcs",  "maxArcSweep", "maxHelixSweep",
                                           "minArcRadius", "maxArcRadius", "arcWords",    "tolerance",
                                           "cycles",       "maxAxes"};

QString qs(const std::string& text) { return QString::fromStdString(text); }
std::string str(const QJSValue& value) { return value.toString().toStdString(); }

std::string seconds(std::chrono::milliseconds budget)
{
    return base::NumberFormat{3, true}.format(static_cast<double>(budget.count()) / 1000.0);
}

// Line of the first `key:` (an object key) at or after `from` in the source, 0 when not found.
int lineOfKey(const std::string& source, const std::string& key, std::size_t from = 0)
{
    for (std::size_t at = source.find(key, from); at != std::string::npos; at = source.find(key, at + 1)) {
        const bool startsWord = at == 0 || !(std::isalnum(static_cast<unsigned char>(source[at - 1])) ||
                                             source[at - 1] == '_' || source[at - 1] == '$');
        std::size_t after = at + key.size();
        if (after < source.size() && (source[after] == '"' || source[after] == '\''))
            ++after;  // quoted keys
        while (after < source.size() && (source[after] == ' ' || source[after] == '\t'))
            ++after;
        if (startsWord && after < source.size() && (source[after] == ':' || source[after] == '='))
            return 1 + static_cast<int>(std::count(source.begin(), source.begin() + at, '\n'));
    }
    return 0;
}

bool isCycleKind(const std::string& kind)
{
    for (toolpath::CycleKind k :
         {toolpath::CycleKind::Drill, toolpath::CycleKind::DrillDwell, toolpath::CycleKind::Peck,
          toolpath::CycleKind::ChipBreak, toolpath::CycleKind::Tap, toolpath::CycleKind::Bore})
        if (kind == toolpath::name(k))
            return true;
    return false;
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
    for (const char* name :
         {"createFormat", "createVariable", "createModal", "createPending", "writeComment", "writeln", "warning",
          "error", "setBlockNumbering", "getCurrentPosition", "getCurrentAxis", "getProperty", "expandCyclePoint",
          "machiningSeconds", "getFiveAxisTravel", "getMachinePose", "include"})
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

base::Status ScriptRun::readDeclarations(const std::string& source, PostInfo& info)
{
    auto text = [this](const QJSValue& object, const char* name) {
        const QJSValue value = object.property(name);
        return value.isUndefined() || value.isNull() ? std::string() : str(value);
    };
    auto declError = [&](const std::string& message, const std::string& key, std::size_t from = 0) {
        return base::makeError(message, m_postFile, lineOfKey(source, key, from));
    };

    info.filePath = m_postFile;
    info.id = std::filesystem::path(m_postFile).stem().string();
    if (const std::string declared = text(m_post, "id"); !declared.empty() && declared != info.id)
        return declError("post.id \"" + declared + "\" does not match the file name " + info.id +
                             ".js; the file name is the post id",
                         "id");
    info.description = text(m_post, "description");
    info.vendor = text(m_post, "vendor");
    info.extension = text(m_post, "extension");
    if (!info.extension.empty() && info.extension.front() == '.')
        info.extension.erase(0, 1);
    if (info.extension.empty())
        info.extension = "nc";
    m_postId = info.id;

    // Capabilities: unknown keys are refused, so that a typo cannot silently change the arc policy.
    PostCapabilities& caps = info.capabilities;
    const QJSValue declared = m_post.property("capabilities");
    if (!declared.isUndefined()) {
        if (!declared.isObject())
            return declError("post.capabilities must be an object", "capabilities");
        QJSValueIterator it(declared);
        while (it.hasNext()) {
            it.next();
            const std::string key = it.name().toStdString();
            if (std::find_if(std::begin(kCapabilityKeys), std::end(kCapabilityKeys),
                             [&](const char* k) { return key == k; }) == std::end(kCapabilityKeys))
                return declError("post.capabilities." + key + " is not a capability", key);
        }
        auto number = [&](const char* key, double& target, double min, double max) -> base::Status {
            const QJSValue value = declared.property(key);
            if (value.isUndefined())
                return {};
            if (!value.isNumber() || !(value.toNumber() >= min && value.toNumber() <= max))
                return declError(std::string("post.capabilities.") + key + " must be a number in " +
                                     base::NumberFormat{6, true}.format(min) + ".." +
                                     base::NumberFormat{6, true}.format(max),
                                 key);
            target = value.toNumber();
            return {};
        };
        auto strings = [&](const char* key, std::vector<std::string>& target, auto valid) -> base::Status {
            const QJSValue value = declared.property(key);
            if (value.isUndefined())
                return {};
            if (!value.isArray())
                return declError(std::string("post.capabilities.") + key + " must be an array of strings", key);
            target.clear();
            for (int i = 0; i < value.property("length").toInt(); ++i) {
                const std::string item = str(value.property(static_cast<quint32>(i)));
                if (!valid(item))
                    return declError(std::string("post.capabilities.") + key + ": unknown entry \"" + item + "\"", key);
                target.push_back(item);
            }
            return {};
        };
        double maxAxes = caps.maxAxes;
        for (base::Status s :
             {number("maxArcSweep", caps.maxArcSweepDeg, 1, 360),
              number("maxHelixSweep", caps.maxHelixSweepDeg, 1, 36000),
              number("minArcRadius", caps.minArcRadiusMm, 0, 1e9), number("maxArcRadius", caps.maxArcRadiusMm, 0, 1e9),
              number("tolerance", caps.toleranceMm, 1e-6, 10), number("maxAxes", maxAxes, 3, 5),
              strings("arcPlanes", caps.arcPlanes,
                      [](const std::string& p) { return BlockTemplates::planeIndex(p) >= 0; }),
              strings("cycles", caps.cycles, isCycleKind)})
            if (!s)
                return s;
        caps.maxAxes = static_cast<int>(maxAxes);
        caps.cyclesDeclared = !declared.property("cycles").isUndefined();
        if (const QJSValue helical = declared.property("helicalArcs"); helical.isBool()) {
            if (!helical.toBool())
                caps.helicalPlanes.clear();
        } else if (!helical.isUndefined()) {  // the planes it writes helices in
            if (!helical.isArray())
                return declError("post.capabilities.helicalArcs must be true, false or an array of planes",
                                 "helicalArcs");
            if (base::Status s = strings("helicalArcs", caps.helicalPlanes,
                                         [](const std::string& p) { return BlockTemplates::planeIndex(p) >= 0; });
                !s)
                return s;
        }
        if (const QJSValue words = declared.property("arcWords"); !words.isUndefined()) {
            if (str(words) != "center" && str(words) != "radius")
                return declError("post.capabilities.arcWords must be \"center\" or \"radius\"", "arcWords");
            caps.arcRadiusWords = str(words) == "radius";
        }
        if (caps.minArcRadiusMm > caps.maxArcRadiusMm)
            return declError("post.capabilities.minArcRadius is above maxArcRadius", "minArcRadius");
    }
    m_capabilities = caps;

    // Typed user properties, with their defaults checked now rather than at the first run.
    const QJSValue properties = m_post.property("properties");
    const std::size_t propertiesAt = source.find("properties");
    if (!properties.isUndefined()) {
        if (!properties.isObject() || properties.isArray())
            return declError("post.properties must be an object of property declarations", "properties");
        QJSValueIterator it(properties);
        while (it.hasNext()) {
            it.next();
            PropertyDef def;
            def.name = it.name().toStdString();
            def.line = lineOfKey(source, def.name, propertiesAt == std::string::npos ? 0 : propertiesAt);
            const QJSValue d = it.value();
            const std::string at = "post.properties." + def.name;
            auto fail = [&](const std::string& message) {
                return base::makeError(at + ": " + message, m_postFile, def.line);
            };
            if (!d.isObject())
                return fail("expected {title, description, type, default}");
            const std::optional<PropertyType> type = propertyTypeFromName(text(d, "type"));
            if (!type)
                return fail("type must be bool, int, number, enum or string");
            def.type = *type;
            def.title = text(d, "title").empty() ? def.name : text(d, "title");
            def.description = text(d, "description");
            const QJSValue value = d.property("default");
            if (value.isUndefined())
                return fail("no default");
            def.defaultValue = value.isBool() ? (value.toBool() ? "true" : "false") : wordText(value);
            if (value.isNumber())
                def.defaultValue = base::NumberFormat{12, true}.format(value.toNumber());
            for (const char* bound : {"min", "max"}) {
                const QJSValue limit = d.property(bound);
                if (limit.isUndefined())
                    continue;
                if (!limit.isNumber() || (def.type != PropertyType::Integer && def.type != PropertyType::Number))
                    return fail(std::string(bound) + " is for int and number properties, as a number");
                (std::string(bound) == "min" ? def.min : def.max) = limit.toNumber();
            }
            if (def.type == PropertyType::Enum) {
                const QJSValue values = d.property("values");
                for (int i = 0; values.isArray() && i < values.property("length").toInt(); ++i)
                    def.values.push_back(str(values.property(static_cast<quint32>(i))));
                if (def.values.empty())
                    return fail("an enum needs values: [\"a\", \"b\", ...]");
            }
            if (auto parsed = parsePropertyValue(def, def.defaultValue); !parsed)
                return fail("default: " + parsed.error().message);
            // Read by the post per section (in its handlers), so an operation may set its own.
            const QJSValue perOperation = d.property("perOperation");
            if (!perOperation.isUndefined() && !perOperation.isBool())
                return fail("perOperation must be true or false");
            def.perOperation = perOperation.toBool();
            info.properties.push_back(std::move(def));
        }
    }
    m_propertyDefs = info.properties;

    if (const QJSValue machines = m_post.property("machines"); machines.isArray()) {
        for (int i = 0; i < machines.property("length").toInt(); ++i)
            info.machines.push_back(str(machines.property(static_cast<quint32>(i))));
    } else if (!machines.isUndefined()) {
        return declError("post.machines must be an array of machine ids", "machines");
    }
    info.defaultMachine = text(m_post, "machine");
    if (!info.defaultMachine.empty() && !info.machines.empty() &&
        std::find(info.machines.begin(), info.machines.end(), info.defaultMachine) == info.machines.end())
        return declError("post.machine \"" + info.defaultMachine + "\" is not in post.machines", "machine");

    for (int i = 0; i < static_cast<int>(Handler::Count); ++i) {
        QJSValue handler = m_post.property(kHandlerNames[i]);
        if (!handler.isCallable())
            handler = m_engine.globalObject().property(kHandlerNames[i]);
        m_handlers[i] = handler.isCallable() ? handler : QJSValue();
    }
    if (caps.cyclesDeclared && !caps.cycles.empty() && !has(Handler::Cycle) && !has(Handler::CyclePoint))
        return declError("post.capabilities.cycles lists native cycles but the post has no onCycle or onCyclePoint",
                         "cycles");

    auto templates = parseBlockTemplates(m_post.property("blocks"), m_postFile, lineOfKey(source, "blocks"));
    if (!templates)
        return templates.error();
    m_templates = std::move(templates).value();
    return readFiveAxis(source);
}

// post.fiveAxis = {output, feed, poleCone, reconfigure, retract, reconfigureStep}: unknown keys
// and values are refused, as for the capabilities.
base::Status ScriptRun::readFiveAxis(const std::string& source)
{
    const QJSValue declared = m_post.property("fiveAxis");
    if (declared.isUndefined())
        return {};
    auto declError = [&](const std::string& message) {
        return base::makeError("post.fiveAxis" + message, m_postFile, lineOfKey(source, "fiveAxis"));
    };
    if (!declared.isObject())
        return declError(" must be an object {output, feed, poleCone, reconfigure, retract, reconfigureStep}");
    if (m_capabilities.maxAxes < 5)
        return declError(" needs post.capabilities.maxAxes 5");
    FiveAxisDeclaration five;
    auto choice = [&](const QJSValue& value, const char* a, const char* b, bool& second) {
        second = str(value) == b;
        return str(value) == a || second;
    };
    auto number = [](const QJSValue& value, double min, double max, double& out) {
        out = value.toNumber();
        return value.isNumber() && out >= min && out <= max;
    };
    QJSValueIterator it(declared);
    while (it.hasNext()) {
        it.next();
        const std::string key = it.name().toStdString();
        const QJSValue value = it.value();
        bool refuse = false;
        bool ok = false;
        if ((key == "output" || key == "feed") && value.isCallable()) {
            // Asked at each five-axis section, under that section's post properties.
            (key == "output" ? five.chooseOutput : five.chooseFeed) = value;
            ok = true;
        } else if (key == "output")
            ok = choice(value, "tip", "machine", five.machineCoordinates);
        else if (key == "feed") {
            const std::string text = str(value);
            ok = text == "tip" || text == "combined" || text == "inverse";
            five.feed = text == "combined"  ? FiveAxisFeed::Combined
                        : text == "inverse" ? FiveAxisFeed::InverseTime
                                            : FiveAxisFeed::Tip;
        } else if (key == "reconfigure")
            ok = choice(value, "retract", "refuse", refuse);
        else if (key == "poleCone")
            ok = number(value, 0, 10, five.options.poleConeDeg);
        else if (key == "retract")
            ok = number(value, 0.001, 10000, five.options.retractMm);
        else if (key == "reconfigureStep")
            ok = number(value, 0.001, 360, five.options.reconfigureStepDeg);
        else
            return declError("." + key +
                             " is not a five-axis setting (output, feed, poleCone, reconfigure, retract, "
                             "reconfigureStep)");
        if (!ok)
            return declError("." + key + ": \"" + str(value) +
                             "\" is not accepted (output tip|machine, feed tip|combined|inverse, reconfigure "
                             "retract|refuse, poleCone 0..10 deg, retract > 0 mm, reconfigureStep > 0 deg)");
        if (key == "reconfigure")
            five.options.retractToReconfigure = !refuse;
    }
    m_fiveAxis = five;
    return {};
}

}  // namespace camwb::post
