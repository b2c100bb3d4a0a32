#include "gui/shell/Autosave.h"

#include "document/JobFile.h"
#include "gui/shell/Workbench.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>

namespace camwb::gui {

namespace {

const QString kSuffix = QStringLiteral(".autosave");

// "<name>-<pid>.camwb.autosave": the pid tells a running window's file from a crash's.
qint64 writerPid(const QString& fileName)
{
    return fileName.chopped(kSuffix.size() + 6).section(QLatin1Char('-'), -1).toLongLong();
}

bool processRuns(qint64 pid)
{
    return pid > 0 &&
           (pid == QCoreApplication::applicationPid() || QFileInfo::exists(QStringLiteral("/proc/%1").arg(pid)));
}

// The side files matching `pattern` in `folder` that no running CAM Workbench writes, newest first.
QStringList orphans(const QString& folder, const QString& pattern)
{
    QStringList found;
    for (const QFileInfo& file : QDir(folder).entryInfoList({pattern}, QDir::Files, QDir::Time))
        if (!processRuns(writerPid(file.fileName())))
            found << file.absoluteFilePath();
    return found;
}

// The job's name to be recognised by a person, a hash of its full path to tell apart jobs of the
// same name in different folders.
QString sideStem(const QString& jobPath)
{
    const QFileInfo job(jobPath);
    const QByteArray hash =
        QCryptographicHash::hash(QDir::cleanPath(job.absoluteFilePath()).toUtf8(), QCryptographicHash::Sha1).toHex();
    return job.completeBaseName() + QLatin1Char('-') + QString::fromLatin1(hash.left(12));
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

QString Autosaver::sidePathFor(const QString& jobPath, qint64 pid)
{
    return autosaveFolder() + QStringLiteral("/%1-%2.camwb%3")
                                  .arg(sideStem(jobPath))
                                  .arg(pid > 0 ? pid : QCoreApplication::applicationPid())
                                  .arg(kSuffix);
}

QString Autosaver::autosaveFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
}

QString Autosaver::untitledFolder() { return autosaveFolder() + QStringLiteral("/untitled"); }

QStringList Autosaver::orphanedUntitled() { return orphans(untitledFolder(), QStringLiteral("untitled-*") + kSuffix); }

QString Autosaver::newerAutosave(const QString& jobPath)
{
    const QStringList found = orphans(autosaveFolder(), sideStem(jobPath) + QStringLiteral("-*.camwb") + kSuffix);
    const QFileInfo job(jobPath);
    if (found.isEmpty() || (job.exists() && QFileInfo(found.first()).lastModified() < job.lastModified()))
        return {};
    return found.first();
}

void Autosaver::setIntervalSeconds(int seconds) { m_interval.setInterval(std::max(seconds, 1) * 1000); }

void Autosaver::adopt(const QString& sidePath) { m_inherited = sidePath; }

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
    if (!m_inherited.isEmpty())  // the edits it held are in this window's file now
        QFile::remove(std::exchange(m_inherited, QString()));
    emit written(m_side);
}

void Autosaver::removeOwned()
{
    if (std::exchange(m_owned, false))
        QFile::remove(m_side);
    if (!m_inherited.isEmpty())
        QFile::remove(std::exchange(m_inherited, QString()));
}

}  // namespace camwb::gui
