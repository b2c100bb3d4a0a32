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
};

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
    std::vector<std::string> coolants;  // "flood", "mist", "throughTool": what the machine has
    KinematicChain kinematics;          // three-axis unless the file gives a chain (version 2)
    std::string filePath;

    const Axis* axis(const std::string& axisName) const;
    bool hasCoolant(const std::string& mode) const;
};

// Version 1 grows by optional fields (feed.minCutting, toolChanger.manual, an axis' endless and
// maxRpm): every file written before them still loads and means what it meant. A version 1
// reader that predates them rejects an endless axis (it has no min) and ignores the rest.
// Version 2 adds the kinematic chain ("kinematics"); a version 1 file is a three-axis chain
// whatever rotary axes it lists, as it always was.
inline constexpr int kMachineFormatVersion = 2;

// The rapid rate a machining time estimate assumes for `machine` (toolpath::StatsOptions): its
// own when the file gives one, else toolpath::kDefaultRapidMmPerMin. nullptr: no machine.
double estimateRapidMmPerMin(const Machine* machine);

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
