#include "gui/actions/ActionRegistry.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QToolBar>

#include <algorithm>

namespace camwb::gui {

ActionRegistry::ActionRegistry(QObject* parent) : QObject(parent) {}

QAction* ActionRegistry::add(const ActionSpec& spec)
{
    auto* action = new QAction(spec.text, this);
    action->setShortcut(spec.shortcut);
    QString label = QString(spec.text).remove('&');
    action->setToolTip(spec.toolTip.isEmpty() ? label : spec.toolTip);
    if (label.endsWith(QChar(0x2026)))
        label.chop(1);
    action->setIconText(label);
    return adopt(spec, action);
}

QAction* ActionRegistry::adopt(const ActionSpec& spec, QAction* action)
{
    Q_ASSERT_X(!m_byId.count(spec.id), "ActionRegistry::add", "duplicate action id");
    action->setObjectName(spec.id);
    action->setData(spec.id);
    m_entries.push_back({spec, action});
    m_byId[spec.id] = action;
    return action;
}

QAction* ActionRegistry::action(const QString& id) const
{
    auto it = m_byId.find(id);
    return it == m_byId.end() ? nullptr : it->second;
}

QStringList ActionRegistry::ids() const
{
    QStringList list;
    for (const Entry& e : m_entries)
        list << e.spec.id;
    return list;
}

bool ActionRegistry::trigger(const QString& id)
{
    QAction* a = action(id);
    if (!a || !a->isEnabled())
        return false;
    a->trigger();
    return true;
}

void ActionRegistry::moveBefore(const QString& id, const QString& beforeId)
{
    auto byId = [](const QString& wanted) { return [&wanted](const Entry& e) { return e.spec.id == wanted; }; };
    auto moved = std::find_if(m_entries.begin(), m_entries.end(), byId(id));
    if (moved == m_entries.end() || std::none_of(m_entries.begin(), m_entries.end(), byId(beforeId)))
        return;
    Entry entry = *moved;
    m_entries.erase(moved);
    m_entries.insert(std::find_if(m_entries.begin(), m_entries.end(), byId(beforeId)), entry);
}

void ActionRegistry::buildMenus(QMenuBar* menuBar) const
{
    std::map<QString, QMenu*> menus;
    for (const Entry& e : m_entries) {
        if (e.spec.menu.isEmpty())
            continue;
        QMenu*& menu = menus[e.spec.menu];
        if (!menu)
            menu = menuBar->addMenu(e.spec.menu);
        if (e.spec.separatorBefore)
            menu->addSeparator();
        menu->addAction(e.action);
    }
}

void ActionRegistry::buildToolBar(QToolBar* toolBar) const
{
    for (const Entry& e : m_entries) {
        if (!e.spec.onToolBar)
            continue;
        if (e.spec.separatorBefore && !toolBar->actions().isEmpty())
            toolBar->addSeparator();
        toolBar->addAction(e.action);
    }
}

}  // namespace camwb::gui
