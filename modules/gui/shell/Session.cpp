#include "gui/shell/Session.h"

#include "document/JobFile.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/Autosave.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/NcDocument.h"
#include "gui/shell/PreferencesDialog.h"
#include "gui/shell/Prompter.h"
#include "gui/shell/RecentFiles.h"
#include "gui/shell/ReportView.h"
#include "gui/shell/Workbench.h"

#include <QAction>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QStatusBar>

namespace camwb::gui {

namespace {

bool isJobFile(const QString& path) { return path.endsWith(QLatin1String(".camwb"), Qt::CaseInsensitive); }

QString when(const QString& path) { return QLocale().toString(QFileInfo(path).lastModified(), QLocale::ShortFormat); }

}  // namespace

Session::Session(MainWindow& window, const QString& fileMenu, const QString& editMenu) :
    QObject(&window),
    m_window(window),
    m_preferences(Preferences::load()),
    m_recent(new RecentFiles(this)),
    m_autosaver(new Autosaver(window.workbench(), this))
{
    m_autosaver->setIntervalSeconds(m_preferences.autosaveSeconds);
    setDisplayUnit(m_preferences.units);
    connect(m_autosaver, &Autosaver::message, window.reportView(), &ReportView::append);
    connect(m_recent, &RecentFiles::openRequested, this, &Session::openRecent);
    trackRecentJobs();
    registerActions(fileMenu, editMenu);
}

void Session::registerActions(const QString& file, const QString& edit)
{
    ActionRegistry& actions = m_window.actions();
    QAction* newJob = actions.add({QStringLiteral("Cam.File.New"), tr("&New Job"), file, QKeySequence::New, true});
    connect(newJob, &QAction::triggered, this, &Session::newJob);
    actions.moveBefore(QStringLiteral("Cam.File.New"), QStringLiteral("Cam.File.Open"));

    auto* recentMenu = new QMenu(tr("Open &Recent"), &m_window);
    recentMenu->setObjectName(QStringLiteral("recentFilesMenu"));
    m_recent->attach(recentMenu);
    actions.adopt({QStringLiteral("Cam.File.OpenRecent"), recentMenu->title(), file}, recentMenu->menuAction());
    actions.moveBefore(QStringLiteral("Cam.File.OpenRecent"), QStringLiteral("Cam.File.Save"));

    QAction* preferences = actions.add({QStringLiteral("Cam.Edit.Preferences"), tr("&Preferences…"), edit,
                                        QKeySequence(Qt::CTRL | Qt::Key_Comma), false, true});
    connect(preferences, &QAction::triggered, this, &Session::showPreferences);
}

// A job that is opened or saved (clean, with a path) goes to the front of the recent files.
void Session::trackRecentJobs()
{
    Workbench& workbench = m_window.workbench();
    connect(&workbench, &Workbench::jobChanged, this, [this, &workbench] {
        const QString path = QString::fromStdString(workbench.document().path());
        if (path.isEmpty() || workbench.document().isModified()) {
            m_lastRecorded.clear();  // the next clean state (a save) is recorded again
            return;
        }
        if (path != m_lastRecorded)
            m_recent->add(path);
        m_lastRecorded = path;
    });
}

void Session::setPreferences(const Preferences& preferences)
{
    m_preferences = preferences;
    m_preferences.save();
    m_autosaver->setIntervalSeconds(preferences.autosaveSeconds);
    setDisplayUnit(preferences.units);
    emit preferencesChanged(m_preferences);
}

bool Session::openJob(const QString& path)
{
    const QString side = Autosaver::newerAutosave(path);
    if (!side.isEmpty()) {
        const Choice choice = offerRecovery(side, path);
        if (choice == Choice::Cancelled)
            return false;
        if (choice == Choice::Recovered)
            return true;
    }
    return m_window.workbench().openJob(path);
}

Session::Choice Session::offerRecovery(const QString& sidePath, const QString& jobPath)
{
    const QString text =
        jobPath.isEmpty() ? tr("An untitled job has changes that were autosaved on %1 and never saved: CAM Workbench "
                               "may have stopped. Recover them?")
                                .arg(when(sidePath))
                          : tr("The job %1 has changes that were autosaved on %2 and not saved: CAM Workbench may have "
                               "stopped. Recover them?")
                                .arg(QFileInfo(jobPath).fileName(), when(sidePath));
    const Prompter::Answer answer =
        m_window.prompter().ask({tr("Recover unsaved changes"), text, tr("Recover"), tr("Discard")});
    if (answer == Prompter::Answer::Cancel)
        return Choice::Cancelled;
    if (answer == Prompter::Answer::Discard) {
        QFile::remove(sidePath);
        m_window.reportView()->append(base::Severity::Note, tr("Discarded the autosaved changes %1").arg(sidePath));
        return Choice::Declined;
    }
    return recover(sidePath, jobPath) ? Choice::Recovered : Choice::Declined;
}

// The job as saved (when it can be read) with the autosaved job as one undoable edit on top: the
// window shows it modified, Save writes it to the job's own path, Undo shows what was saved.
bool Session::recover(const QString& sidePath, const QString& jobPath)
{
    auto recovered = document::loadJob(sidePath.toStdString());
    if (!recovered) {
        // Never lost: kept beside, under a name no one will open or overwrite by accident.
        const QString kept = sidePath + QStringLiteral(".corrupt");
        QFile::remove(kept);
        QFile::rename(sidePath, kept);
        const QString why = QString::fromStdString(recovered.error().toString());
        const QString text =
            tr("The autosaved changes cannot be read: %1\nThe file is kept as %2.").arg(why, kept) +
            (jobPath.isEmpty() ? QString() : tr("\nThe job %1 is opened as it was saved.").arg(jobPath));
        m_window.reportView()->append(base::Severity::Error, text);
        m_window.prompter().showError(tr("Recover unsaved changes"), text);
        return false;
    }
    document::Job base = recovered.value();
    if (!jobPath.isEmpty())
        if (auto saved = document::loadJob(jobPath.toStdString()))
            base = std::move(saved).value();
    Workbench& workbench = m_window.workbench();
    workbench.setJob(std::move(base), jobPath);
    m_autosaver->adopt(sidePath);
    workbench.document().edit(tr("Recover Autosaved Changes").toStdString(),
                              [&recovered](document::Job& job) { job = recovered.value(); });
    m_window.reportView()->append(base::Severity::Note, tr("Recovered the autosaved changes %1").arg(sidePath));
    return true;
}

void Session::offerRecoveryAtStart()
{
    QList<std::pair<QString, QString>> candidates;  // side file, job (empty: untitled)
    for (const QString& side : Autosaver::orphanedUntitled())
        candidates.append({side, QString()});
    for (const QString& path : m_recent->paths())
        if (isJobFile(path))
            if (const QString side = Autosaver::newerAutosave(path); !side.isEmpty())
                candidates.append({side, path});
    for (const auto& [side, job] : candidates) {
        const Choice choice = offerRecovery(side, job);
        if (choice == Choice::Cancelled || choice == Choice::Recovered)
            return;
    }
}

void Session::newJob()
{
    if (!m_window.settleTaskPanel() || !m_window.confirmDiscard() ||
        !m_window.ncDocument()->mayReplace(tr("A new job replaces them with its program.")))
        return;
    document::Job job;
    if (!m_preferences.defaultPostId.isEmpty())
        job.postId = m_preferences.defaultPostId.toStdString();
    job.machineId = m_preferences.defaultMachineId.toStdString();
    m_window.workbench().setJob(std::move(job), QString());
    m_window.reportView()->append(base::Severity::Note, tr("New job"));
}

void Session::openRecent(const QString& path)
{
    if (!QFileInfo::exists(path)) {
        m_recent->remove(path);
        m_window.prompter().showError(tr("Open Recent"),
                                      tr("%1 does not exist any more; it is removed from the recent files.").arg(path));
        return;
    }
    if (!isJobFile(path))
        m_window.openNcFile(path);
    else if (m_window.settleTaskPanel() && m_window.confirmDiscard())
        m_window.openJob(path);
}

void Session::showPreferences()
{
    PreferencesDialog dialog(m_preferences, m_window.prompter(), &m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const bool languageChanged = dialog.preferences().language != m_preferences.language;
    setPreferences(dialog.preferences());
    if (languageChanged)
        m_window.statusBar()->showMessage(tr("The language changes when CAM Workbench is started again."), 8000);
}

}  // namespace camwb::gui
