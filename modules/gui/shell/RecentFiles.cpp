#include "gui/shell/RecentFiles.h"

#include "gui/shell/Preferences.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace camwb::gui {

namespace {

const QString kKey = QStringLiteral("recentFiles");

QString absolute(const QString& path) { return QDir::cleanPath(QFileInfo(path).absoluteFilePath()); }

}  // namespace

RecentFiles::RecentFiles(QObject* parent) : QObject(parent) {}

QStringList RecentFiles::paths() const { return appSettings()->value(kKey).toStringList(); }

void RecentFiles::add(const QString& path)
{
    const QString file = absolute(path);
    QStringList list = paths();
    list.removeAll(file);
    list.prepend(file);
    store(list.mid(0, kMaxRecentFiles));
}

void RecentFiles::remove(const QString& path)
{
    QStringList list = paths();
    list.removeAll(absolute(path));
    store(list);
}

void RecentFiles::clear() { store({}); }

void RecentFiles::store(const QStringList& paths) { appSettings()->setValue(kKey, paths); }

void RecentFiles::attach(QMenu* menu)
{
    connect(menu, &QMenu::aboutToShow, this, [this, menu] { fill(menu); });
    fill(menu);
}

void RecentFiles::fill(QMenu* menu)
{
    menu->clear();
    const QStringList list = paths();
    int number = 1;
    for (const QString& path : list) {
        const bool exists = QFileInfo::exists(path);
        // "&1 job.camwb": a digit to reach it by keyboard; the full path in the tooltip and status bar.
        QString text = QStringLiteral("&%1 %2").arg(number++).arg(QFileInfo(path).fileName());
        if (!exists)
            text = tr("%1 (missing)").arg(text);
        QAction* action = menu->addAction(text);
        action->setToolTip(path);
        action->setStatusTip(path);
        action->setData(path);
        action->setEnabled(exists);
        connect(action, &QAction::triggered, this, [this, path] { emit openRequested(path); });
    }
    if (list.isEmpty())
        menu->addAction(tr("No recent files"))->setEnabled(false);
    menu->addSeparator();
    QAction* clearAction = menu->addAction(tr("&Clear Recent Files"));
    clearAction->setObjectName(QStringLiteral("clearRecentFiles"));
    clearAction->setEnabled(!list.isEmpty());
    connect(clearAction, &QAction::triggered, this, &RecentFiles::clear);
}

}  // namespace camwb::gui
