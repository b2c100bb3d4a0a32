#include "document/JobPipeline.h"

#include "post/PostRegistry.h"

namespace camwb::document {

base::Result<occ::Model> loadJobModel(const Job& job, const occ::ProgressFn& progress)
{
    if (job.modelPath.empty())
        return base::makeError("the job has no model");
    return occ::Model::load(job.modelPath, progress);
}

base::Result<toolpath::Toolpath> computeProgram(const Job& job, const occ::Model& model)
{
    toolpath::Toolpath program;
    program.add(toolpath::WorkOffset{job.workOffset});
    int currentTool = -1;

    for (std::size_t i = 0; i < job.operations.size(); ++i) {
        const Operation& op = job.operations[i];
        const int index = static_cast<int>(i);
        const std::string label = "operation \"" + op.profile.name + "\": ";
        const ops::ToolController* tc = job.tool(op.toolNumber);
        if (!tc)
            return base::makeError(label + "no tool number " + std::to_string(op.toolNumber) + " in the job");

        auto boundary = model.planarFaceOuterProfile(op.profile.faceIndex);
        if (!boundary)
            return base::makeError(label + boundary.error().message);
        auto section = ops::computeOuterProfile(boundary.value(), op.profile, *tc, index);
        if (!section)
            return base::makeError(label + section.error().message);

        for (std::size_t r = 0; r < section->size(); ++r) {
            program.add(section->record(r), section->source(r));
            const bool isSectionStart = std::holds_alternative<toolpath::SectionBegin>(section->record(r));
            if (isSectionStart && tc->tool.number != currentTool) {
                program.add(toolpath::ToolChange{tc->tool}, {index, -1});
                program.add(toolpath::Spindle{tc->spindleRpm, true}, {index, -1});
                currentTool = tc->tool.number;
            }
        }
    }
    return program;
}

base::Result<post::PostProcessor> loadJobPost(const Job& job, const std::vector<base::DataDir>& postDirs)
{
    auto path = post::findPost(job.postId, postDirs);
    if (!path)
        return path.error();
    return post::PostProcessor::load(path.value());
}

base::Result<post::RunOptions> jobRunOptions(const Job& job, const post::PostProcessor& post, post::PostContext context,
                                             const std::vector<std::string>& machineDirs)
{
    post::RunOptions options;
    options.context = std::move(context);
    options.properties = job.postProperties;
    auto machine = post::machineForPost(post.info(), job.machineId, machineDirs);
    if (!machine)
        return machine.error();
    options.machine = std::move(machine).value();
    return options;
}

}  // namespace camwb::document
