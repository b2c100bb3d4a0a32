// The drilling task panel: cycle (simple, dwell, peck, chip-breaking) with its peck or dwell,
// depths from the holes or the heights, retract plane between holes, hole order, point angle
// and breakthrough.
#include "gui/tasks/GeometryList.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/detail/KindPanels.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>

namespace camwb::gui {

namespace {

class DrillPanel : public OperationPanel {
    // No Q_OBJECT in a .cpp-local class: tr() needs its own context to match what lupdate records.
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::DrillPanel)

public:
    explicit DrillPanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return GeometryList::Holes; }

    void buildParameters(ParamForm& form) override
    {
        using toolpath::CycleKind;
        auto& p = std::get<ops::DrillParams>(m_op.params);
        form.choice<CycleKind>(tr("Cycle"), "cycleCombo", p.cycle,
                               {{tr("Drill"), CycleKind::Drill},
                                {tr("Drill with dwell"), CycleKind::DrillDwell},
                                {tr("Peck (full retract)"), CycleKind::Peck},
                                {tr("Chip breaking"), CycleKind::ChipBreak}});
        form.enableWhen(form.length(tr("Peck depth"), "peckBox", p.peckMm, 100),
                        [&p] { return p.cycle == CycleKind::Peck || p.cycle == CycleKind::ChipBreak; });
        form.enableWhen(form.number(tr("Dwell"), "dwellBox", p.dwellSeconds, 0, 60, tr(" s"), 2),
                        [&p] { return p.cycle == CycleKind::DrillDwell; });
        form.flag(tr("Depths from each hole"), "depthsFromHolesCheck", p.depthsFromHoles,
                  tr("Each hole from its top to its bottom; unchecked: the start and final Z of the heights"));
        form.flag(tr("Retract to clearance (G98)"), "retractToClearanceCheck", p.retractToClearance,
                  tr("Between holes; unchecked: to the safe plane (R, G99)"));
        form.flag(tr("Keep the listed order"), "keepOrderCheck", p.keepOrder,
                  tr("Unchecked: the order that shortens the rapids"));
        form.flag(
            tr("Depth at full diameter"), "depthAtShoulderCheck", p.depthAtShoulder,
            tr("The final depth is where the drill has its full diameter: the tip goes deeper by the point length"));
        form.length(tr("Breakthrough"), "breakthroughBox", p.breakthroughMm, 50);
    }
};

}  // namespace

OperationPanel* makeDrillPanel(const OperationPanelArgs& args) { return new DrillPanel(args); }

}  // namespace camwb::gui
