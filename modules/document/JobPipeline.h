// From a job to NC: load the model, compute every operation into one program toolpath
// (tool changes inserted where the tool changes), and post it. Used by camwb-cli and the GUI
// alike, so both produce the same NC for the same job.
#pragma once

#include "base/DataDirs.h"
#include "base/Result.h"
#include "document/Job.h"
#include "occ/Model.h"
#include "ops/OpCommon.h"
#include "post/PostProcessor.h"
#include "toolpath/Toolpath.h"

#include <string>
#include <vector>

namespace camwb::document {

// False for a lathe job: one whose operations are all turning operations (parametric grooves).
bool jobNeedsModel(const Job& job);
// The job's model in work coordinates: moved by -job.origin (face and edge indices unchanged).
// A job without a model path gets an empty model when it needs none, else an error.
base::Result<occ::Model> loadJobModel(const Job& job, const occ::ProgressFn& progress = {});
// Re-resolves a "from model" stock from `model` (as loadJobModel gives it) after a (re)load.
void resolveJobStock(Job& job, const occ::Model& model);

// The whole program: work offset, then per operation its section with the tool change and
// spindle start inserted after SectionBegin when the tool differs from the previous one.
// Disabled operations are skipped (no section, no tool change). The first failing operation's error is returned.
struct OperationFailure {
    int operation = 0;  // index in the job
    std::string message;
};
struct ProgramReport {
    std::vector<base::Diagnostic> warnings;  // each names its operation: "pocket \"P\": ..."
    std::vector<ops::MotionCounts> counts;   // per operation, in job order (zero: disabled)
    // Set by the caller: compute the operations after a failing one too, so that `failures`
    // names every operation that cannot be made (the GUI marks each one), not only the first.
    bool allFailures = false;
    std::vector<OperationFailure> failures;
};
base::Result<toolpath::Toolpath> computeProgram(const Job& job, const occ::Model& model,
                                                const ops::Progress& progress = {}, ProgramReport* report = nullptr);

base::Result<post::PostProcessor> loadJobPost(const Job& job, const std::vector<base::DataDir>& postDirs);

// The job's name and stock for the post's header (no stock when the box is empty).
post::JobFacts jobFacts(const Job& job);

// How the job asks to be posted: its post property values and its machine (or the post's
// default machine, found in machineDirs), with the given context.
base::Result<post::RunOptions> jobRunOptions(const Job& job, const post::PostProcessor& post, post::PostContext context,
                                             const std::vector<std::string>& machineDirs);

}  // namespace camwb::document
