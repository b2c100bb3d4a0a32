// The per-kind task panels' factories (one file each), used by OperationPanel::create.
#pragma once

#include "document/Job.h"

#include <optional>

class QWidget;

namespace camwb::gui {

class OperationPanel;
class TaskOverlay;
class Workbench;

struct OperationPanelArgs {
    Workbench& workbench;
    TaskOverlay* overlay;
    int index;
    const document::Operation& operation;
    const std::optional<ops::ToolController>& newTool;
    QWidget* parent;
};

OperationPanel* makeContourPanel(const OperationPanelArgs& args);
OperationPanel* makePocketPanel(const OperationPanelArgs& args);
OperationPanel* makeHelixPanel(const OperationPanelArgs& args);
OperationPanel* makeDrillPanel(const OperationPanelArgs& args);
OperationPanel* makeSwarfPanel(const OperationPanelArgs& args);
OperationPanel* makePocket3dPanel(const OperationPanelArgs& args);
OperationPanel* makeWaterlinePanel(const OperationPanelArgs& args);
OperationPanel* makeParallelPanel(const OperationPanelArgs& args);
OperationPanel* makeGroovePanel(const OperationPanelArgs& args);

}  // namespace camwb::gui
