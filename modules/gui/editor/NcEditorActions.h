// The CIMCO-like NC tools as registered actions (menu "NC"): Find, Go to Block, Renumber, Remove
// Numbers, Compare, Program Info. One entry point, so the main window adds them with one call and
// tests trigger them by id through the registry.
#pragma once

#include <functional>

class QWidget;

namespace camwb::gui {

class ActionRegistry;
class NcEditor;
class Prompter;

// Ids: Cam.Nc.Find, Cam.Nc.GotoBlock, Cam.Nc.Renumber, Cam.Nc.RemoveNumbers, Cam.Nc.Compare,
// Cam.Nc.ProgramInfo. Dialogs open over `dialogParent`; Compare and Program Info are modeless
// children of it (found with findChild<CompareDialog*>() / findChild<ProgramInfoDialog*>()).
// Compare asks `prompter` for the file first and opens with both sides. Renumbering and removing
// numbers are one undo step each in the editor. Results and notes go to the status bar when
// `dialogParent` is a QMainWindow. `machineRapid` answers the rapid rate of the machine the
// program is for (0: none known), which Program Information's time estimate then assumes.
void registerNcEditorActions(ActionRegistry& registry, NcEditor* editor, QWidget* dialogParent,
                             std::function<Prompter&()> prompter, std::function<double()> machineRapid = {});

}  // namespace camwb::gui
