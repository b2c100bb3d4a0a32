// The job tree dock's widget: model, stock, WCS, machine, post (and its non-default properties),
// tools and operations (tool, planned time, enabled check box) of the current job, rebuilt from
// the Workbench on every change with the selection kept. Problems are shown in red with the
// reason. Context menus, drag to reorder, and keys (Enter edits, Space toggles, Ctrl+Up/Down
// moves) act through the Workbench's undoable edits and the ActionRegistry's actions.
#pragma once

#include <QTreeWidget>

class QMenu;

namespace camwb::gui {

class ActionRegistry;
class Workbench;

class JobTree : public QTreeWidget {
    Q_OBJECT
public:
    // What a row stands for (its context menu and what Enter opens).
    enum class ItemKind { Other, Job, Model, Stock, Wcs, Machine, Post, Tools, Tool, Operations, Operation };

    explicit JobTree(Workbench& workbench, QWidget* parent = nullptr);

    // Registers the operation actions the tree offers (Cam.Op.ToggleEnabled, MoveUp, MoveDown,
    // Duplicate, Rename; their keys act while the tree has focus) and routes the setup requests
    // to Cam.Job.Setup / Cam.Job.PostSettings when those are registered. `menu`: the
    // operations' menu title. Call once.
    void registerActions(ActionRegistry& registry, const QString& menu);

    // Fills the tree from the job again (it does on every job change; also when the display
    // unit changed).
    void rebuild();

    // Index of the selected operation, -1 when none is selected.
    int selectedOperation() const;
    void selectOperation(int index);
    static ItemKind kindOf(const QTreeWidgetItem* item);
    // The first row of `kind` (nullptr when none).
    QTreeWidgetItem* itemOf(ItemKind kind) const;
    QTreeWidgetItem* operationItem(int index) const;

    // The context menu of a row (the caller owns it); empty when the row offers nothing.
    QMenu* contextMenuFor(QTreeWidgetItem* item);
    // The drop of the selected operation at `pos` (viewport) as a drag ends it: moved before or
    // after the row under it (one undoable step); false when it would not move.
    bool dropSelectedOperationAt(const QPoint& pos);
    // Opens the selected operation's name for editing in place; Enter renames it (undoable).
    void renameSelected();

signals:
    void editOperationRequested(int index);
    void editJobSetupRequested();
    void editPostRequested();

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dragMoveEvent(QDragMoveEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEditor(QWidget* editor, QAbstractItemDelegate::EndEditHint hint) override;

private:
    void addSetupItems(QTreeWidgetItem* jobItem);
    void addOperationItems(QTreeWidgetItem* jobItem);
    void onItemChanged(QTreeWidgetItem* item, int column);
    void openItem(QTreeWidgetItem* item);
    void updateActions();
    // Where a drop at `pos` (viewport) would move the selected operation to; -1: nowhere.
    int dropTarget(const QPoint& pos) const;
    QAction* registered(const char* id) const;

    Workbench& m_workbench;
    ActionRegistry* m_actions = nullptr;
    int m_selectAfterRebuild = -1;  // the operation an edit of ours moved or made
    bool m_rebuilding = false;
    bool m_rebuildPending = false;  // a rebuild waits for the name editor to close
};

}  // namespace camwb::gui
