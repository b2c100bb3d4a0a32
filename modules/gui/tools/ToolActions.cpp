#include "gui/tools/ToolActions.h"

#include "base/DataDirs.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/Workbench.h"
#include "gui/tools/ToolLibraryDialog.h"

#include <QAction>
#include <QCoreApplication>
#include <QPointer>
#include <QStandardPaths>
#include <QWidget>

namespace camwb::gui {

namespace {

// Translation context of the strings below (lupdate reads Q_DECLARE_TR_FUNCTIONS).
class Tr {
    Q_DECLARE_TR_FUNCTIONS(ToolActions)
};

}  // namespace

QString userToolLibraryPath()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/tools.camwb-tools.json");
}

QString defaultToolLibraryPath()
{
    auto path = base::findDataFile("tool library", "default", ".camwb-tools.json",
                                   base::dataDirPaths("CAMWB_TOOLS_PATH", "tools", "resources/tools"));
    return path ? QString::fromStdString(path.value()) : QString();
}

void registerToolActions(ActionRegistry& registry, Workbench& workbench, std::function<Prompter&()> prompter,
                         QWidget* parent)
{
    const QString menu = Tr::tr("&Tools");
    // One dialog at a time; it reads the library file again each time it is opened.
    auto dialog = std::make_shared<QPointer<ToolLibraryDialog>>();
    QAction* library = registry.add({"Cam.Tools.Library", Tr::tr("Tool &Library…"), menu, QKeySequence(), false, false,
                                     Tr::tr("The tool library: add its tools to the job, import, export")});
    QObject::connect(library, &QAction::triggered, parent, [&workbench, prompter, parent, dialog] {
        if (*dialog) {
            (*dialog)->raise();
            (*dialog)->activateWindow();
            return;
        }
        *dialog = new ToolLibraryDialog(workbench, prompter(), userToolLibraryPath(), defaultToolLibraryPath(), parent);
        (*dialog)->setAttribute(Qt::WA_DeleteOnClose);
        (*dialog)->show();
    });
    QAction* compute =
        registry.add({"Cam.Tools.ComputeFeeds", Tr::tr("Compute &Feeds and Speeds"), menu, QKeySequence(), false, false,
                      Tr::tr("Set the job's tools' spindle speed and feeds from their cutting data and the "
                             "job's stock material")});
    QObject::connect(compute, &QAction::triggered, parent, [&workbench] { workbench.computeFeeds(); });
}

}  // namespace camwb::gui
