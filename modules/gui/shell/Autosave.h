// Autosave: while the job has unsaved edits it is written, with the same atomic writer as a save,
// to a side file in the app data folder's autosave/ a moment after each edit and every N seconds.
// Not beside the job: its folder may be read-only or shared. The writer's pid is in the name, so a
// running window's file is never offered as a crash's. A save, an undo back to the saved state or
// a clean close removes it; a crash leaves it for recovery (gui/shell/Session.h).
#pragma once

#include "base/Diagnostic.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

namespace camwb::gui {

class Workbench;

class Autosaver : public QObject {
    Q_OBJECT
public:
    Autosaver(Workbench& workbench, QObject* parent = nullptr);
    // Removes the side file it wrote: the window closed cleanly (saved or the edits discarded).
    ~Autosaver() override;

    // The side file of a saved job written by process `pid` (0: this one):
    // autosave/<job name>-<path hash>-<pid>.camwb.autosave.
    static QString sidePathFor(const QString& jobPath, qint64 pid = 0);
    static QString autosaveFolder();
    // Where untitled jobs are autosaved: autosave/untitled/untitled-<time>-<pid>.camwb.autosave.
    static QString untitledFolder();
    // Untitled autosaves no running CAM Workbench is writing, newest first.
    static QStringList orphanedUntitled();
    // The newest side file of `jobPath` no running window writes, when it is at least as new as
    // the job; else empty.
    static QString newerAutosave(const QString& jobPath);

    QString sidePath() const { return m_side; }
    void setIntervalSeconds(int seconds);
    void setDebounceMs(int ms) { m_debounce.setInterval(ms); }
    // Takes over a recovered side file: removed once this window has written its own (or the
    // job is saved, or the window closes cleanly), so the edits it holds are never unsaved nowhere.
    void adopt(const QString& sidePath);
    // Writes the job now when it has edits not yet autosaved.
    void writeNow();

signals:
    void written(const QString& sidePath);
    void message(camwb::base::Severity severity, const QString& text);

private:
    void jobChanged();
    QString currentSidePath() const;
    void removeOwned();

    Workbench& m_workbench;
    QTimer m_debounce;       // after an edit: written once the user pauses
    QTimer m_interval;       // and every N seconds during a long stream of edits
    QString m_untitled;      // this window's side file for an untitled job
    QString m_side;          // the side file of the job now open
    QString m_inherited;     // a recovered side file, until this window's own replaces it
    bool m_owned = false;    // m_side was written by this window
    bool m_pending = false;  // edits not yet autosaved
    bool m_failed = false;   // a failure was reported (once, not on every edit)
};

}  // namespace camwb::gui
