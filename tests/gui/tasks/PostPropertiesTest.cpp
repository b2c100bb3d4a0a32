// The post properties form generated from both bundled production posts (a widget per type, the
// description as tooltip, the default shown, bold when changed, reset), and the post settings
// panel on the example job: a changed property is one undo step that changes the NC, a change of
// post keeps the matching values and reports the dropped ones, undo restores both. Screenshots of
// the panel for both posts (CAMWB_SHOTS_DIR). Under Xvfb and offscreen.
#include "QtTestRun.h"
#include "Shots.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/PostPropertiesForm.h"
#include "gui/tasks/PostSettingsPanel.h"
#include "gui/view3d/View3D.h"
#include "post/PostProcessor.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>

using camwb::gui::MainWindow;
using camwb::gui::PostPropertiesForm;
using camwb::gui::PostSettingsPanel;
using camwb::gui::Workbench;
namespace post = camwb::post;

namespace {

post::PostInfo bundled(const char* id)
{
    auto loaded = post::PostProcessor::load(QStringLiteral(CAMWB_POSTS_DIR "/%1.js").arg(id).toStdString());
    return loaded ? loaded->info() : post::PostInfo{};
}

const char* widgetClass(post::PropertyType type)
{
    switch (type) {
    case post::PropertyType::Bool:
        return "QCheckBox";
    case post::PropertyType::Enum:
        return "QComboBox";
    case post::PropertyType::Integer:
        return "QSpinBox";
    case post::PropertyType::Number:
        return "QDoubleSpinBox";
    case post::PropertyType::String:
        break;
    }
    return "QLineEdit";
}

bool isBold(QWidget* widget) { return widget->font().bold(); }

void waitIdle(Workbench& workbench)
{
    QElapsedTimer waited;
    waited.start();
    while (workbench.isBusy() && waited.elapsed() < 120000)
        QTest::qWait(20);
    QVERIFY(!workbench.isBusy());
}

// Runs `change` and waits until the program posted after it is there.
template <class Change> void andWaitForNc(Workbench& workbench, Change change)
{
    QSignalSpy posted(&workbench, &Workbench::postFinished);
    change();
    QVERIFY(posted.count() > 0 || posted.wait(120000));
    waitIdle(workbench);
}

PostSettingsPanel* openPanel(MainWindow& window)
{
    if (!window.actions().trigger(QStringLiteral("Cam.Job.PostSettings")))
        return nullptr;
    for (PostSettingsPanel* panel : window.findChildren<PostSettingsPanel*>())
        if (panel->isVisible())  // a closed one may wait for its deleteLater
            return panel;
    return nullptr;
}

}  // namespace

class PostPropertiesTest : public QObject {
    Q_OBJECT

private slots:
    void formHasAWidgetPerPropertyWithTooltipDefaultAndReset_data()
    {
        QTest::addColumn<QString>("postId");
        QTest::addColumn<QString>("property");  // an int or enum property to change
        QTest::addColumn<QString>("newValue");
        QTest::newRow("sinumerik828d-emco") << "sinumerik828d-emco"
                                            << "sequenceStep"
                                            << "5";
        QTest::newRow("heidenhain-itnc530") << "heidenhain-itnc530"
                                            << "language"
                                            << "czech";
    }
    void formHasAWidgetPerPropertyWithTooltipDefaultAndReset()
    {
        QFETCH(QString, postId);
        QFETCH(QString, property);
        QFETCH(QString, newValue);
        const post::PostInfo info = bundled(qPrintable(postId));
        QVERIFY(!info.properties.empty());

        PostPropertiesForm form;
        form.setPost(info, {});
        QVERIFY(form.values().empty());
        for (const post::PropertyDef& def : info.properties) {
            QWidget* editor = form.editor(def.name);
            QVERIFY2(editor, def.name.c_str());
            QVERIFY2(editor->inherits(widgetClass(def.type)), def.name.c_str());
            QVERIFY(editor->toolTip().contains(QString::fromStdString(def.description)));
            QCOMPARE(form.value(def.name), def.defaultValue);
            QVERIFY(!isBold(editor));
            auto* reset = form.findChild<QToolButton*>(QStringLiteral("reset.") + QString::fromStdString(def.name));
            QVERIFY(reset);
            QVERIFY(!reset->isEnabled());
            if (auto* spin = qobject_cast<QSpinBox*>(editor)) {  // the declared range
                if (def.min)
                    QCOMPARE(spin->minimum(), int(*def.min));
                if (def.max)
                    QCOMPARE(spin->maximum(), int(*def.max));
            }
            if (auto* combo = qobject_cast<QComboBox*>(editor))
                QCOMPARE(combo->count(), int(def.values.size()));
        }
        // The default is shown beside each editor.
        QCOMPARE(form.findChildren<QLabel*>(QStringLiteral("defaultHint")).size(), qsizetype(info.properties.size()));

        // The user changes one: it is the only value, bold, resettable; changed() is emitted.
        QSignalSpy changed(&form, &PostPropertiesForm::changed);
        QWidget* editor = form.editor(property.toStdString());
        if (auto* spin = qobject_cast<QSpinBox*>(editor))
            spin->setValue(newValue.toInt());
        else if (auto* combo = qobject_cast<QComboBox*>(editor))
            combo->setCurrentText(newValue);
        QCOMPARE(changed.count(), 1);
        const std::map<std::string, std::string> expected{{property.toStdString(), newValue.toStdString()}};
        QCOMPARE(form.values(), expected);
        QVERIFY(isBold(editor));
        auto* reset = form.findChild<QToolButton*>(QStringLiteral("reset.") + property);
        QVERIFY(reset->isEnabled());
        saveShot(&form, QStringLiteral("postprops-form-%1.png").arg(postId));

        QTest::mouseClick(reset, Qt::LeftButton);
        QCOMPARE(changed.count(), 2);
        QVERIFY(form.values().empty());
        QVERIFY(!isBold(editor));
        QVERIFY(!reset->isEnabled());

        // A job's values are shown (canonical text); a value the post refuses shows the default.
        form.setPost(info, {{property.toStdString(), newValue.toStdString()}, {"noSuchProperty", "1"}});
        QCOMPARE(form.values(), expected);
    }

    void perOperationPropertiesAreShownAsTheOperationsDefault()
    {
        const post::PostInfo info = bundled("heidenhain-itnc530");
        const post::PropertyDef* tcpm = info.property("tcpm");
        QVERIFY(tcpm && tcpm->perOperation);
        PostPropertiesForm form;
        form.setPost(info, {{"tcpm", "function-tcpm"}});
        QVERIFY(form.editor("tcpm"));
        QCOMPARE(form.values(), (std::map<std::string, std::string>{{"tcpm", "function-tcpm"}}));
        QVERIFY(form.findChild<QLabel*>(QStringLiteral("sectionHeading")));
    }

    // Through the action on the example job: a property changed in the panel is one undo step and
    // changes the NC; a change of post keeps what the new post takes, reports the rest; undo.
    void panelAppliesPropertiesAndPostAsOneUndoStepEach()
    {
        MainWindow window;
        window.resize(1400, 900);
        Workbench& workbench = window.workbench();
        QStringList messages;
        connect(&workbench, &Workbench::message, this,
                [&messages](Workbench::Severity, const QString& text) { messages << text; });
        andWaitForNc(workbench, [&] { QVERIFY(window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB))); });
        QCOMPARE(workbench.job().postId, std::string("sinumerik828d-emco"));
        const QString defaultNc = workbench.ncText();
        QVERIFY(defaultNc.contains(QLatin1String("\nN20 ")));
        QVERIFY(!defaultNc.contains(QLatin1String("\nN15 ")));
        const std::size_t steps = workbench.document().undoStack().count();
        QMenu* jobMenu = nullptr;
        for (QAction* menu : window.menuBar()->actions())
            if (menu->text() == QLatin1String("&Job"))
                jobMenu = menu->menu();
        QVERIFY(jobMenu &&
                jobMenu->actions().contains(window.actions().action(QStringLiteral("Cam.Job.PostSettings"))));

        QElapsedTimer opening;  // printed, not asserted: the panel loads every post's declarations
        opening.start();
        PostSettingsPanel* panel = openPanel(window);
        qInfo("post settings panel opened in %lld ms", static_cast<long long>(opening.elapsed()));
        QVERIFY(panel);
        // The example's machine (the EMCO, SINUMERIK 828D) is served by the 828D post alone.
        QCOMPARE(panel->offeredPosts(), QStringList{QStringLiteral("sinumerik828d-emco")});
        panel->showAllPosts()->setChecked(true);
        QVERIFY(panel->offeredPosts().contains(QStringLiteral("heidenhain-itnc530")));
        panel->showAllPosts()->setChecked(false);
        QCOMPARE(panel->offeredPosts().size(), 1);

        auto* step = qobject_cast<QSpinBox*>(panel->form()->editor("sequenceStep"));
        QVERIFY(step);
        step->setValue(5);
        qobject_cast<QComboBox*>(panel->form()->editor("units"))->setCurrentText(QStringLiteral("G700"));
        saveShot(panel, QStringLiteral("postprops-panel-sinumerik828d-emco.png"));
        andWaitForNc(workbench, [&] { panel->accept(); });
        QCOMPARE(workbench.document().undoStack().count(), steps + 1);
        QCOMPARE(workbench.document().undoStack().undoText(), std::string("Post properties"));
        const std::map<std::string, std::string> chosen{{"sequenceStep", "5"}, {"units", "G700"}};
        QCOMPARE(workbench.job().postProperties, chosen);
        QVERIFY(workbench.isProgramCurrent());
        QVERIFY(workbench.ncText().contains(QLatin1String("\nN15 ")));
        QVERIFY(workbench.ncText().contains(QLatin1String("G700")));

        // To the 840D (same SINUMERIK properties): both values are kept, nothing is reported.
        messages.clear();
        andWaitForNc(workbench, [&] { QVERIFY(workbench.setPost("sinumerik840d")); });
        QCOMPARE(workbench.document().undoStack().undoText(), std::string("Post"));
        QCOMPARE(workbench.job().postId, std::string("sinumerik840d"));
        QCOMPARE(workbench.job().postProperties, chosen);
        QVERIFY2(messages.filter(QStringLiteral("does not keep")).isEmpty(), qPrintable(messages.join('\n')));
        andWaitForNc(workbench, [&] { workbench.undo(); });
        QCOMPARE(workbench.job().postId, std::string("sinumerik828d-emco"));

        // In the panel, to the iTNC: nothing of the SINUMERIK's is kept, the panel says so before OK
        // and the report names each dropped property after it.
        panel = openPanel(window);
        QVERIFY(panel);
        QCOMPARE(panel->form()->values(), chosen);
        QVERIFY(panel->choosePost(QStringLiteral("heidenhain-itnc530")));
        auto* note = panel->findChild<QLabel*>(QStringLiteral("droppedNote"));
        QVERIFY(note && !note->isHidden());
        QVERIFY(note->text().contains(QLatin1String("sequenceStep")));
        QVERIFY(note->text().contains(QLatin1String("units")));
        QVERIFY(panel->form()->values().empty());
        // The job names no machine: with the iTNC post it is posted for that post's default machine.
        auto* machine = panel->findChild<QLabel*>(QStringLiteral("machineNote"));
        QVERIFY(machine && machine->text().startsWith(QLatin1String("mas-mcvl1000")));
        qobject_cast<QComboBox*>(panel->form()->editor("language"))->setCurrentText(QStringLiteral("czech"));
        saveShot(panel, QStringLiteral("postprops-panel-heidenhain-itnc530.png"));
        messages.clear();
        andWaitForNc(workbench, [&] { panel->accept(); });
        QCOMPARE(workbench.document().undoStack().count(), steps + 2);  // the 840D step was undone, then replaced
        QCOMPARE(workbench.document().undoStack().undoText(), std::string("Post"));
        QCOMPARE(workbench.job().postId, std::string("heidenhain-itnc530"));
        QCOMPARE(workbench.job().postProperties, (std::map<std::string, std::string>{{"language", "czech"}}));
        QVERIFY2(messages.filter(QStringLiteral("sequenceStep")).size() == 1, qPrintable(messages.join('\n')));
        QVERIFY2(messages.filter(QStringLiteral("property units")).size() == 1, qPrintable(messages.join('\n')));
        QVERIFY2(workbench.isProgramCurrent(), qPrintable(workbench.programProblem()));
        QCOMPARE(workbench.ncExtension(), QStringLiteral("h"));
        QVERIFY(workbench.ncText().contains(QLatin1String("BEGIN PGM")));
        QVERIFY(workbench.ncText().contains(QLatin1String("NASTROJ")));  // the Czech comment words

        // Undo: the 828D with its values and its program, byte for byte.
        andWaitForNc(workbench, [&] { workbench.undo(); });
        QCOMPARE(workbench.job().postId, std::string("sinumerik828d-emco"));
        QCOMPARE(workbench.job().postProperties, chosen);
        andWaitForNc(workbench, [&] { workbench.undo(); });
        QVERIFY(workbench.job().postProperties.empty());
        QCOMPARE(workbench.ncText(), defaultNc);
    }

    void cancelAndAnUnchangedOkAddNoStep()
    {
        MainWindow window;
        Workbench& workbench = window.workbench();
        andWaitForNc(workbench, [&] { QVERIFY(window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB))); });
        const std::size_t steps = workbench.document().undoStack().count();
        PostSettingsPanel* panel = openPanel(window);
        QVERIFY(panel);
        qobject_cast<QSpinBox*>(panel->form()->editor("sequenceStep"))->setValue(5);
        panel->reject();
        QCOMPARE(workbench.document().undoStack().count(), steps);
        QVERIFY(workbench.job().postProperties.empty());
        QTest::qWait(0);  // the closed panel deletes itself
        panel = openPanel(window);
        QVERIFY(panel);
        panel->accept();
        QCOMPARE(workbench.document().undoStack().count(), steps);
    }

    // A job's own machine stays with a post that drives it, and gives way to the post's default
    // (said in the report) when the new post cannot drive it, rather than a run that is refused.
    void aMachineTheNewPostCannotDriveGivesWayToItsDefault()
    {
        MainWindow window;
        Workbench& workbench = window.workbench();
        QStringList messages;
        connect(&workbench, &Workbench::message, this,
                [&messages](Workbench::Severity, const QString& text) { messages << text; });
        andWaitForNc(workbench, [&] { QVERIFY(window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB))); });
        andWaitForNc(workbench, [&] { QVERIFY(workbench.setPost("heidenhain-itnc530", "mas-mcvl1000")); });
        QCOMPARE(workbench.job().machineId, std::string("mas-mcvl1000"));
        andWaitForNc(workbench,
                     [&] { QVERIFY(workbench.setPost("heidenhain-itnc530", "mas-mcvl1000-nikken-guaranteed")); });
        QCOMPARE(workbench.job().machineId, std::string("mas-mcvl1000-nikken-guaranteed"));
        messages.clear();
        andWaitForNc(workbench, [&] { QVERIFY(workbench.setPost("sinumerik828d-emco")); });
        QVERIFY(workbench.job().machineId.empty());
        QVERIFY2(messages.filter(QStringLiteral("does not drive machine mas-mcvl1000-nikken-guaranteed")).size() == 1,
                 qPrintable(messages.join('\n')));
        QVERIFY2(workbench.isProgramCurrent(), qPrintable(workbench.programProblem()));
        // An unknown post changes nothing and says why.
        const std::size_t steps = workbench.document().undoStack().count();
        QVERIFY(!workbench.setPost("no-such-post"));
        QCOMPARE(workbench.document().undoStack().count(), steps);
        QVERIFY(!messages.filter(QStringLiteral("no-such-post")).isEmpty());
    }
};

int main(int argc, char** argv)
{
    // A fixed date in the program header: undo must give the same program byte for byte.
    qputenv("SOURCE_DATE_EPOCH", "1767225600");
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    PostPropertiesTest test;
    run.run(&test);
    return run.finish();
}

#include "PostPropertiesTest.moc"
