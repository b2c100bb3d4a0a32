// The groove roughing task panel (turning, seed-001): the groove as the thesis gives it, each field
// with its R name beside its own (what a turner who knows the published program looks for), the
// insert width read from the chosen grooving tool (R9), the strategy's step factor, infeed and
// safety distance, and the cutting data of the Kod 5 frame (G96 S, LIMS, G95 F, M8).
// The ranges only keep the numbers finite: the operation checks every value and its message shows
// in the panel's status (the spin boxes would otherwise silently clamp a wrong value).
#include "gui/shell/Preferences.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/detail/KindPanels.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLineEdit>

namespace camwb::gui {

namespace {

constexpr double kLengthLimitMm = 10000;

class GroovePanel : public OperationPanel {
    // No Q_OBJECT in a .cpp-local class: tr() needs its own context to match what lupdate records.
    Q_DECLARE_TR_FUNCTIONS(camwb::gui::GroovePanel)

public:
    explicit GroovePanel(const OperationPanelArgs& args) : OperationPanel(args) {}

protected:
    int geometryKinds() const override { return 0; }  // the groove is given by its numbers
    bool takesWorkingPlane() const override { return false; }
    bool takesHeights() const override { return false; }  // XZ plane: the safety distance instead

    void buildParameters(ParamForm& form) override
    {
        auto& p = std::get<ops::GrooveParams>(m_op.params);
        sim::GrooveParameters& g = p.groove;
        const QString deg = tr(" °");
        auto length = [&](const QString& label, const char* name, double& field, double min = 0) {
            return form.length(label, name, field, min, kLengthLimitMm);
        };
        length(tr("Start point X, radius (R0)"), "r0Box", g.r0, -kLengthLimitMm)
            ->setToolTip(tr("Where the right flank meets the surface (P): its radius"));
        length(tr("Start point Z (R1)"), "r1Box", g.r1, -kLengthLimitMm)
            ->setToolTip(tr("Where the right flank meets the surface (P): along the spindle"));
        form.number(tr("Cone angle (R2)"), "r2Box", g.r2, -89.9, 89.9, deg)
            ->setToolTip(tr("Angle of the shaft's surface to the Z axis, rising to the right; 0 for a cylinder"));
        length(tr("Depth (R3)"), "r3Box", g.r3)->setToolTip(tr("Radial depth of the groove below P"));
        length(tr("Bottom width (R4)"), "r4Box", g.r4);
        form.number(tr("Right flank angle (R5)"), "r5Box", g.r5, -89.9, 89.9, deg)
            ->setToolTip(tr("From the radial direction; 0 for a square flank"));
        form.number(tr("Left flank angle (R6)"), "r6Box", g.r6, -89.9, 89.9, deg)
            ->setToolTip(tr("From the radial direction; 0 for a square flank"));
        length(tr("Bottom allowance (R7)"), "r7Box", g.r7)->setToolTip(tr("Left on the bottom, in X"));
        length(tr("Flank allowance (R8)"), "r8Box", g.r8)->setToolTip(tr("Left on the flanks, normal to them"));

        m_width = new QLineEdit;
        m_width->setObjectName(QStringLiteral("insertWidthEdit"));
        m_width->setReadOnly(true);
        m_width->setToolTip(tr("The chosen grooving tool's width (its diameter field)"));
        form.row(tr("Insert width (R9)"), m_width);
        showInsertWidth();

        form.number(tr("Step factor (R10)"), "stepFactorBox", p.stepFactor, 0, 2, QString(), 3)
            ->setToolTip(tr("Axial step between plunges as a share of the insert width (0 < f ≤ 1)"));
        length(tr("Infeed (R11)"), "infeedBox", p.infeedMm)
            ->setToolTip(tr("Each plunge goes this much deeper than the one before"));
        length(tr("Safety distance (R30)"), "safetyBox", p.safetyMm)
            ->setToolTip(tr("Clearance of every retract over the material"));
        length(tr("Final retract"), "finalRetractBox", p.finalRetractMm)
            ->setToolTip(tr("The last rapid goes to X = R0 + this (the thesis' R0 + 100)"));

        form.number(tr("Surface speed (G96)"), "surfaceSpeedBox", p.surfaceSpeedMPerMin, 0, 10000, tr(" m/min"), 1);
        form.number(tr("Spindle limit (LIMS)"), "maxRpmBox", p.maxRpm, 0, 100000, tr(" rpm"), 0);
        form.number(tr("Feed (G95)"), "feedBox", p.feedMmPerRev, 0, 100, tr(" mm/rev"), 3);
        form.flag(tr("Coolant (M8)"), "coolantCheck", p.coolant);
    }

    void toolChanged() override { showInsertWidth(); }

private:
    void showInsertWidth()
    {
        const ops::ToolController* tc = selectedTool();
        if (tc == nullptr)
            m_width->setText(tr("no tool"));
        else if (tc->tool.kind != "groove")
            m_width->setText(tr("not a grooving tool (%1)").arg(QString::fromStdString(tc->tool.kind)));
        else
            m_width->setText(formatLength(tc->tool.diameterMm));
    }

    QLineEdit* m_width = nullptr;
};

}  // namespace

OperationPanel* makeGroovePanel(const OperationPanelArgs& args) { return new GroovePanel(args); }

}  // namespace camwb::gui
