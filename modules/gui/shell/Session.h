// What the window does around the job's files: File ▸ New Job (with the preferences' post and
// machine), Open Recent, autosave and the recovery of autosaved edits (on start and when a job
// with a newer autosave is opened), and Edit ▸ Preferences. Its actions are registered here.
#pragma once

#include "gui/shell/Preferences.h"

#include <QObject>
#include <QString>

namespace camwb::gui {

class Autosaver;
class MainWindow;
class RecentFiles;

class Session : public QObject {
    Q_OBJECT
public:
    // Registers Cam.File.New, Cam.File.OpenRecent and Cam.Edit.Preferences in `window`'s registry,
    // in the menus titled `fileMenu` and `editMenu` (the window's own, translated titles).
    Session(MainWindow& window, const QString& fileMenu, const QString& editMenu);

    RecentFiles& recentFiles() { return *m_recent; }
    Autosaver& autosaver() { return *m_autosaver; }
    const Preferences& preferences() const { return m_preferences; }
    void setPreferences(const Preferences& preferences);

    // Opens a job, first offering to recover its autosave when that is newer than the job
    // (Cancel: nothing is opened); false when nothing was opened.
    bool openJob(const QString& path);
    // Asks about each autosave a stopped CAM Workbench left (untitled jobs, recent jobs) until
    // one is recovered or the user cancels.
    void offerRecoveryAtStart();
    // A new, untitled job with the preferences' default post and machine (after asking to save).
    void newJob();
    // Opens an entry of Open Recent; a file that is gone is said so and dropped from the list.
    void openRecent(const QString& path);
    void showPreferences();

signals:
    void preferencesChanged(const camwb::gui::Preferences& preferences);

private:
    void registerActions(const QString& file, const QString& edit);
    void trackRecentJobs();
    enum class Choice { Recovered, Declined, Cancelled };
    Choice offerRecovery(const QString& sidePath, const QString& jobPath);
    bool recover(const QString& sidePath, const QString& jobPath);

    MainWindow& m_window;
    Preferences m_preferences;
    RecentFiles* m_recent;
    Autosaver* m_autosaver;
    QString m_lastRecorded;  // the job path last put into the recent files
};

}  // namespace camwb::gui
