// The 3D view: the model (shaded, with feature edges) and the toolpath backplot, drawn by VTK in
// a Qt6 QOpenGLWidget. Without OpenGL (offscreen platform, CAMWB_NO_OPENGL=1) it shows a message
// instead and keeps working as a data holder, so headless tests and remote sessions never crash.
#pragma once

#include <QImage>
#include <QString>
#include <QWidget>

#include <memory>

namespace camwb::occ {
struct DisplayMesh;
}
namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::gui {

class View3D : public QWidget {
    Q_OBJECT

public:
    enum class Preset { Isometric, Top, Front, Right };

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
    void setToolpath(const toolpath::Toolpath& toolpath);  // rapid orange, feed blue, arc/helix green
    void clearModel();
    void clearToolpath();
    bool hasModelActor() const;
    bool hasToolpathActor() const;
    int toolpathSegmentCount() const;  // line segments in the toolpath polydata (rapid + cutting)

    void setViewPreset(Preset preset);  // also fits everything into the view
    void fitAll();

    // What the view shows (rendered now), or a null image without OpenGL.
    QImage grabImage();

private:
    struct Private;
    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
