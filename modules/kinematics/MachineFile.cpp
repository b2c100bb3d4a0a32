#include "base/AtomicFile.h"
#include "base/DataDirs.h"
#include "base/JsonRead.h"
#include "kinematics/Machine.h"
#include "kinematics/detail/ChainFile.h"
#include "toolpath/ProgramStats.h"

#include <algorithm>
#include <limits>

namespace camwb::kinematics {

using namespace base::jsonread;

namespace {

double optionalNumber(const Json& object, const char* key, const std::string& where, double fallback)
{
    return optionalMember(object, key, where) ? number(object, key, where) : fallback;
}

double positive(const Json& object, const char* key, const std::string& where, const char* what)
{
    const double value = number(object, key, where);
    if (!(value > 0))
        throw JsonFieldError{where + "." + key + ": expected " + what + " above 0"};
    return value;
}

// The limits a file leaves out (Machine.h says which defaults and why).
void applyMotionDefaults(Machine& m)
{
    const double linear = m.rapidMmPerMin > 0            ? m.rapidMmPerMin
                          : m.maxCuttingFeedMmPerMin > 0 ? m.maxCuttingFeedMmPerMin
                                                         : toolpath::kDefaultRapidMmPerMin;
    for (Axis& a : m.axes) {
        if (!a.velocityFromFile)
            a.maxVelocity = !a.rotary ? linear : a.maxRpm > 0 ? a.maxRpm * 360 : kDefaultRotaryDegPerMin;
        if (!a.accelerationFromFile)
            a.maxAcceleration = a.rotary ? kDefaultRotaryAccelerationDegPerS2 : kDefaultLinearAccelerationMmPerS2;
    }
    if (m.toolChangeSeconds <= 0)
        m.toolChangeSeconds = m.manualToolChange ? kDefaultManualToolChangeSeconds : kDefaultToolChangeSeconds;
    if (m.spindleRampSeconds <= 0)
        m.spindleRampSeconds = kDefaultSpindleRampSeconds;
}

Axis readAxis(const Json& a, const std::string& where)
{
    Axis axis;
    axis.name = text(a, "name", where);
    const std::string type = text(a, "type", where);
    if (type != "linear" && type != "rotary")
        throw JsonFieldError{where + ".type: expected \"linear\" or \"rotary\""};
    axis.rotary = type == "rotary";
    axis.endless = optionalMember(a, "endless", where) && boolean(a, "endless", where);
    if (axis.endless) {
        if (!axis.rotary)
            throw JsonFieldError{where + ": a linear axis cannot be endless"};
        // Both would be a contradiction: which one does the file mean?
        if (optionalMember(a, "min", where) || optionalMember(a, "max", where))
            throw JsonFieldError{where + ": an endless axis has no min or max (drop them, or \"endless\")"};
        axis.min = -std::numeric_limits<double>::infinity();
        axis.max = std::numeric_limits<double>::infinity();
    } else {
        axis.min = number(a, "min", where);
        axis.max = number(a, "max", where);
        if (axis.min > axis.max)
            throw JsonFieldError{where + ": min is above max"};
    }
    if (optionalMember(a, "maxRpm", where)) {
        if (!axis.rotary)
            throw JsonFieldError{where + ".maxRpm: only a rotary axis has one (a linear axis' speed is feed.rapid)"};
        axis.maxRpm = number(a, "maxRpm", where);
        if (axis.maxRpm <= 0)
            throw JsonFieldError{where + ".maxRpm: expected a speed above 0"};
    }
    if (optionalMember(a, "maxVelocity", where)) {
        if (axis.maxRpm > 0)  // two figures for one speed: which one does the file mean?
            throw JsonFieldError{where + ": maxRpm and maxVelocity both give the axis' speed (keep one)"};
        axis.maxVelocity = positive(a, "maxVelocity", where, "a speed");
        axis.velocityFromFile = true;
    }
    if (optionalMember(a, "maxAcceleration", where)) {
        axis.maxAcceleration = positive(a, "maxAcceleration", where, "an acceleration");
        axis.accelerationFromFile = true;
    }
    return axis;
}

void readToolChanger(const Json& changer, const std::string& at, Machine& m)
{
    m.manualToolChange = optionalMember(changer, "manual", at) && boolean(changer, "manual", at);
    m.toolStations = optionalMember(changer, "stations", at) ? integer(changer, "stations", at) : 0;
    if (m.manualToolChange && m.toolStations > 0)
        throw JsonFieldError{at + ": a manual tool change has no stations"};
    m.maxToolDiameterMm = optionalNumber(changer, "maxToolDiameter", at, 0);
    m.maxToolLengthMm = optionalNumber(changer, "maxToolLength", at, 0);
    if (optionalMember(changer, "changeSeconds", at))
        m.toolChangeSeconds = positive(changer, "changeSeconds", at, "a time");
}

void readFeed(const Json& feed, const std::string& at, Machine& m)
{
    m.minCuttingFeedMmPerMin = optionalNumber(feed, "minCutting", at, 0);
    m.maxCuttingFeedMmPerMin = optionalNumber(feed, "maxCutting", at, 0);
    m.rapidMmPerMin = optionalNumber(feed, "rapid", at, 0);
    if (m.maxCuttingFeedMmPerMin > 0 && m.minCuttingFeedMmPerMin > m.maxCuttingFeedMmPerMin)
        throw JsonFieldError{at + ": minCutting is above maxCutting"};
}

Machine readMachine(const Json& root)
{
    const std::string where = "machine";
    if (text(root, "format", where) != "camwb-machine")
        throw JsonFieldError{"not a CAM Workbench machine (format is not \"camwb-machine\")"};
    const int version = integer(root, "version", where);
    if (version > kMachineFormatVersion || version < 1)
        throw JsonFieldError{"machine format version " + std::to_string(version) + " is not supported (this is " +
                             std::to_string(kMachineFormatVersion) + ")"};
    Machine m;
    m.id = text(root, "id", where);
    m.name = text(root, "name", where);
    m.control = text(root, "control", where);
    const Json& axes = member(root, "axes", where);
    if (!axes.is_array())
        throw JsonFieldError{where + ".axes: expected an array"};
    for (std::size_t i = 0; i < axes.size(); ++i) {
        Axis axis = readAxis(axes[i], where + ".axes[" + std::to_string(i) + "]");
        if (m.axis(axis.name))
            throw JsonFieldError{where + ".axes: axis " + axis.name + " twice"};
        m.axes.push_back(std::move(axis));
    }
    if (const Json* spindle = optionalMember(root, "spindle", where)) {
        m.spindleMinRpm = optionalNumber(*spindle, "minRpm", where + ".spindle", 0);
        m.spindleMaxRpm = optionalNumber(*spindle, "maxRpm", where + ".spindle", 0);
        if (optionalMember(*spindle, "rampSeconds", where + ".spindle"))
            m.spindleRampSeconds = positive(*spindle, "rampSeconds", where + ".spindle", "a time");
    }
    if (const Json* changer = optionalMember(root, "toolChanger", where))
        readToolChanger(*changer, where + ".toolChanger", m);
    if (const Json* feed = optionalMember(root, "feed", where))
        readFeed(*feed, where + ".feed", m);
    if (const Json* coolants = optionalMember(root, "coolants", where)) {
        for (const Json& c : *coolants) {
            if (!c.is_string())
                throw JsonFieldError{where + ".coolants: expected strings"};
            const std::string mode = c.get<std::string>();
            if (mode != "flood" && mode != "mist" && mode != "throughTool")
                throw JsonFieldError{where + ".coolants: unknown coolant \"" + mode + "\" (flood, mist, throughTool)"};
            m.coolants.push_back(mode);
        }
    }
    if (const Json* chain = optionalMember(root, "kinematics", where)) {
        if (version < 2)
            throw JsonFieldError{where + ".kinematics: a kinematic chain needs format version 2"};
        m.kinematics = detail::readKinematicChain(*chain, where + ".kinematics", m);
    }
    applyMotionDefaults(m);
    return m;
}

}  // namespace

const Axis* Machine::axis(const std::string& axisName) const
{
    for (const Axis& a : axes)
        if (a.name == axisName)
            return &a;
    return nullptr;
}

bool Machine::hasCoolant(const std::string& mode) const
{
    return std::find(coolants.begin(), coolants.end(), mode) != coolants.end();
}

double estimateRapidMmPerMin(const Machine* machine)
{
    return machine != nullptr && machine->rapidMmPerMin > 0 ? machine->rapidMmPerMin : toolpath::kDefaultRapidMmPerMin;
}

Machine defaultLimitsMachine()
{
    Machine m;
    m.id = "default-limits";
    m.name = "default limits";
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (const char* name : {"X", "Y", "Z"})
        m.axes.push_back({name, false, -kInf, kInf});
    applyMotionDefaults(m);
    return m;
}

base::Result<Machine> parseMachine(const std::string& json, const std::string& path)
{
    auto root = parse(json, path);
    if (!root)
        return root.error();
    try {
        Machine machine = readMachine(root.value());
        machine.filePath = path;
        return machine;
    } catch (const JsonFieldError& e) {
        return base::makeError(e.message, path);
    }
}

base::Result<Machine> loadMachine(const std::string& path)
{
    auto content = base::readTextFile(path);
    if (!content)
        return content.error();
    return parseMachine(content.value(), path);
}

std::vector<std::string> defaultMachineDirs()
{
    return base::dataDirPaths("CAMWB_MACHINE_PATH", "machines", "resources/machines");
}

std::vector<base::DataFile> listMachineFiles()
{
    return base::listDataFiles(base::dataDirs("CAMWB_MACHINE_PATH", "machines", "resources/machines"), ".json");
}

base::Result<Machine> findMachine(const std::string& id, const std::vector<std::string>& dirs)
{
    if (id.size() > 5 && id.compare(id.size() - 5, 5, ".json") == 0)
        return loadMachine(id);  // a machine file named by its path, not looked up
    auto path = base::findDataFile("machine", id, ".json", dirs);
    if (!path)
        return path.error();
    auto machine = loadMachine(path.value());
    if (machine && machine->id != id)
        return base::makeError(
            "machine file says id \"" + machine->id + "\"; the file name is the id (" + id + ".json)", path.value());
    return machine;
}

}  // namespace camwb::kinematics
