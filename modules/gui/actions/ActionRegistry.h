// Registry of UI actions with stable ids ("Cam.Job.Post"). Menus, toolbars and shortcuts are
// built from it, and tests trigger actions by id, so no feature hides inside a widget.
#pragma once

#include <QKeySequence>
#include <QObject>
#include <QString>
#include <QStringList>

#include <map>
#include <vector>

class QAction;
class QMenuBar;
class QToolBar;

namespace camwb::gui {

struct ActionSpec {
    QString id;    // stable: Cam.<Area>.<Verb>
    QString text;  // translated menu text
    QString menu;  // translated menu title the action goes into ("&File")
    QKeySequence shortcut = {};
    bool onToolBar = false;
    bool separatorBefore = false;
    QString toolTip = {};
};

class ActionRegistry : public QObject {
    Q_OBJECT
public:
    explicit ActionRegistry(QObject* parent = nullptr);

    // Registers and returns the action (owned by the registry). Ids must be unique. Its toolbar
    // label (iconText) is fixed to the spec's text, so a text that changes later (Undo <step>)
    // changes the menu, not the toolbar's width.
    QAction* add(const ActionSpec& spec);
    // Registers an action made elsewhere (a dock's show/hide action) for the menus and by id; it
    // keeps its own text and owner.
    QAction* adopt(const ActionSpec& spec, QAction* action);
    // Puts `id` just before `beforeId` in the menus and the toolbar (an action registered later
    // by its own file that belongs higher in a menu, as New above Open). Unknown ids: no-op.
    void moveBefore(const QString& id, const QString& beforeId);
    QAction* action(const QString& id) const;  // nullptr when unknown
    QStringList ids() const;                   // in registration order
    // Triggers an enabled action by id; false when unknown or disabled.
    bool trigger(const QString& id);

    void buildMenus(QMenuBar* menuBar) const;  // menus in order of first use
    void buildToolBar(QToolBar* toolBar) const;

private:
    struct Entry {
        ActionSpec spec;
        QAction* action;
    };
    std::vector<Entry> m_entries;
    std::map<QString, QAction*> m_byId;
};

}  // namespace camwb::gui
