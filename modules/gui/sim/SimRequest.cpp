#include "gui/sim/SimRequest.h"

#include "document/StockBlank.h"
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
    const std::optional<base::Box3> stockBox = workbench.job().stock.box();
    if (editorShowsPostedProgram && stockBox) {
        // The stock as the solid it is: a box, a cylinder, or the blank's mesh.
        const std::shared_ptr<const sim::TriangleMesh> blank = workbench.stockBlank();
        if (workbench.job().stock.shape == document::Stock::Shape::Blank && !blank) {
            *why = Tr::tr("The blank stock's file is not read (the report says why): nothing to cut yet.");
            return std::nullopt;
        }
        sim::StockSpec stock =
            document::jobStockSpec(workbench.job(), workbench.model(), blank ? *blank : sim::TriangleMesh{}, 0);
        request.stockBox = stock.box;
        request.stockSolid = std::move(stock.blank);
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
