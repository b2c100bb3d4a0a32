// Bridge between Qt6's QOpenGLWidget and VTK's vtkGenericOpenGLRenderWindow, because Debian's
// VTK Qt module is built for Qt5. VTK renders only inside paintGL, into its own framebuffer,
// which is then blitted into the widget's framebuffer; mouse input drives a trackball camera.
// Private to gui/view3d: no VTK header here, only forward declarations.
#pragma once

#include <QOpenGLWidget>
#include <QSurfaceFormat>

#include <memory>

class vtkGenericOpenGLRenderWindow;

namespace camwb::gui {

class VtkOpenGLWidget : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit VtkOpenGLWidget(QWidget* parent = nullptr);
    ~VtkOpenGLWidget() override;

    // OpenGL 3.2 core, what VTK's OpenGL2 backend needs.
    static QSurfaceFormat vtkSurfaceFormat();

    // Add renderers here. Never call its Render() directly: call update() (or it is a no-op).
    vtkGenericOpenGLRenderWindow* renderWindow() const;

signals:
    // Emitted in paintGL right before VTK renders, e.g. to sync an orientation marker.
    void aboutToRender();

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    struct Private;
    void releaseGraphics();
    void syncSize();
    void forwardMouse(QMouseEvent* event, unsigned long vtkEvent);

    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
