// Drives the tool library on the real main window through the action registry, with a
// ScriptedPrompter: the dialog opens on the default library, "Add to Job" copies tools into the
// job as one undo step (a taken number gets the next free one and the report says so), feeds and
// speeds are computed from the cutting data and the job's material (clamped to the machine), a
// Fusion library imports, and a corrupt user library is reported and never written over.
#include "document/ToolLibrary.h"
#include "QtTestRun.h"
#include "ScriptedPrompter.h"
#include "Shots.h"
#include "document/JobFile.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Workbench.h"
#include "gui/tools/ToolActions.h"
#include "gui/tools/ToolLibraryDialog.h"
#include "gui/tools/ToolModels.h"
#include "gui/view3d/View3D.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using camwb::gui::MainWindow;
using camwb::gui::ToolLibraryDialog;
using camwb::gui::Workbench;

class ToolLibraryTest : public QObject {
    Q_OBJECT

private:
    static ScriptedPrompter* scriptPrompts(MainWindow& window)
    {
        auto* prompter = new ScriptedPrompter;
        window.setPrompter(std::unique_ptr<camwb::gui::Prompter>(prompter));
        return prompter;
    }

    static void openExample(MainWindow& window)
    {
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB)));
        QVERIFY(posted.wait(120000));
        QCOMPARE(posted.first().first().toBool(), true);
    }

    static ToolLibraryDialog* openLibrary(MainWindow& window)
    {
        if (!window.actions().trigger(QStringLiteral("Cam.Tools.Library")))
            return nullptr;
        return window.findChild<ToolLibraryDialog*>();
    }

    static int rowOf(const ToolLibraryDialog& dialog, const std::string& name)
    {
        const auto& tools = dialog.library().tools;
        for (std::size_t i = 0; i < tools.size(); ++i)
            if (tools[i].tool.name == name)
                return static_cast<int>(i);
        return -1;
    }

    static QByteArray readFile(const QString& path)
    {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    }

    static QStringList messages(const QSignalSpy& spy)
    {
        QStringList texts;
        for (const auto& args : spy)
            texts << args.at(1).toString();
        return texts;
    }

private slots:
    void init() { QFile::remove(camwb::gui::userToolLibraryPath()); }

    void addingLibraryToolsToTheJobIsOneUndoStep()
    {
        MainWindow window;
        ScriptedPrompter* prompter = scriptPrompts(window);
        window.show();
        openExample(window);
        const std::string before = camwb::document::serializeJob(window.workbench().job());

        ToolLibraryDialog* dialog = openLibrary(window);
        QVERIFY(dialog);
        QVERIFY(dialog->canSave());
        QVERIFY2(dialog->library().tools.size() >= 10, "starts from the shipped default library");
        const int d10 = rowOf(*dialog, "Flat end mill D10");
        const int d3 = rowOf(*dialog, "Flat end mill D3");
        QVERIFY(d10 >= 0 && d3 >= 0);
        dialog->selectTools({d10, d3});
        saveShot(dialog, QStringLiteral("tool-library.png"));

        QSignalSpy messageSpy(&window.workbench(), &Workbench::message);
        dialog->findChild<QPushButton*>(QStringLiteral("addToJob"))->click();
        const auto& tools = window.workbench().job().tools;
        QCOMPARE(int(tools.size()), 5);
        QCOMPARE(tools[3].tool.name, std::string("Flat end mill D10"));
        QCOMPARE(tools[3].tool.number, 4);  // T1 is the job's own D10
        QCOMPARE(tools[4].tool.number, 5);
        QVERIFY(!tools[4].cuttingData.empty());
        QVERIFY2(messages(messageSpy).join('\n').contains(QStringLiteral("added as T4: T1 is taken")),
                 qPrintable(messages(messageSpy).join('\n')));

        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(camwb::document::serializeJob(window.workbench().job()), before);
        QCOMPARE(prompter->errors.size(), 0);
    }

    void feedsAreComputedFromCuttingDataAndClampedToTheMachine()
    {
        MainWindow window;
        ScriptedPrompter* prompter = scriptPrompts(window);
        window.show();
        openExample(window);
        ToolLibraryDialog* dialog = openLibrary(window);
        QVERIFY(dialog);
        dialog->selectTools({rowOf(*dialog, "Flat end mill D3")});
        dialog->findChild<QPushButton*>(QStringLiteral("addToJob"))->click();
        const std::string withTool = camwb::document::serializeJob(window.workbench().job());

        // No material yet: an error, nothing changed.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Tools.ComputeFeeds")));
        QCOMPARE(prompter->errors.size(), 1);
        QVERIFY2(prompter->errors.first().contains(QStringLiteral("no stock material")),
                 qPrintable(prompter->errors.first()));
        QCOMPARE(camwb::document::serializeJob(window.workbench().job()), withTool);

        window.workbench().setMaterial("aluminium");
        QSignalSpy messageSpy(&window.workbench(), &Workbench::message);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Tools.ComputeFeeds")));
        const auto* d3 = window.workbench().job().tool(5);
        QVERIFY(d3);
        // vc 200 m/min on D3 wants 21221 rpm; the EMCO's spindle stops at 5000, fz 0.015 · 2 kept.
        QCOMPARE(d3->spindleRpm, 5000.0);
        QCOMPARE(d3->cuttingFeedMmPerMin, 150.0);
        const QString said = messages(messageSpy).join('\n');
        QVERIFY2(said.contains(QStringLiteral("spindle maximum")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("left as it was")), qPrintable(said));  // the job's own tools

        // The computed values stay editable in the job tools table: one undo step per edit.
        auto* tabs = dialog->findChild<QTabWidget*>(QStringLiteral("toolTabs"));
        QVERIFY(tabs);
        tabs->setCurrentWidget(dialog->jobToolView());
        QAbstractItemModel* jobTools = dialog->jobToolView()->model();
        QCOMPARE(jobTools->rowCount(), 4);
        QCOMPARE(jobTools->data(jobTools->index(3, camwb::gui::JobToolsModel::Rpm)).toDouble(), 5000.0);
        saveShot(dialog, QStringLiteral("tool-library-job-tools.png"));
        QVERIFY(jobTools->setData(jobTools->index(3, camwb::gui::JobToolsModel::Rpm), QStringLiteral("4500")));
        QCOMPARE(window.workbench().job().tool(5)->spindleRpm, 4500.0);
        QVERIFY(!jobTools->setData(jobTools->index(3, camwb::gui::JobToolsModel::Rpm), QStringLiteral("fast")));
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(window.workbench().job().tool(5)->spindleRpm, 5000.0);

        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(window.workbench().job().tool(5)->spindleRpm, 0.0);
    }

    void fusionLibraryImportsAndExports()
    {
        MainWindow window;
        ScriptedPrompter* prompter = scriptPrompts(window);
        window.show();
        ToolLibraryDialog* dialog = openLibrary(window);
        QVERIFY(dialog);
        const int before = int(dialog->library().tools.size());
        // Fusion's .tools (a zip holding tools.json), as Fusion exports it.
        prompter->files.push_back(QStringLiteral(CAMWB_TOOLS_DATA "/fusion/shop.tools"));
        dialog->findChild<QPushButton*>(QStringLiteral("importTools"))->click();
        QVERIFY2(prompter->errors.isEmpty(), qPrintable(prompter->errors.join('\n')));
        QCOMPARE(int(dialog->library().tools.size()), before + 3);
        QVERIFY(dialog->isModified());

        dialog->findChild<QLineEdit*>(QStringLiteral("toolFilter"))->setText(QStringLiteral("3FL"));
        QCOMPARE(dialog->toolView()->model()->rowCount(), 1);

        QTemporaryDir dir;
        const QString exported = dir.filePath(QStringLiteral("out.camwb-tools.json"));
        prompter->files.push_back(exported);
        dialog->findChild<QPushButton*>(QStringLiteral("exportTools"))->click();
        auto back = camwb::document::loadToolLibrary(exported.toStdString());
        QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
        QCOMPARE(int(back->tools.size()), before + 3);

        // A broken import: the error names the file and field; nothing is added.
        prompter->files.push_back(QStringLiteral(CAMWB_TOOLS_DATA "/fusion/bad-diameter.json"));
        dialog->findChild<QPushButton*>(QStringLiteral("importTools"))->click();
        QCOMPARE(int(dialog->library().tools.size()), before + 3);
        QCOMPARE(prompter->errors.size(), 1);
        QVERIFY2(prompter->errors.first().contains(QStringLiteral("geometry.DC")),
                 qPrintable(prompter->errors.first()));
        // A damaged .tools archive: said so, nothing added.
        prompter->files.push_back(QStringLiteral(CAMWB_TOOLS_DATA "/fusion/damaged.tools"));
        dialog->findChild<QPushButton*>(QStringLiteral("importTools"))->click();
        QCOMPARE(int(dialog->library().tools.size()), before + 3);
        QCOMPARE(prompter->errors.size(), 2);
        QVERIFY2(prompter->errors.last().contains(QStringLiteral("checksum does not match")),
                 qPrintable(prompter->errors.last()));

        // Closing a modified library asks; Save writes the user's library.
        prompter->answers.push_back(ScriptedPrompter::Answer::Accept);
        dialog->findChild<QPushButton*>(QStringLiteral("closeLibrary"))->click();
        QCOMPARE(prompter->questions.size(), 1);
        auto saved = camwb::document::loadToolLibrary(camwb::gui::userToolLibraryPath().toStdString());
        QVERIFY2(saved.ok(), saved.ok() ? "" : saved.error().toString().c_str());
        QCOMPARE(int(saved->tools.size()), before + 3);
    }

    void corruptLibraryIsReportedAndLeftUntouched()
    {
        const QString path = camwb::gui::userToolLibraryPath();
        QDir().mkpath(QFileInfo(path).absolutePath());
        const QByteArray corrupt = readFile(QStringLiteral(CAMWB_TOOLS_DATA "/corrupt.camwb-tools.json"));
        QVERIFY(!corrupt.isEmpty());
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(corrupt);
        }
        MainWindow window;
        ScriptedPrompter* prompter = scriptPrompts(window);
        window.show();
        ToolLibraryDialog* dialog = openLibrary(window);
        QVERIFY(dialog);
        QCOMPARE(prompter->errors.size(), 1);
        QVERIFY2(prompter->errors.first().contains(path), qPrintable(prompter->errors.first()));
        QVERIFY2(prompter->errors.first().contains(QStringLiteral("will not be saved over")),
                 qPrintable(prompter->errors.first()));
        QVERIFY(!dialog->canSave());
        QVERIFY(!dialog->findChild<QPushButton*>(QStringLiteral("saveLibrary"))->isEnabled());

        dialog->addTool();
        QVERIFY(!dialog->save());
        dialog->findChild<QPushButton*>(QStringLiteral("closeLibrary"))->click();
        QCOMPARE(prompter->questions.size(), 0);  // nothing to offer: it cannot be saved
        QCOMPARE(readFile(path), corrupt);
        QFile::remove(path);
    }
};

int main(int argc, char** argv)
{
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    // The user's library goes to the test's own data folder (XDG_DATA_HOME, set per test and platform).
    QtTestRun run(argc, argv);
    ToolLibraryTest test;
    run.run(&test);
    return run.finish();
}

#include "ToolLibraryTest.moc"
