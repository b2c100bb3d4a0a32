#include "gui/shell/KeyboardFocus.h"

#include "gui/actions/ActionRegistry.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QStatusBar>

namespace camwb::gui {

namespace {

bool takesTab(const QWidget* widget, const QWidget* root)
{
    return (widget->focusPolicy() & Qt::TabFocus) != 0 && widget->isEnabled() && widget->isVisibleTo(root);
}

// Shows and raises the dock `name` (tabbed docks hide each other) and focuses what it holds.
void focusDock(QMainWindow& window, const char* name, const QString& closedMessage)
{
    auto* dock = window.findChild<QDockWidget*>(QLatin1String(name));
    if (dock == nullptr)
        return;
    // The task dock is open only with a panel: an empty one is not shown for the key.
    if (dock->isHidden() && !closedMessage.isEmpty()) {
        window.statusBar()->showMessage(closedMessage, 5000);
        return;
    }
    dock->show();
    dock->raise();
    if (QWidget* target = firstFocusable(dock->widget()))
        target->setFocus(Qt::ShortcutFocusReason);
}

}  // namespace

QWidget* firstFocusable(QWidget* root)
{
    if (root == nullptr)
        return nullptr;
    if (takesTab(root, root))
        return root;
    for (QWidget* child : root->findChildren<QWidget*>())  // depth first, in creation order
        if (takesTab(child, root))
            return child;
    return nullptr;
}

void registerFocusActions(ActionRegistry& actions, QMainWindow& window, const QString& menu)
{
    auto add = [&actions, &menu](const char* id, const QString& text, Qt::Key key, bool separator, auto slot) {
        QAction* action = actions.add({QLatin1String(id), text, menu, QKeySequence(Qt::ALT | key), false, separator});
        QObject::connect(action, &QAction::triggered, action, slot);
    };
    QMainWindow* w = &window;
    add("Cam.View.GoToJobTree", QObject::tr("Go to &Job Tree"), Qt::Key_1, true, [w] { focusDock(*w, "jobDock", {}); });
    add("Cam.View.GoToTask", QObject::tr("Go to Tas&k Panel"), Qt::Key_2, false,
        [w] { focusDock(*w, "taskDock", QObject::tr("No task panel is open.")); });
    add("Cam.View.GoToNc", QObject::tr("Go to &NC Program"), Qt::Key_3, false, [w] { focusDock(*w, "ncDock", {}); });
    add("Cam.View.GoToReport", QObject::tr("Go to Re&port"), Qt::Key_4, false,
        [w] { focusDock(*w, "reportDock", {}); });
    add("Cam.View.GoTo3D", QObject::tr("Go to 3D &View"), Qt::Key_0, false, [w] {
        if (QWidget* target = firstFocusable(w->centralWidget()))
            target->setFocus(Qt::ShortcutFocusReason);
    });
}

}  // namespace camwb::gui
