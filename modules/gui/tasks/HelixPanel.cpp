// The helix (hole milling) task panel: pitch, direction, depths from the holes or the heights,
// radial stock, a finishing circle and the breakthrough of through holes.
#include "gui/tasks/GeometryList.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/detail/KindPanels.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>

namespace camwb::gui {

namespace {

class HelixPanel : public OperationPanel {
    // No Q_OBJECT in a .cpp-local class: tr() needs its own context to match what lupdate records.
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::HelixPanel)

public:
    explicit HelixPanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return GeometryList::Holes | GeometryList::Edges; }  // edges: circles

    void buildParameters(ParamForm& form) override
    {
        auto& p = std::get<ops::HelixParams>(m_op.params);
        form.length(tr("Pitch per turn"), "pitchBox", p.pitchMm, 50);
        form.flag(tr("Climb milling"), "climbCheck", p.climb);
        form.flag(tr("Depths from each hole"), "depthsFromHolesCheck", p.depthsFromHoles,
                  tr("Each hole from its top to its bottom; unchecked: the start and final Z of the heights"));
        form.enableWhen(form.length(tr("Breakthrough"), "breakthroughBox", p.breakthroughMm, 50),
                        [&p] { return p.depthsFromHoles; });
        form.length(tr("Radial stock"), "radialStockBox", p.radialStockMm, 50);
        form.flag(tr("Finishing circle"), "finishingCircleCheck", p.finishingCircle);
        form.length(tr("Tolerance"), "toleranceBox", p.toleranceMm, 0.0001, 1, 4);
    }
};

}  // namespace

OperationPanel* makeHelixPanel(const OperationPanelArgs& args) { return new HelixPanel(args); }

}  // namespace camwb::gui
