#include "document/JobPipeline.h"

#include "document/OperationGeometry.h"
#include "post/PostRegistry.h"

#include <algorithm>
#include <optional>

namespace camwb::document {

bool jobNeedsModel(const Job& job)
{
    return job.operations.empty() || std::any_of(job.operations.begin(), job.operations.end(),
                                                 [](const Operation& op) { return !isTurningKind(op.kind()); });
}

base::Result<occ::Model> loadJobModel(const Job& job, const occ::ProgressFn& progress)
{
    if (job.modelPath.empty()) {
        if (!jobNeedsModel(job))
            return occ::Model();  // a lathe job: its grooves are parametric
        return base::makeError(job.operations.empty() ? "the job has no model"
                                                      : "the job has no model (its milling operations need one)");
    }
    auto model = occ::Model::load(job.modelPath, progress);
    if (!model || job.origin == base::Vec3{})
        return model;
    if (!model->hasBRep())
        return base::makeError("a mesh (STL) model cannot be moved to a work origin; use the model's zero",
                               job.modelPath);
    // Translated, not turned: faces and edges keep their indices (inFrame moves the same shape).
    return model->inFrame(job.origin, {1, 0, 0}, {0, 0, 1});
}

void resolveJobStock(Job& job, const occ::Model& model)
{
    if (!model.empty())
        job.stock.resolve(model.boundsMin(), model.boundsMax());
}

base::Result<toolpath::Toolpath> computeProgram(const Job& job, const occ::Model& model, const ops::Progress& progress,
                                                ProgramReport* report)
{
    toolpath::Toolpath program;
    program.add(toolpath::WorkOffset{job.workOffset});
    int currentTool = -1;
    const double count = static_cast<double>(std::max<std::size_t>(job.operations.size(), 1));
    std::optional<base::Error> firstError;

    for (std::size_t i = 0; i < job.operations.size(); ++i) {
        const int index = static_cast<int>(i);
        if (!job.operations[i].enabled) {
            // Skipped, not removed: the others keep their job indices (messages, sources, the
            // NC line -> operation map); the next tool change compares with the last posted tool.
            if (report)
                report->counts.emplace_back();
            continue;
        }
        // Each operation reports its own 0..1 as a slice of the whole.
        ops::Progress slice{nullptr, progress.cancel};
        if (progress.report)
            slice.report = [&, i](double f) { progress.report((static_cast<double>(i) + f) / count); };
        auto section = computeOperation(job, index, model, slice);
        if (!section) {
            if (report)
                report->failures.push_back({index, section.error().toString()});
            if (!report || !report->allFailures || progress.cancelled())
                return section.error();
            if (!firstError)
                firstError = section.error();
            report->counts.emplace_back();  // keeps `counts` in job order
            continue;
        }
        const Operation& op = job.operations[i];
        if (report) {
            // The operations name themselves in their warnings ("pocket \"P\": ...").
            report->warnings.insert(report->warnings.end(), section->warnings.begin(), section->warnings.end());
            report->counts.push_back(section->counts);
        }
        const ops::ToolController& tc = *job.tool(op.toolNumber);  // computeOperation checked it
        const toolpath::Toolpath& records = section->toolpath;
        for (std::size_t r = 0; r < records.size(); ++r) {
            toolpath::Record record = records.record(r);
            if (auto* begin = std::get_if<toolpath::SectionBegin>(&record))
                begin->postProperties.assign(op.postProperties.begin(), op.postProperties.end());
            program.add(record, records.source(r));
            const bool isSectionStart = std::holds_alternative<toolpath::SectionBegin>(records.record(r));
            if (isSectionStart && tc.tool.number != currentTool) {
                program.add(toolpath::ToolChange{tc.tool}, {index, -1});
                // A turning operation starts its own spindle (G96 constant surface speed and
                // its limit, with the feed per revolution): the controller's rpm is a mill's.
                if (!isTurningKind(op.kind()))
                    program.add(toolpath::Spindle{tc.spindleRpm, true}, {index, -1});
                currentTool = tc.tool.number;
            }
        }
    }
    if (firstError)
        return *firstError;
    return program;
}

base::Result<post::PostProcessor> loadJobPost(const Job& job, const std::vector<base::DataDir>& postDirs)
{
    auto path = post::findPost(job.postId, postDirs);
    if (!path)
        return path.error();
    return post::PostProcessor::load(path.value());
}

post::JobFacts jobFacts(const Job& job)
{
    post::JobFacts facts;
    facts.name = job.name;
    facts.stock = job.stock.box();
    return facts;
}

base::Result<post::RunOptions> jobRunOptions(const Job& job, const post::PostProcessor& post, post::PostContext context,
                                             const std::vector<std::string>& machineDirs)
{
    post::RunOptions options;
    options.context = std::move(context);
    options.properties = job.postProperties;
    options.job = jobFacts(job);
    auto machine = post::machineForPost(post.info(), job.machineId, machineDirs);
    if (!machine)
        return machine.error();
    options.machine = std::move(machine).value();
    return options;
}

}  // namespace camwb::document
