#include "gui/sim/SimActions.h"

#include "gui/actions/ActionRegistry.h"
#include "gui/sim/SimPlayer.h"
#include "kinematics/Machine.h"

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
    QAction* machineFrame = registry.add({"Cam.Sim.MachineFrame", Tr::tr("&Machine Frame"), menu, {}, false, true});
    machineFrame->setCheckable(true);
    QObject::connect(machineFrame, &QAction::toggled, player, [player](bool on) { player->setMachineFrame(on); });
    QObject::connect(player, &SimPlayer::machineFrameChanged, machineFrame, &QAction::setChecked);
    auto updateFrame = [player, machineFrame] {
        const MachineFrameSupport support = player->machineFrameSupport();
        machineFrame->setEnabled(support == MachineFrameSupport::Available);
        switch (support) {
        case MachineFrameSupport::Available:
            machineFrame->setToolTip(Tr::tr("Show the scene as the machine sees it: the tool along the spindle, the "
                                            "stock, the model, the path and the rotary table turned by the table's "
                                            "axes (a head's axes tilt the tool)"));
            break;
        case MachineFrameSupport::NoRun:
            machineFrame->setToolTip(Tr::tr("Machine frame: simulate a five-axis program first"));
            break;
        case MachineFrameSupport::NoMachine:
            machineFrame->setToolTip(Tr::tr("Machine frame: no machine is chosen for this program, so no kinematic "
                                            "chain says what the table turns (choose a five-axis machine in the NC "
                                            "inspector)"));
            break;
        case MachineFrameSupport::NoChain:
            machineFrame->setToolTip(
                Tr::tr("Machine frame: the machine %1 has no five-axis kinematic chain in its file, so nothing says "
                       "what its table turns")
                    .arg(QString::fromStdString(player->run()->machine->id)));
            break;
        }
    };
    // A run the machine frame cannot show turns it off (a disabled button shown pressed would say
    // it is on); clearing before the next run does not, so a five-axis run simulated again keeps it.
    QObject::connect(player, &SimPlayer::ready, player, [player, updateFrame] {
        if (player->machineFrameSupport() != MachineFrameSupport::Available)
            player->setMachineFrame(false);
        updateFrame();
    });
    QObject::connect(player, &SimPlayer::cleared, player, updateFrame);
    updateFrame();
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
