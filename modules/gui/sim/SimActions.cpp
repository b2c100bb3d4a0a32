#include "gui/sim/SimActions.h"

#include "gui/actions/ActionRegistry.h"
#include "gui/sim/SimPlayer.h"

#include <QAction>
#include <QCoreApplication>

namespace camwb::gui {

namespace {

// Translation context of the strings below (lupdate reads Q_DECLARE_TR_FUNCTIONS).
class Tr {
    Q_DECLARE_TR_FUNCTIONS(SimulatorActions)
};

}  // namespace

void registerSimulatorActions(ActionRegistry& registry, SimPlayer* player,
                              std::function<std::optional<SimRunRequest>()> request, std::function<int()> line,
                              std::function<void()> importMeasured)
{
    const QString menu = Tr::tr("&Simulate");
    auto add = [&](ActionSpec spec, auto slot) {
        QAction* action = registry.add(spec);
        QObject::connect(action, &QAction::triggered, player, slot);
        return action;
    };
    add({"Cam.Sim.Start", Tr::tr("&Simulate"), menu, QKeySequence(Qt::Key_F6), true, true,
         Tr::tr("Simulate the NC program in the editor: the machine's motion, the stock cut, the analysis")},
        [player, request] {
            if (auto what = request())
                player->start(std::move(*what));
        });
    QAction* play = add({"Cam.Sim.Play", Tr::tr("&Play"), menu, {}, false, true}, [player] { player->play(); });
    QAction* pause = add({"Cam.Sim.Pause", Tr::tr("P&ause"), menu}, [player] { player->pause(); });
    QAction* back = add({"Cam.Sim.StepBack", Tr::tr("Step &Back"), menu, QKeySequence(Qt::SHIFT | Qt::Key_F10)},
                        [player] { player->stepBack(); });
    QAction* step = add({"Cam.Sim.StepForward", Tr::tr("S&tep Block"), menu, QKeySequence(Qt::Key_F10)},
                        [player] { player->stepForward(); });
    QAction* jump = add({"Cam.Sim.JumpToLine",
                         Tr::tr("&Jump to Line"),
                         menu,
                         {},
                         false,
                         false,
                         Tr::tr("Move the playback to the first run of the line given beside the button")},
                        [player, line] { player->jumpToLine(line()); });
    QAction* import = add({"Cam.Sim.ImportMeasured",
                           Tr::tr("&Import Measured Trace…"),
                           menu,
                           {},
                           false,
                           true,
                           Tr::tr("Overlay a trace the control recorded (TNCscope CSV) on the simulated program: "
                                  "nominal and actual paths on the workpiece, the deviation per sample")},
                          [importMeasured] { importMeasured(); });
    QAction* clearMeasured =
        add({"Cam.Sim.ClearMeasured", Tr::tr("C&lear Measured Trace"), menu}, [player] { player->clearMeasured(); });
    auto update = [player, play, pause, back, step, jump, import, clearMeasured] {
        const bool has = player->hasRun();
        play->setEnabled(has && !player->isPlaying());
        pause->setEnabled(has && player->isPlaying());
        for (QAction* action : {back, step, jump, import})
            action->setEnabled(has);
        clearMeasured->setEnabled(player->measured() != nullptr);
    };
    QObject::connect(player, &SimPlayer::measuredChanged, player, update);
    QObject::connect(player, &SimPlayer::ready, player, update);
    QObject::connect(player, &SimPlayer::cleared, player, update);
    QObject::connect(player, &SimPlayer::playingChanged, player, update);
    update();
}

}  // namespace camwb::gui
