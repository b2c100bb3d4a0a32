// The contour task panel: side, direction, stock, step-downs and radial passes, leads, entry,
// tabs and the output form (tool centre or cutter compensation by the control).
#include "gui/tasks/GeometryList.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/detail/KindPanels.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QSpinBox>

namespace camwb::gui {

namespace {

class ContourPanel : public OperationPanel {
    // No Q_OBJECT in a .cpp-local class: tr() needs its own context to match what lupdate records.
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::ContourPanel)

public:
    explicit ContourPanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return GeometryList::Faces | GeometryList::Edges; }

    void buildParameters(ParamForm& form) override
    {
        using namespace ops;
        auto& p = std::get<ContourParams>(m_op.params);
        form.choice<ContourSide>(tr("Side"), "sideCombo", p.side,
                                 {{tr("Outside"), ContourSide::Outside},
                                  {tr("Inside"), ContourSide::Inside},
                                  {tr("On the contour"), ContourSide::On},
                                  {tr("Left (open chains)"), ContourSide::Left},
                                  {tr("Right (open chains)"), ContourSide::Right}});
        form.flag(tr("Climb milling"), "climbCheck", p.climb);
        form.length(tr("Radial stock"), "radialStockBox", p.radialStockMm, 100);
        form.length(tr("Axial stock"), "axialStockBox", p.axialStockMm, 100);
        form.length(tr("Step-down (0 = one level)"), "stepDownBox", p.stepDownMm);
        form.count(tr("Radial passes"), "radialPassesBox", p.radialPasses, 1, 100);
        form.enableWhen(form.length(tr("Radial stepover"), "radialStepoverBox", p.radialStepoverMm, 100),
                        [&p] { return p.radialPasses > 1; });
        const std::vector<std::pair<QString, LeadKind>> leads{
            {tr("None"), LeadKind::None}, {tr("Arc"), LeadKind::Arc}, {tr("Line"), LeadKind::Line}};
        form.choice<LeadKind>(tr("Lead-in"), "leadInCombo", p.leadIn, leads);
        form.choice<LeadKind>(tr("Lead-out"), "leadOutCombo", p.leadOut, leads);
        form.enableWhen(form.length(tr("Lead radius / length"), "leadRadiusBox", p.leadRadiusMm, 100),
                        [&p] { return p.leadIn != LeadKind::None || p.leadOut != LeadKind::None; });
        form.choice<EntryKind>(
            tr("Entry"), "entryCombo", p.entry,
            {{tr("Plunge"), EntryKind::Plunge}, {tr("Ramp"), EntryKind::Ramp}, {tr("Helix"), EntryKind::Helix}});
        form.enableWhen(form.number(tr("Ramp angle"), "rampAngleBox", p.rampAngleDeg, 0.1, 90, tr(" °"), 1),
                        [&p] { return p.entry == EntryKind::Ramp; });
        form.enableWhen(form.length(tr("Helix diameter (0 = tool)"), "helixDiameterBox", p.helixDiameterMm, 100),
                        [&p] { return p.entry == EntryKind::Helix; });
        form.enableWhen(form.length(tr("Helix pitch"), "helixPitchBox", p.helixPitchMm, 50),
                        [&p] { return p.entry == EntryKind::Helix; });
        form.count(tr("Tabs"), "tabCountBox", p.tabCount, 0, 100);
        form.enableWhen(form.length(tr("Tab width"), "tabWidthBox", p.tabWidthMm, 100),
                        [&p] { return p.tabCount > 0; });
        form.enableWhen(form.length(tr("Tab height"), "tabHeightBox", p.tabHeightMm, 100),
                        [&p] { return p.tabCount > 0; });
        form.choice<CompensationOutput>(tr("Output"), "compensationCombo", p.compensation,
                                        {{tr("Tool centre path"), CompensationOutput::ToolCentre},
                                         {tr("Contour, G41/G42"), CompensationOutput::Control}});
        form.length(tr("Tolerance"), "toleranceBox", p.toleranceMm, 0.0001, 1, 4);
    }
};

}  // namespace

OperationPanel* makeContourPanel(const OperationPanelArgs& args) { return new ContourPanel(args); }

}  // namespace camwb::gui
