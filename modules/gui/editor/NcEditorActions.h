// The CIMCO-like NC tools as registered actions (menu "NC"): Find, Go to Block, Renumber, Remove
// Numbers, Compare, Program Info. One entry point, so the main window adds them with one call and
// tests trigger them by id through the registry.
#pragma once

#include <functional>
#include <memory>

class QWidget;

namespace camwb::kinematics {
struct Machine;
}

namespace camwb::gui {

class ActionRegistry;
class NcEditor;
class Prompter;

// Ids: Cam.Nc.Find, Cam.Nc.GotoBlock, Cam.Nc.Renumber, Cam.Nc.RemoveNumbers, Cam.Nc.Compare,
// Cam.Nc.ProgramInfo. Dialogs open over `dialogParent`; Compare and Program Info are modeless
// children of it (found with findChild<CompareDialog*>() / findChild<ProgramInfoDialog*>()).
// Compare asks `prompter` for the file first and opens with both sides. Renumbering and removing
// numbers are one undo step each in the editor. Results and notes go to the status bar when
// `dialogParent` is a QMainWindow. `machine` answers the machine the program is for (null: none
// known): Program Information's simple estimate assumes its rapid, and its cycle time with
// accelerations plans the motion on its axes' limits.
void registerNcEditorActions(ActionRegistry& registry, NcEditor* editor, QWidget* dialogParent,
                             std::function<Prompter&()> prompter,
                             std::function<std::shared_ptr<const kinematics::Machine>()> machine = {});

}  // namespace camwb::gui
