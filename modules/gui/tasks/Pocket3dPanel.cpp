// The 3D pocket task panel: the faces that bound the area (none: the whole model within the
// stock), pattern, stepover, step-down, stock on the sides and the bottom, rest machining, direction
// and entry.
#include "gui/tasks/GeometryList.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/detail/KindPanels.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>

namespace camwb::gui {

namespace {

class Pocket3dPanel : public OperationPanel {
    // No Q_OBJECT in a .cpp-local class: tr() needs its own context to match what lupdate records.
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::Pocket3dPanel)

public:
    explicit Pocket3dPanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return GeometryList::Faces; }
    bool takesWorkingPlane() const override { return false; }

    void buildParameters(ParamForm& form) override
    {
        using namespace ops;
        auto& p = std::get<Pocket3dParams>(m_op.params);
        form.choice<PocketPattern>(
            tr("Pattern"), "patternCombo", p.pattern,
            {{tr("Offset (spiral inward)"), PocketPattern::Offset}, {tr("Zig-zag"), PocketPattern::ZigZag}});
        form.enableWhen(form.number(tr("Zig-zag angle"), "zigZagAngleBox", p.zigZagAngleDeg, -180, 180, tr(" °"), 1),
                        [&p] { return p.pattern == PocketPattern::ZigZag; });
        form.enableWhen(form.number(tr("Stepover"), "stepoverPercentBox", p.stepoverPercent, 1, 100, tr(" % of Ø"), 1),
                        [&p] { return p.stepoverMm <= 0; });
        form.length(tr("Stepover (mm, 0 = use %)"), "stepoverMmBox", p.stepoverMm, 100);
        form.length(tr("Step-down"), "stepDownBox", p.stepDownMm)
            ->setToolTip(tr("Levels also land on every flat floor of the model"));
        form.length(tr("Side stock"), "sideStockBox", p.sideStockMm, 100)
            ->setToolTip(tr("Left on walls, measured across the tool axis"));
        form.length(tr("Bottom stock"), "bottomStockBox", p.bottomStockMm, 100)
            ->setToolTip(tr("Left on floors and shallow surfaces, measured along the tool axis"));
        form.flag(tr("Rest machining"), "restMachiningCheck", p.restMachining,
                  tr("Cut only the material the operations before this one left"));
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

OperationPanel* makePocket3dPanel(const OperationPanelArgs& args) { return new Pocket3dPanel(args); }

}  // namespace camwb::gui
