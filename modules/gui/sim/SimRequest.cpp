#include "gui/sim/SimRequest.h"

#include "gui/inspector/NcInspector.h"
#include "gui/shell/Workbench.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace camwb::gui {

namespace {

class Tr {
    Q_DECLARE_TR_FUNCTIONS(SimulationRequest)
};

}  // namespace

std::optional<SimRunRequest> simulationRequest(const NcInspector& inspector, const Workbench& workbench,
                                               bool editorShowsPostedProgram, double resolutionMm, QString* why)
{
    const auto trace = inspector.trace();
    if (inspector.isTracing() || !trace) {
        *why = Tr::tr("Nothing to simulate yet: the NC program is being traced (or none is open).");
        return std::nullopt;
    }
    if (trace->program.empty()) {
        *why = Tr::tr("Nothing to simulate: the NC program makes no records.");
        return std::nullopt;
    }
    SimRunRequest request;
    request.trace = trace;
    request.resolutionMm = resolutionMm;
    request.programName = QFileInfo(inspector.filePath()).fileName().toStdString();
    request.machine = inspector.sharedMachine();
    const document::Stock& stock = workbench.job().stock;
    const bool stockGiven = stock.max.x > stock.min.x && stock.max.y > stock.min.y && stock.max.z > stock.min.z;
    if (editorShowsPostedProgram && stockGiven) {
        base::Box3 box;
        box.add(stock.min);
        box.add(stock.max);
        request.stockBox = box;
        if (!workbench.model().empty())
            request.model = workbench.model();
        const toolpath::Toolpath& cl = workbench.toolpath();
        for (std::size_t i = 0; i < cl.size(); ++i)
            if (const auto* change = std::get_if<toolpath::ToolChange>(&cl.record(i)))
                request.tools[change->tool.number] = change->tool;
    }
    return request;
}

}  // namespace camwb::gui
