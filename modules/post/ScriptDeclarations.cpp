// Reading a post script's declarations after it is evaluated: identity, capabilities, typed
// properties, machines, the C++ block templates and post.fiveAxis. Anything malformed is a load
// error naming the post file and the line of the key.
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

std::string str(const QJSValue& value) { return value.toString().toStdString(); }

constexpr const char* kCapabilityKeys[] = {"arcPlanes",    "helicalArcs",  "maxArcSweep", "maxHelixSweep",
                                           "minArcRadius", "maxArcRadius", "arcWords",    "tolerance",
                                           "cycles",       "maxAxes"};

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
    // Which controls the post writes for (kinematics::Machine::control): a GUI offers the post for
    // the machines with one of them.
    if (const QJSValue controls = m_post.property("controls"); controls.isArray()) {
        for (int i = 0; i < controls.property("length").toInt(); ++i)
            info.controls.push_back(str(controls.property(static_cast<quint32>(i))));
    } else if (!controls.isUndefined()) {
        return declError("post.controls must be an array of control names", "controls");
    }
    info.defaultMachine = text(m_post, "machine");
    if (!info.defaultMachine.empty() && !info.machines.empty() &&
        std::find(info.machines.begin(), info.machines.end(), info.defaultMachine) == info.machines.end())
        return declError("post.machine \"" + info.defaultMachine + "\" is not in post.machines", "machine");

    for (int i = 0; i < static_cast<int>(Handler::Count); ++i) {
        QJSValue handler = m_post.property(handlerName(static_cast<Handler>(i)));
        if (!handler.isCallable())
            handler = m_engine.globalObject().property(handlerName(static_cast<Handler>(i)));
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
