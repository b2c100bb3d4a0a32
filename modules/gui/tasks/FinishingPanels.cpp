// The task panels of the 3D finishing passes: waterline (scallop height, step-down limit, the
// slope above which it cuts, stock, direction) and parallel (stepover, angle, the slope below
// which it cuts, stock, zig-zag). Faces bound the area; none: the whole model.
#include "gui/tasks/GeometryList.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/detail/KindPanels.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>

namespace camwb::gui {

namespace {

class WaterlinePanel : public OperationPanel {
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::WaterlinePanel)

public:
    explicit WaterlinePanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return GeometryList::Faces; }
    bool takesWorkingPlane() const override { return false; }

    void buildParameters(ParamForm& form) override
    {
        auto& p = std::get<ops::WaterlineParams>(m_op.params);
        form.length(tr("Scallop height"), "scallopBox", p.scallopMm, 0.0001, 5, 4)
            ->setToolTip(tr("The highest ridge left between two contours; sets the step-down"));
        form.length(tr("Maximum step-down"), "maxStepDownBox", p.maxStepDownMm, 50);
        form.number(tr("Steeper than"), "minSlopeBox", p.minSlopeDeg, 0, 90, tr(" °"), 1)
            ->setToolTip(tr("Contours only where the model is steeper than this; parallel finishing takes the rest"));
        form.length(tr("Stock to leave"), "stockBox", p.stockMm, 50);
        form.flag(tr("Climb milling"), "climbCheck", p.climb);
        form.length(tr("Tolerance"), "toleranceBox", p.toleranceMm, 0.0001, 1, 4);
    }
};

class ParallelPanel : public OperationPanel {
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::ParallelPanel)

public:
    explicit ParallelPanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return GeometryList::Faces; }
    bool takesWorkingPlane() const override { return false; }

    void buildParameters(ParamForm& form) override
    {
        auto& p = std::get<ops::ParallelParams>(m_op.params);
        form.length(tr("Stepover"), "stepoverBox", p.stepoverMm, 50);
        form.number(tr("Angle"), "angleBox", p.angleDeg, -180, 180, tr(" °"), 1)
            ->setToolTip(tr("Of the lines to the X axis"));
        form.number(tr("Up to slope"), "maxSlopeBox", p.maxSlopeDeg, 0, 90, tr(" °"), 1)
            ->setToolTip(tr("Lines only where the model is at most this steep; waterline takes the steeper walls"));
        form.length(tr("Stock to leave"), "stockBox", p.stockMm, 50);
        form.flag(tr("Zig-zag"), "zigZagCheck", p.zigZag, tr("Cut both ways; unticked, every line the same way"));
        form.length(tr("Tolerance"), "toleranceBox", p.toleranceMm, 0.0001, 1, 4);
    }
};

}  // namespace

OperationPanel* makeWaterlinePanel(const OperationPanelArgs& args) { return new WaterlinePanel(args); }
OperationPanel* makeParallelPanel(const OperationPanelArgs& args) { return new ParallelPanel(args); }

}  // namespace camwb::gui
