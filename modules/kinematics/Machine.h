// A machine definition (resources/machines/<id>.json): what posts and the simulator need to know
// about a machine tool: its control, axes with travel (rotary axes possibly endless), spindle
// range, tool changer (or a manual change), feed limits and coolants. Jobs and `camwb-cli post
// --machine` pick one by id.
#pragma once

#include "base/DataDirs.h"
#include "base/Result.h"
#include "kinematics/KinematicChain.h"

#include <string>
#include <vector>

namespace camwb::kinematics {

struct Axis {
    std::string name;  // "X", "Y", "Z", "A", "B", "C"
    bool rotary = false;
    double min = 0;        // mm or degrees; an endless axis: -infinity ...
    double max = 0;        // ... and +infinity, so that a range check that ignores `endless` passes
    bool endless = false;  // a rotary axis that turns without limit (a rotary table's C)
    double maxRpm = 0;     // a rotary axis' top speed, 0: unknown
    // Motion limits the simulator's motion plan keeps. Always set after loading: the file's
    // "maxVelocity" (mm/min, deg/min) and "maxAcceleration" (mm/s², deg/s²), else the defaults
    // below; `velocityFromFile` and `accelerationFromFile` say which.
    double maxVelocity = 0;
    double maxAcceleration = 0;
    bool velocityFromFile = false;
    bool accelerationFromFile = false;
};

// Defaults for what a machine file does not say. A linear axis without "maxVelocity" moves at
// most at the machine's rapid rate (feed.rapid, else feed.maxCutting, else the time estimate's
// toolpath::kDefaultRapidMmPerMin): nothing on the machine moves faster than its rapid. A rotary
// axis without one turns at its maxRpm, else at kDefaultRotaryDegPerMin (10 rpm, slower than
// most NC rotary tables, 11-50 rpm). Accelerations default low on purpose: 1 m/s² (machining
// centres reach 2-10 m/s²) and 360 deg/s²; a low figure makes a cycle time too long, never too
// short. A tool change without "toolChanger.changeSeconds" takes 5 s (chip to chip of common
// changers is 2-8 s; a manual change: 60 s), a spindle start or stop without "spindle.rampSeconds"
// takes 2 s from standstill to maxRpm.
inline constexpr double kDefaultRotaryDegPerMin = 3600;
inline constexpr double kDefaultLinearAccelerationMmPerS2 = 1000;
inline constexpr double kDefaultRotaryAccelerationDegPerS2 = 360;
inline constexpr double kDefaultToolChangeSeconds = 5;
inline constexpr double kDefaultManualToolChangeSeconds = 60;
inline constexpr double kDefaultSpindleRampSeconds = 2;

struct Machine {
    std::string id;
    std::string name;
    std::string control;  // "sinumerik-828d", "heidenhain-itnc530", "linuxcnc", ...
    std::vector<Axis> axes;
    double spindleMinRpm = 0;
    double spindleMaxRpm = 0;           // 0: not limited
    int toolStations = 0;               // 0: not limited
    bool manualToolChange = false;      // the operator changes tools: no changer, no M6
    double maxToolDiameterMm = 0;       // 0: not limited
    double maxToolLengthMm = 0;         // 0: not limited
    double minCuttingFeedMmPerMin = 0;  // 0: not limited
    double maxCuttingFeedMmPerMin = 0;  // 0: not limited
    double rapidMmPerMin = 0;           // 0: unknown
    double toolChangeSeconds = 0;       // always set after loading (the file's, else a default above)
    double spindleRampSeconds = 0;      // standstill to spindleMaxRpm (or to any speed if 0)
    std::vector<std::string> coolants;  // "flood", "mist", "throughTool": what the machine has
    KinematicChain kinematics;          // three-axis unless the file gives a chain (version 2)
    std::string filePath;

    const Axis* axis(const std::string& axisName) const;
    bool hasCoolant(const std::string& mode) const;
};

// Version 1 grows by optional fields (feed.minCutting, toolChanger.manual, an axis' endless and
// maxRpm): every file written before them still loads and means what it meant. A version 1
// reader that predates them rejects an endless axis (it has no min) and ignores the rest.
// Axis maxVelocity/maxAcceleration, toolChanger.changeSeconds and spindle.rampSeconds are
// optional in both versions, with the defaults above.
// Version 2 adds the kinematic chain ("kinematics"); a version 1 file is a three-axis chain
// whatever rotary axes it lists, as it always was.
inline constexpr int kMachineFormatVersion = 2;

// The rapid rate a machining time estimate assumes for `machine` (toolpath::StatsOptions): its
// own when the file gives one, else toolpath::kDefaultRapidMmPerMin. nullptr: no machine.
double estimateRapidMmPerMin(const Machine* machine);

// The machine a simulation plans on when none is chosen: X, Y and Z without travel limits and
// every motion limit at its default above (the time it gives is said to be on default limits).
Machine defaultLimitsMachine();

base::Result<Machine> parseMachine(const std::string& json, const std::string& pathForMessages);
base::Result<Machine> loadMachine(const std::string& path);

// $CAMWB_MACHINE_PATH entries, ~/.local/share/camwb/machines, the installed share/camwb/machines
// and the source tree's resources/machines, in that order; "<dir>/<id>.json", first match wins.
// An `id` ending in ".json" is the path of a machine file, read as it is.
std::vector<std::string> defaultMachineDirs();
// Every "<id>.json" in those folders, sorted by id, the first folder's file for an id.
std::vector<base::DataFile> listMachineFiles();
base::Result<Machine> findMachine(const std::string& id, const std::vector<std::string>& dirs);

}  // namespace camwb::kinematics
