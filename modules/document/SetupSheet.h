// The facts of a setup sheet: what the operator at the machine needs to set up and run a job
// (stock, work offset, machine and post, the tools with the stick-out each needs, per operation
// its tool, feeds, depths and time, and what the simulator found). Plain data gathered from the
// job and its computed program; the sheet module turns it into HTML and PDF.
#pragma once

#include "base/DataDirs.h"
#include "base/Result.h"
#include "base/Vec.h"
#include "document/Job.h"
#include "kinematics/Machine.h"
#include "toolpath/ClRecords.h"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace camwb::occ {
class Model;
}
namespace camwb::sim {
struct MoveList;
}
namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::document {

struct SheetTool {
    ops::ToolController controller;
    std::vector<std::string> operations;  // the operations that use it, in job order
    // How far the tool must stick out of its holder: its deepest tip below the highest point the
    // holder must clear, plus the margin; none when the program never moves it.
    std::optional<double> stickOutMm;
    // The tool's own length (toolpath::Tool::lengthMm, 0 = not given) is shorter than stickOutMm.
    bool tooShort = false;
};

struct SheetOperation {
    std::string name;
    std::string kind;  // kindLabel(): "contour", "pocket", ...
    int toolNumber = 0;
    double spindleRpm = 0;
    double cuttingFeed = 0, plungeFeed = 0, rampFeed = 0;  // mm/min
    // A turning operation cuts at constant surface speed and a feed per revolution (its own
    // values, not the tool controller's): "G96 300 m/min, LIMS 3000" and "0.2 mm/rev".
    std::string turningSpeed, turningFeed;
    std::optional<ops::Heights> heights;  // none when its geometry did not resolve
    double stepDownMm = 0;                // 0: one level (or not a layered operation)
    double seconds = 0;                   // planned on the machine, tool change included
};

// sim::simulate's findings, when the sheet ran it.
struct SheetVerification {
    bool run = false;
    int gouges = 0, holderCollisions = 0, rapidsInStock = 0, machineLimits = 0, otherErrors = 0, warnings = 0;
    double maxGougeMm = 0;
    double resolutionMm = 0;
    bool turning = false;  // a lathe job's: its grooves' revolved stock and offset contour, no height field
    std::vector<std::string> firstFindings;  // "operation: message", the first few errors
};

struct SetupSheet {
    std::string jobName;
    std::string created, user, version;  // UTC date (SOURCE_DATE_EPOCH pins it), CAMWB_USER, CAMWB_VERSION
    std::string jobFile;                 // file name only
    std::string modelFile;               // file name only
    std::optional<base::Box3> stock;
    base::Box3 modelBounds;
    int workOffset = 1;
    std::string machineId, machineName;  // empty: no machine (default limits)
    std::string postId, postDescription;
    std::vector<std::pair<std::string, std::string>> postProperties;  // non-default: name, value
    std::string ncFile;                                               // "<job file stem>.<post extension>"
    std::vector<SheetTool> tools;                                     // by number
    std::vector<SheetOperation> operations;                           // job order
    double cycleSeconds = 0;   // planned with the machine's accelerations (sim::planMotion)
    double simpleSeconds = 0;  // distance/feed estimate (toolpath::programStats)
    double rapidLengthMm = 0, feedLengthMm = 0;
    double stickOutMarginMm = 0;
    SheetVerification verification;
};

struct SheetOptions {
    double stickOutMarginMm = 2;
    bool simulate = true;
    std::optional<kinematics::Machine> machine;  // overrides the job's
    std::vector<base::DataDir> postDirs;         // where the job's post is found
    // Set from another thread to stop the simulation: collectSetupSheet then answers an error
    // (kCollectCancelled). Progress is the simulation's, 0..1.
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(double fraction)> progress;
};

// The message of the error collectSetupSheet answers when SheetOptions::cancel stopped it.
inline constexpr const char* kCollectCancelled = "setup sheet cancelled";

// Everything the sheet shows; errors when the post or machine cannot be loaded.
base::Result<SetupSheet> collectSetupSheet(const Job& job, const std::string& jobPath, const occ::Model& model,
                                           const toolpath::Toolpath& program, const SheetOptions& options);

// The stick-out `tool` needs: over its moves, the largest distance along the tool axis from the
// tip down from the highest corner of `clear` (the stock, or the model when it stands higher),
// plus `marginMm`. None when the tool makes no move.
std::optional<double> requiredStickOut(const sim::MoveList& moves, int tool, const base::Box3& clear, double marginMm);

}  // namespace camwb::document
