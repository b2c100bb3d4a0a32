// The swarf task panel: the one ruled face (and optionally its drive edge) from the geometry list,
// climb, axial offset, radial stock and passes, and the chord, angle and gouge tolerances. The
// tool axis follows the face, so the working plane box is hidden.
#include "gui/tasks/GeometryList.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/detail/KindPanels.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>

namespace camwb::gui {

namespace {

class SwarfPanel : public OperationPanel {
    // No Q_OBJECT in a .cpp-local class: tr() needs its own context to match what lupdate records.
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::SwarfPanel)

public:
    explicit SwarfPanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return GeometryList::Faces | GeometryList::Edges; }  // edge: the drive
    bool takesWorkingPlane() const override { return false; }

    void buildParameters(ParamForm& form) override
    {
        auto& p = std::get<ops::SwarfParams>(m_op.params);
        form.flag(tr("Climb milling"), "climbCheck", p.climb);
        form.length(tr("Axial offset"), "axialOffsetBox", p.axialOffsetMm, -50, 50, 3)
            ->setToolTip(tr("The tool tip above (+) or below (−) the face's bottom edge, along the tool axis"));
        form.length(tr("Radial stock"), "radialStockBox", p.radialStockMm, 50);
        form.count(tr("Radial passes"), "radialPassesBox", p.radialPasses, 1, 100);
        form.enableWhen(form.length(tr("Radial stepover"), "radialStepoverBox", p.radialStepoverMm, 50),
                        [&p] { return p.radialPasses > 1; });
        form.length(tr("Chord tolerance"), "chordToleranceBox", p.chordToleranceMm, 0.0001, 1, 4);
        form.number(tr("Angle tolerance"), "angleToleranceBox", p.angleToleranceDeg, 0.01, 45, QStringLiteral(" °"), 2)
            ->setToolTip(tr("The most the tool axis turns from one point to the next"));
        form.length(tr("Gouge tolerance"), "gougeToleranceBox", p.gougeToleranceMm, 0.0001, 1, 4)
            ->setToolTip(tr("How deep the tool may enter the model before the operation fails"));
    }
};

}  // namespace

OperationPanel* makeSwarfPanel(const OperationPanelArgs& args) { return new SwarfPanel(args); }

}  // namespace camwb::gui
