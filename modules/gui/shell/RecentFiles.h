// The jobs and NC programs opened or saved last (File ▸ Open Recent), newest first, at most
// kMaxRecentFiles, kept in the application's settings so they survive a restart.
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

class QMenu;

namespace camwb::gui {

inline constexpr int kMaxRecentFiles = 8;

class RecentFiles : public QObject {
    Q_OBJECT
public:
    explicit RecentFiles(QObject* parent = nullptr);

    QStringList paths() const;  // newest first, absolute
    // Moves `path` (made absolute) to the front; the oldest beyond kMaxRecentFiles drop out.
    void add(const QString& path);
    void remove(const QString& path);
    void clear();

    // Fills `menu` with the list each time it opens: one entry per file (a missing file greyed),
    // then "Clear Recent Files". Choosing an entry emits openRequested.
    void attach(QMenu* menu);
    void fill(QMenu* menu);

signals:
    void openRequested(const QString& path);

private:
    void store(const QStringList& paths);
};

}  // namespace camwb::gui
