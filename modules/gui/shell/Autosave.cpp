#include "gui/shell/Autosave.h"

#include "document/JobFile.h"
#include "gui/shell/Workbench.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>

namespace camwb::gui {

namespace {

const QString kSuffix = QStringLiteral(".autosave");

// "untitled-<time>-<pid>.camwb.autosave": the pid tells a running window's file from an orphan.
qint64 writerPid(const QString& fileName)
{
    const QStringList parts = fileName.section(QLatin1Char('.'), 0, 0).split(QLatin1Char('-'));
    return parts.size() == 4 ? parts[3].toLongLong() : 0;
}

bool processRuns(qint64 pid)
{
    return pid > 0 &&
           (pid == QCoreApplication::applicationPid() || QFileInfo::exists(QStringLiteral("/proc/%1").arg(pid)));
}

}  // namespace

Autosaver::Autosaver(Workbench& workbench, QObject* parent) : QObject(parent), m_workbench(workbench)
{
    m_untitled = untitledFolder() + QStringLiteral("/untitled-%1-%2.camwb%3")
                                        .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss")))
                                        .arg(QCoreApplication::applicationPid())
                                        .arg(kSuffix);
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(2000);
    m_interval.setInterval(60 * 1000);
    connect(&m_debounce, &QTimer::timeout, this, &Autosaver::writeNow);
    connect(&m_interval, &QTimer::timeout, this, &Autosaver::writeNow);
    connect(&m_workbench, &Workbench::jobChanged, this, &Autosaver::jobChanged);
    m_side = currentSidePath();
}

Autosaver::~Autosaver() { removeOwned(); }

QString Autosaver::sidePathFor(const QString& jobPath) { return jobPath + kSuffix; }

QString Autosaver::untitledFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
}

QStringList Autosaver::orphanedUntitled()
{
    const QFileInfoList files =
        QDir(untitledFolder()).entryInfoList({QStringLiteral("untitled-*.camwb") + kSuffix}, QDir::Files, QDir::Time);
    QStringList orphans;
    for (const QFileInfo& file : files)
        if (!processRuns(writerPid(file.fileName())))
            orphans << file.absoluteFilePath();
    return orphans;
}

QString Autosaver::newerAutosave(const QString& jobPath)
{
    const QFileInfo side(sidePathFor(jobPath));
    const QFileInfo job(jobPath);
    if (!side.exists() || (job.exists() && side.lastModified() < job.lastModified()))
        return {};
    return side.absoluteFilePath();
}

void Autosaver::setIntervalSeconds(int seconds) { m_interval.setInterval(std::max(seconds, 1) * 1000); }

void Autosaver::adopt(const QString& sidePath)
{
    if (m_workbench.document().path().empty())
        m_untitled = sidePath;
    m_side = sidePath;
    m_owned = true;
}

QString Autosaver::currentSidePath() const
{
    const QString path = QString::fromStdString(m_workbench.document().path());
    return path.isEmpty() ? m_untitled : sidePathFor(path);
}

void Autosaver::jobChanged()
{
    const QString side = currentSidePath();
    if (side != m_side) {  // another job (open, new, save as): its edits were saved or discarded
        removeOwned();
        m_side = side;
    }
    if (m_workbench.document().isModified()) {
        m_pending = true;
        m_debounce.start();
        if (!m_interval.isActive())
            m_interval.start();
        return;
    }
    // Saved, or undone back to the saved state: the file on disk is the job.
    m_pending = false;
    m_debounce.stop();
    m_interval.stop();
    removeOwned();
}

void Autosaver::writeNow()
{
    if (!m_pending)
        return;
    QDir().mkpath(QFileInfo(m_side).absolutePath());
    if (base::Status saved = document::saveJob(m_workbench.job(), m_side.toStdString()); !saved) {
        if (!std::exchange(m_failed, true))
            emit message(base::Severity::Warning,
                         tr("Autosave failed: %1").arg(QString::fromStdString(saved.error().toString())));
        return;
    }
    m_failed = false;
    m_owned = true;
    m_pending = false;
    emit written(m_side);
}

void Autosaver::removeOwned()
{
    if (std::exchange(m_owned, false))
        QFile::remove(m_side);
}

}  // namespace camwb::gui
