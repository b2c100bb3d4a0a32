#include "gui/tasks/JobSetupActions.h"

#include "document/JobPipeline.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/Workbench.h"
#include "sim/TurningProfile.h"

#include <QAction>
#include <QCoreApplication>

#include <memory>
#include <utility>

namespace camwb::gui {

namespace {

// Translation context of the strings below (lupdate reads Q_DECLARE_TR_FUNCTIONS).
class Tr {
    Q_DECLARE_TR_FUNCTIONS(JobSetupActions)
};

}  // namespace

void registerJobSetupActions(ActionRegistry& registry, std::function<void()> openPanel)
{
    QAction* action = registry.add({"Cam.Job.Setup", Tr::tr("Job &Setup…"), Tr::tr("&Job"), QKeySequence(), false,
                                    false, Tr::tr("Model, stock, work coordinates, machine, post and output")});
    QObject::connect(action, &QAction::triggered, action, [openPanel] { openPanel(); });
}

std::optional<LatheSection> latheSectionOf(const document::Job& job)
{
    if (document::jobNeedsModel(job))
        return std::nullopt;  // a milling job (or one with no operations yet)
    LatheSection section;
    for (const document::Operation& op : job.operations) {
        const auto* groove = std::get_if<ops::GrooveParams>(&op.params);
        if (groove == nullptr)
            continue;  // a turning operation of another kind would add its own contour here
        const sim::GrooveParameters& g = groove->groove;
        if (section.contours.empty())
            section.stock = sim::grooveStock(g);
        const sim::GrooveGeometry geo = sim::grooveGeometry(g);
        section.contours.push_back({geo.c1, geo.bottomLeft, geo.bottomRight, geo.p});
        section.offsetContours.push_back({geo.r, geo.s, geo.t, geo.u});
    }
    if (section.contours.empty())
        return std::nullopt;
    return section;
}

void showJobSetupInView(Workbench& workbench, View3D& view)
{
    auto turning = std::make_shared<bool>(false);
    auto show = [&workbench, &view, turning] {
        const document::Job& job = workbench.job();
        const std::optional<LatheSection> section = latheSectionOf(job);
        const document::Stock& stock = job.stock;
        const bool blank = stock.shape == document::Stock::Shape::Blank;
        view.setJobSetup(section ? std::nullopt : stock.box(), stock.shape == document::Stock::Shape::Cylinder,
                         blank ? workbench.stockBlank() : nullptr);
        view.setLatheSection(section);
        // Turned to the lathe's view when the job becomes a turning job, and back when it stops.
        if (std::exchange(*turning, section.has_value()) != section.has_value())
            view.setViewPreset(section ? View3D::Preset::LatheXZ : View3D::Preset::Isometric);
    };
    QObject::connect(&workbench, &Workbench::jobChanged, &view, show);
    QObject::connect(&workbench, &Workbench::stockBlankChanged, &view, show);
    show();
}

}  // namespace camwb::gui
