#include "gui/sim/SimRun.h"

#include "kinematics/Machine.h"

namespace camwb::gui {

namespace {

bool cancelled(const SimRunRequest& request) { return request.cancel && request.cancel->load(); }

void progress(const SimRunRequest& request, int percent)
{
    if (request.progress)
        request.progress(percent);
}

}  // namespace

std::shared_ptr<SimRun> buildSimRun(const SimRunRequest& request)
{
    auto run = std::make_shared<SimRun>();
    run->trace = request.trace;
    run->programName = request.programName;
    if (!request.trace)
        return run;
    progress(request, 5);
    sim::MoveOptions options;
    run->moves = sim::buildMoves(request.trace->program, options, request.trace->recordsInError);
    if (cancelled(request))
        return nullptr;
    progress(request, 30);

    run->timeline = Timeline(&run->moves, {}, {});
    const auto trace = request.trace;
    run->timeline.setLineOfRecord([trace](std::size_t record) { return trace->lineOfRecord(record); });
    progress(request, 100);
    return run;
}

}  // namespace camwb::gui
