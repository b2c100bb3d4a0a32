#include "gui/tasks/JobSetupActions.h"

#include "gui/actions/ActionRegistry.h"
#include "gui/shell/Workbench.h"
#include "gui/view3d/View3D.h"

#include <QAction>
#include <QCoreApplication>

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

void showJobSetupInView(Workbench& workbench, View3D& view)
{
    auto show = [&workbench, &view] {
        const document::Stock& stock = workbench.job().stock;
        view.setJobSetup(stock.box(), stock.shape == document::Stock::Shape::Cylinder);
    };
    QObject::connect(&workbench, &Workbench::jobChanged, &view, show);
    show();
}

}  // namespace camwb::gui
