// Helpers of JobStateTest: the example job copied to a scratch folder and opened with a scripted
// prompter (tests/gui/common), and readers of what the window shows (banners, the job tree's marks).
#pragma once

#include "gui/shell/JobTree.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Prompter.h"
#include "gui/shell/Workbench.h"

#include "ScriptedPrompter.h"
#include "Shots.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QGuiApplication>
#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include <memory>

using camwb::gui::MainWindow;
using camwb::gui::Prompter;
using camwb::gui::Workbench;

namespace {

bool withGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

QString readFile(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

bool writeFile(const QString& path, const QByteArray& text)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(text) == text.size();
}

// The example job and its model in a scratch folder (saves must not touch the sources).
QString copyExample(const QTemporaryDir& dir, const QString& modelName = QStringLiteral("example-block.step"))
{
    const QString sources = QFileInfo(QStringLiteral(CAMWB_EXAMPLE_JOB)).absolutePath();
    QFile::copy(sources + QStringLiteral("/example-block.step"), dir.filePath(QStringLiteral("example-block.step")));
    QString job = readFile(QStringLiteral(CAMWB_EXAMPLE_JOB));
    job.replace(QStringLiteral("\"example-block.step\""), QLatin1Char('"') + modelName + QLatin1Char('"'));
    const QString path = dir.filePath(modelName == QLatin1String("example-block.step") ? QStringLiteral("job.camwb")
                                                                                       : QStringLiteral("other.camwb"));
    return writeFile(path, job.toUtf8()) ? path : QString();
}

ScriptedPrompter& scripted(MainWindow& window)
{
    auto prompter = std::make_unique<ScriptedPrompter>();
    ScriptedPrompter& ref = *prompter;
    window.setPrompter(std::move(prompter));
    return ref;
}

void waitIdle(MainWindow& window)
{
    QElapsedTimer waited;
    waited.start();
    while (window.workbench().isBusy() && waited.elapsed() < 120000)
        QTest::qWait(20);
    QVERIFY(!window.workbench().isBusy());
}

// Opens `job` and waits for its compute + post to end (ok or not).
bool openAndWait(MainWindow& window, const QString& job)
{
    QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
    if (!window.openJob(job) || !posted.wait(120000))
        return false;
    waitIdle(window);
    return true;
}

// The window (shown at the screenshots' size unless `shown` is false) with a scripted prompter and
// the example job open and posted; nullptr when that failed.
ScriptedPrompter* openExample(MainWindow& window, const QTemporaryDir& dir, bool shown = true)
{
    if (shown) {
        window.resize(1600, 1000);
        window.show();
        if (!QTest::qWaitForWindowExposed(&window))
            return nullptr;
    }
    ScriptedPrompter& prompter = scripted(window);
    return openAndWait(window, copyExample(dir)) ? &prompter : nullptr;
}

QLabel* banner(MainWindow& window, const char* name) { return window.findChild<QLabel*>(QLatin1String(name)); }

QTreeWidgetItem* treeItem(MainWindow& window, const QString& text)
{
    const auto items = window.jobTree()->findItems(text, Qt::MatchExactly | Qt::MatchRecursive);
    return items.isEmpty() ? nullptr : items.first();
}

// The "Error" row the tree puts under a marked item, or an empty text.
QString problemOf(QTreeWidgetItem* item)
{
    for (int i = 0; item != nullptr && i < item->childCount(); ++i)
        if (item->child(i)->data(0, Qt::UserRole).toString() == QLatin1String("problem"))
            return item->child(i)->text(1);
    return {};
}

// The window as the user sees it; the picture must show something (tests/gui/common/Shots.h).
void shot(MainWindow& window, const char* name)
{
    QTest::qWait(300);
    saveShot(&window, QLatin1String(name));
}

// The example's operation 0 (the outer contour) cut 46 mm deep with a 22 mm flute: cannot be made.
camwb::document::Operation tooDeep(MainWindow& window)
{
    camwb::document::Operation op = window.workbench().job().operations.at(0);
    op.heights.finalZ = -30.0;
    return op;
}

}  // namespace
