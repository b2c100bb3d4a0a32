// The 3D view: the model (shaded, with feature edges) and the toolpath backplot, drawn by VTK in
// a Qt6 QOpenGLWidget. Without OpenGL (offscreen platform, CAMWB_NO_OPENGL=1) it shows a message
// instead and keeps working as a data holder, so headless tests and remote sessions never crash.
// The backplot links back to its records: every segment knows the record that made it, a click
// picks the nearest segment (signal with the record index), records can be highlighted and tools
// hidden — what the NC inspector needs to link the editor and the 3D view both ways.
#pragma once

#include "base/Vec.h"
#include "kinematics/KinematicChain.h"
#include "sim/TriangleMesh.h"
#include "sim/TurningStock.h"

#include <QImage>
#include <QPointF>
#include <QString>
#include <QWidget>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace camwb::occ {
struct DisplayMesh;
}
namespace camwb::toolpath {
class Toolpath;
class ToolpathPolylines;
}  // namespace camwb::toolpath

namespace camwb::gui {

class SimOverlay;
class TaskOverlay;
class ToolpathScene;

// A lathe job's half-section in the XZ plane (Vec2::x is Z, Vec2::y is X as a radius, as
// sim::TurningRegion has them): the stock before cutting, filled and translucent, and the part's
// contours and the contours with the finishing allowances as open lines (one per groove).
struct LatheSection {
    sim::TurningRegion stock;
    std::vector<std::vector<base::Vec2>> contours;
    std::vector<std::vector<base::Vec2>> offsetContours;
};

class View3D : public QWidget {
    Q_OBJECT

public:
    // LatheXZ: the lathe drawing's view, looking along -Y with Z to the right and X up.
    enum class Preset { Isometric, Top, Front, Right, LatheXZ };

    explicit View3D(QWidget* parent = nullptr);
    ~View3D() override;

    // Makes OpenGL 3.2 core (what VTK needs) the application's default surface format. Call it
    // before constructing QApplication so every context Qt creates can share with the view's.
    static void setDefaultSurfaceFormat();

    // Whether an OpenGL 3.2 core context can be made here: false on the offscreen/minimal QPA
    // platforms, with CAMWB_NO_OPENGL=1, or when no such context can be created and made current
    // on a QOffscreenSurface. `reason` says why.
    static bool openGlAvailable(QString* reason = nullptr);
    // False -> the widget shows the label "3D view unavailable: <reason>" (objectName
    // "noOpenGlMessage"); every other call still works (keeps data, draws nothing).
    bool hasOpenGl() const;

    void setModel(const occ::DisplayMesh& mesh);           // shaded (light grey) + feature edges
    void setToolpath(const toolpath::Toolpath& toolpath);  // rapid red, feed green, arc/helix blue
    // Builds the backplot data of `toolpath` without touching the view: safe on a worker thread,
    // so a huge program never blocks the GUI. Show it with setPreparedToolpath(). Records flagged
    // in `recordsInError` (nc::recordsInError) are drawn as magenta dashes from start to end.
    static std::shared_ptr<const ToolpathScene> prepareToolpath(const toolpath::Toolpath& toolpath,
                                                                const std::vector<bool>& recordsInError = {});
    void setPreparedToolpath(std::shared_ptr<const ToolpathScene> scene);
    void clearModel();
    void clearToolpath();
    // Hides the backplot (kept, pickable state unchanged) while false: a turning task panel's
    // preview is drawn in the backplot's colours and takes its place.
    void setToolpathShown(bool shown);
    bool isToolpathShown() const;
    // The job's stock, translucent (a box, a cylinder along Z inside `stock`, or `blank`'s solid
    // when given), and the work coordinate system's axes at the origin: the view shows work
    // coordinates. No stock: only the axes. Replaces what was shown.
    void setJobSetup(const std::optional<base::Box3>& stock, bool cylinder,
                     std::shared_ptr<const sim::TriangleMesh> blank = {});
    bool hasStockActor() const;
    // A turning job's half-section at Y = 0 (the CL's plane), instead of a milling stock; nullopt
    // removes it. Replaces what was shown.
    void setLatheSection(const std::optional<LatheSection>& section);
    bool hasLatheSection() const;
    bool hasWorkAxes() const;
    bool hasModelActor() const;
    bool hasToolpathActor() const;
    int toolpathSegmentCount() const;  // line segments in the toolpath polydata (rapid + cutting)
    // The segments shown (record index and tool of each), or nullptr without a toolpath.
    const toolpath::ToolpathPolylines* toolpathPolylines() const;

    // Tools of the backplot in order of first use (0 = moves before any tool change).
    std::vector<int> toolpathTools() const;
    void setToolVisible(int tool, bool visible);
    bool isToolVisible(int tool) const;
    int visibleSegmentCount() const;

    // Draws the segments of these records on top, thick and yellow; empty clears.
    void setHighlightedRecords(const std::vector<std::size_t>& records);
    const std::vector<std::uint32_t>& highlightedSegments() const;

    // Nearest visible segment within `tolerancePx` of a widget position, or -1. Needs OpenGL.
    int pickSegment(const QPointF& widgetPosition, double tolerancePx = 6.0) const;
    // Where a world point appears in the widget (logical pixels), nullopt behind the camera.
    std::optional<QPointF> projectToWidget(const base::Vec3& point) const;

    // The task panels' layer: the live preview of an operation and the faces picked for it. A
    // click on the model that picks no segment selects its face there (Ctrl: adds/removes).
    TaskOverlay& overlay() const;
    // The simulator's layer: tool, travelled path, cut stock, analysis colours (gui/sim).
    SimOverlay& simulation() const;
    // While the simulator shows its stock, the model and the backplot are hidden (the stock would
    // fight the model's surface where it is cut to size); picking segments works all the same.
    void setSimulationShown(bool shown);
    bool isSimulationShown() const;
    // The simulator's machine frame: the model, the job's stock and axes, the backplot and the
    // simulator's workpiece side (SimOverlay::setWorkpieceMotion) drawn moved by `motion`, and
    // segment picking through it; the identity puts them back in work coordinates.
    void setWorkpieceMotion(const kinematics::RigidMotion& motion);

    // The model face (1-based) under a widget position, 0 for none; `point` (when given) gets
    // where the click meets the model's surface (work coordinates). Needs OpenGL.
    int pickFace(const QPointF& widgetPosition, base::Vec3* point = nullptr) const;

    void setViewPreset(Preset preset);  // also fits everything into the view
    Preset viewPreset() const;          // the last preset chosen (the camera may have moved since)
    void fitAll();

    // What the view shows (rendered now), or a null image without OpenGL.
    QImage grabImage();

signals:
    // A left click (without dragging) near a segment: the segment and the record that made it.
    void segmentPicked(int segment, int record);
    // VTK has just drawn a frame (the simulator counts them for its frame rate).
    void frameRendered();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Private;
    void showScene();
    void applyVisibility();
    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
