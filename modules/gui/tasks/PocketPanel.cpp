// The pocket task panel: pattern (offset or zig-zag), stepover, step-down, stock on walls and
// floor, finishing passes, direction and entry (helix, ramp, plunge).
#include "gui/tasks/GeometryList.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/detail/KindPanels.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>

namespace camwb::gui {

namespace {

class PocketPanel : public OperationPanel {
    // No Q_OBJECT in a .cpp-local class: tr() needs its own context to match what lupdate records.
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::PocketPanel)

public:
    explicit PocketPanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return GeometryList::Faces; }

    void buildParameters(ParamForm& form) override
    {
        using namespace ops;
        auto& p = std::get<PocketParams>(m_op.params);
        form.choice<PocketPattern>(
            tr("Pattern"), "patternCombo", p.pattern,
            {{tr("Offset (spiral inward)"), PocketPattern::Offset}, {tr("Zig-zag"), PocketPattern::ZigZag}});
        form.enableWhen(form.number(tr("Zig-zag angle"), "zigZagAngleBox", p.zigZagAngleDeg, -180, 180, tr(" °"), 1),
                        [&p] { return p.pattern == PocketPattern::ZigZag; });
        form.enableWhen(form.number(tr("Stepover"), "stepoverPercentBox", p.stepoverPercent, 1, 100, tr(" % of Ø"), 1),
                        [&p] { return p.stepoverMm <= 0; });
        form.length(tr("Stepover (mm, 0 = use %)"), "stepoverMmBox", p.stepoverMm, 100);
        form.length(tr("Step-down (0 = one level)"), "stepDownBox", p.stepDownMm);
        form.length(tr("Wall stock"), "wallStockBox", p.wallStockMm, 100);
        form.length(tr("Floor stock"), "floorStockBox", p.floorStockMm, 100);
        form.flag(tr("Finish walls"), "finishWallsCheck", p.finishWalls);
        form.flag(tr("Finish floor"), "finishFloorCheck", p.finishFloor);
        form.flag(tr("Climb milling"), "climbCheck", p.climb);
        form.choice<EntryKind>(
            tr("Entry"), "entryCombo", p.entry,
            {{tr("Helix"), EntryKind::Helix}, {tr("Ramp"), EntryKind::Ramp}, {tr("Plunge"), EntryKind::Plunge}});
        form.enableWhen(form.length(tr("Helix diameter (0 = 90 % Ø)"), "helixDiameterBox", p.helixDiameterMm, 100),
                        [&p] { return p.entry == EntryKind::Helix; });
        form.enableWhen(form.length(tr("Helix pitch"), "helixPitchBox", p.helixPitchMm, 50),
                        [&p] { return p.entry == EntryKind::Helix; });
        form.enableWhen(form.number(tr("Ramp angle"), "rampAngleBox", p.rampAngleDeg, 0.1, 90, tr(" °"), 1),
                        [&p] { return p.entry == EntryKind::Ramp; });
        form.length(tr("Tolerance"), "toleranceBox", p.toleranceMm, 0.0001, 1, 4);
    }
};

}  // namespace

OperationPanel* makePocketPanel(const OperationPanelArgs& args) { return new PocketPanel(args); }

}  // namespace camwb::gui
