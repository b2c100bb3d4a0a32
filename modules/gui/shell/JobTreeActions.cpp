// The job tree's actions and context menus (JobTree.h): the operation edits it registers in the
// ActionRegistry, and the menus that offer them and the actions other parts register.
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/JobTree.h"
#include "gui/shell/Workbench.h"

#include <QAction>
#include <QContextMenuEvent>
#include <QMenu>

namespace camwb::gui {

QAction* JobTree::registered(const char* id) const
{
    return m_actions ? m_actions->action(QLatin1String(id)) : nullptr;
}

void JobTree::registerActions(ActionRegistry& registry, const QString& menu)
{
    m_actions = &registry;
    // Keys that mean something else elsewhere (Space presses buttons, Ctrl+Up scrolls) act only
    // while the tree has focus; from the menu the actions work on the tree's selection.
    auto add = [&](ActionSpec spec, auto slot) {
        QAction* action = registry.add(spec);
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        addAction(action);
        connect(action, &QAction::triggered, this, slot);
        return action;
    };
    auto onSelected = [this](auto edit) {
        return [this, edit] {
            if (const int index = selectedOperation(); index >= 0)
                edit(index);
        };
    };
    auto move = [this](int from, int to) {
        m_selectAfterRebuild = to;
        m_workbench.moveOperation(from, to);
    };
    add({"Cam.Op.ToggleEnabled", tr("Disa&ble Operation"), menu, QKeySequence(Qt::Key_Space), false, true},
        onSelected([this](int index) {
            m_workbench.setOperationEnabled(index, !m_workbench.job().operations[index].enabled);
        }));
    add({"Cam.Op.Duplicate", tr("D&uplicate Operation"), menu}, onSelected([this](int index) {
            m_selectAfterRebuild = index + 1;
            m_workbench.duplicateOperation(index);
        }));
    add({"Cam.Op.Rename", tr("&Rename Operation"), menu}, [this] { renameSelected(); });
    add({"Cam.Op.MoveUp", tr("Move Operation &Up"), menu, QKeySequence(Qt::CTRL | Qt::Key_Up)},
        onSelected([move](int index) { move(index, index - 1); }));
    add({"Cam.Op.MoveDown", tr("Move Operation Do&wn"), menu, QKeySequence(Qt::CTRL | Qt::Key_Down)},
        onSelected([move](int index) { move(index, index + 1); }));

    // The setup's panels belong to other parts: found by id when asked, nothing when absent.
    connect(this, &JobTree::editJobSetupRequested, this, [this] {
        if (QAction* setup = registered("Cam.Job.Setup"))
            setup->trigger();
    });
    connect(this, &JobTree::editPostRequested, this, [this] {
        if (QAction* post = registered("Cam.Job.PostSettings"))
            post->trigger();
    });
    connect(this, &QTreeWidget::currentItemChanged, this, &JobTree::updateActions);
    connect(&m_workbench, &Workbench::jobChanged, this, &JobTree::updateActions);
    updateActions();
}

// What the selected operation allows: the toggle says what it will do, moves stop at the ends.
void JobTree::updateActions()
{
    const int index = selectedOperation();
    const int count = static_cast<int>(m_workbench.job().operations.size());
    const bool enabled = index >= 0 && index < count && m_workbench.job().operations[index].enabled;
    if (QAction* toggle = registered("Cam.Op.ToggleEnabled"))
        toggle->setText(index >= 0 && !enabled ? tr("&Enable Operation") : tr("Disa&ble Operation"));
    if (QAction* up = registered("Cam.Op.MoveUp"))
        up->setEnabled(index > 0 && index < count);
    if (QAction* down = registered("Cam.Op.MoveDown"))
        down->setEnabled(index >= 0 && index + 1 < count);
}

void JobTree::renameSelected()
{
    if (QTreeWidgetItem* item = operationItem(selectedOperation())) {
        setCurrentItem(item);
        editItem(item, 0);
    }
}

QMenu* JobTree::contextMenuFor(QTreeWidgetItem* item)
{
    auto* menu = new QMenu(this);
    auto offer = [&](std::initializer_list<const char*> ids) {
        for (const char* id : ids) {
            if (id == nullptr)
                menu->addSeparator();
            else if (QAction* action = registered(id))
                menu->addAction(action);
        }
    };
    if (item != nullptr && kindOf(item) == ItemKind::Other)
        item = item->parent();  // a detail row offers what its row offers
    setCurrentItem(item);
    updateActions();
    switch (kindOf(item)) {
    case ItemKind::Operation:
        offer({"Cam.Op.Edit", "Cam.Op.ToggleEnabled", "Cam.Op.Duplicate", "Cam.Op.Rename", nullptr, "Cam.Op.MoveUp",
               "Cam.Op.MoveDown", nullptr, "Cam.Op.Delete"});
        break;
    case ItemKind::Operations:
        offer({"Cam.Op.NewContour", "Cam.Op.NewPocket", "Cam.Op.NewHelix", "Cam.Op.NewDrill", "Cam.Op.NewSwarf",
               "Cam.Op.NewPocket3d", "Cam.Op.NewWaterline", "Cam.Op.NewParallel", nullptr, "Cam.Op.NewGroove"});
        break;
    case ItemKind::Tools:
    case ItemKind::Tool:
        offer({"Cam.Tools.Library"});
        break;
    case ItemKind::Job:
    case ItemKind::Model:
    case ItemKind::Stock:
    case ItemKind::Wcs:
    case ItemKind::Machine:
        offer({"Cam.Job.Setup"});
        if (kindOf(item) == ItemKind::Model)
            offer({"Cam.File.ImportModel"});
        break;
    case ItemKind::Post:
        offer({"Cam.Job.PostSettings"});
        break;
    default:
        break;
    }
    return menu;
}

void JobTree::contextMenuEvent(QContextMenuEvent* event)
{
    // From the keyboard (the menu key) the menu is the current row's.
    // The view gets the mouse's event through its viewport: the position is the viewport's.
    QTreeWidgetItem* item = event->reason() == QContextMenuEvent::Mouse ? itemAt(event->pos()) : currentItem();
    QMenu* menu = contextMenuFor(item);
    if (!menu->isEmpty())
        menu->exec(event->globalPos());
    menu->deleteLater();
}

}  // namespace camwb::gui
