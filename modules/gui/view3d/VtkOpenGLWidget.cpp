#include "gui/view3d/VtkOpenGLWidget.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLState.h>

namespace camwb::gui {

struct VtkOpenGLWidget::Private {
    vtkNew<vtkGenericOpenGLRenderWindow> renderWindow;
    vtkNew<vtkGenericRenderWindowInteractor> interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    vtkNew<vtkCallbackCommand> windowCallback;
    vtkNew<vtkCallbackCommand> renderRequestCallback;
    QMetaObject::Connection contextConnection;
    bool graphicsReady = false;
    bool inPaint = false;
    int wheelAccumulator = 0;
    Qt::MouseButtons vtkButtons;  // buttons whose press went to VTK
};

namespace {

// VTK asks its host to make the context current / report whether it is; only the widget's own
// context counts.
void onWindowEvent(vtkObject*, unsigned long eventId, void* clientData, void* callData)
{
    auto* widget = static_cast<VtkOpenGLWidget*>(clientData);
    switch (eventId) {
    case vtkCommand::WindowMakeCurrentEvent:
        // QOpenGLWidget::makeCurrent() also rebinds the widget's FBO, behind the back of VTK's
        // GL state cache (VTK calls MakeCurrent while it creates and binds its own FBOs).
        if (QOpenGLContext::currentContext() != widget->context())
            widget->makeCurrent();
        break;
    case vtkCommand::WindowIsCurrentEvent: {
        QOpenGLContext* current = QOpenGLContext::currentContext();
        *static_cast<bool*>(callData) = current != nullptr && current == widget->context();
        break;
    }
    case vtkCommand::WindowSupportsOpenGLEvent:
        *static_cast<int*>(callData) = widget->context() != nullptr ? 1 : 0;
        break;
    case vtkCommand::WindowIsDirectEvent:
        *static_cast<int*>(callData) = 1;
        break;
    default:
        break;
    }
}

// The interactor's renders are redirected into a repaint; VTK then renders inside paintGL.
void onRenderRequest(vtkObject*, unsigned long, void* clientData, void*)
{
    static_cast<VtkOpenGLWidget*>(clientData)->update();
}

}  // namespace

VtkOpenGLWidget::VtkOpenGLWidget(QWidget* parent) : QOpenGLWidget(parent), d(std::make_unique<Private>())
{
    setFormat(vtkSurfaceFormat());
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(64, 64);

    d->windowCallback->SetClientData(this);
    d->windowCallback->SetCallback(&onWindowEvent);
    for (unsigned long event : {vtkCommand::WindowMakeCurrentEvent, vtkCommand::WindowIsCurrentEvent,
                                vtkCommand::WindowSupportsOpenGLEvent, vtkCommand::WindowIsDirectEvent})
        d->renderWindow->AddObserver(event, d->windowCallback);

    // Nothing renders outside paintGL: there the context and the widget's FBO are ready.
    d->renderWindow->SetReadyForRendering(false);
    d->renderWindow->SetFrameBlitModeToNoBlit();
    // Wide lines in a core profile: let VTK draw them itself instead of glLineWidth.
    d->renderWindow->SetForceMaximumHardwareLineWidth(1);
    d->renderWindow->SetMultiSamples(4);

    d->renderRequestCallback->SetClientData(this);
    d->renderRequestCallback->SetCallback(&onRenderRequest);
    d->interactor->SetRenderWindow(d->renderWindow);
    d->interactor->SetInteractorStyle(d->style);
    d->interactor->EnableRenderOff();
    d->interactor->AddObserver(vtkCommand::RenderEvent, d->renderRequestCallback);
    d->interactor->Initialize();
}

VtkOpenGLWidget::~VtkOpenGLWidget()
{
    disconnect(d->contextConnection);
    releaseGraphics();
}

QSurfaceFormat VtkOpenGLWidget::vtkSurfaceFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 2);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setRedBufferSize(8);
    format.setGreenBufferSize(8);
    format.setBlueBufferSize(8);
    format.setAlphaBufferSize(8);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(0);
    format.setSamples(0);  // VTK multisamples its own framebuffer
    format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
    return format;
}

vtkGenericOpenGLRenderWindow* VtkOpenGLWidget::renderWindow() const { return d->renderWindow; }

void VtkOpenGLWidget::initializeGL()
{
    // A reparented QOpenGLWidget (docking) gets a new context: release first, then re-init.
    disconnect(d->contextConnection);
    d->contextConnection = connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] { releaseGraphics(); });

    syncSize();  // VTK sizes its framebuffers on initialisation
    d->renderWindow->SetOwnContext(false);
    d->renderWindow->SetMapped(true);
    d->graphicsReady = d->renderWindow->InitializeFromCurrentContext();
}

void VtkOpenGLWidget::releaseGraphics()
{
    if (!d->graphicsReady)
        return;
    d->graphicsReady = false;
    if (context() == nullptr)
        return;
    makeCurrent();
    d->renderWindow->Finalize();
    doneCurrent();
}

void VtkOpenGLWidget::syncSize()
{
    const qreal dpr = devicePixelRatioF();
    const int w = std::max(1, qRound(width() * dpr));
    const int h = std::max(1, qRound(height() * dpr));
    d->interactor->UpdateSize(w, h);
    const int* size = d->renderWindow->GetSize();
    if (size[0] != w || size[1] != h)
        d->renderWindow->SetSize(w, h);
    d->renderWindow->SetDPI(qRound(72 * dpr));
}

void VtkOpenGLWidget::resizeGL(int, int) { syncSize(); }

void VtkOpenGLWidget::paintGL()
{
    QOpenGLExtraFunctions* f = context()->extraFunctions();
    if (!d->graphicsReady || d->inPaint) {
        f->glClearColor(0.f, 0.f, 0.f, 1.f);
        f->glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    d->inPaint = true;
    syncSize();  // the device pixel ratio may have changed without a resize
    emit aboutToRender();

    d->renderWindow->SetReadyForRendering(true);
    d->renderWindow->Render();  // saves and restores the GL state VTK touches

    // Rendering may have switched contexts (e.g. a progress update painting elsewhere).
    makeCurrent();
    const int* size = d->renderWindow->GetSize();
    f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    f->glDrawBuffers(1, &drawBuffer);
    const bool scissor = f->glIsEnabled(GL_SCISSOR_TEST);
    if (scissor) {
        d->renderWindow->GetState()->vtkglDisable(GL_SCISSOR_TEST);
        f->glDisable(GL_SCISSOR_TEST);
    }
    d->renderWindow->BlitDisplayFramebuffer(0, 0, 0, size[0], size[1], 0, 0, size[0], size[1], GL_COLOR_BUFFER_BIT,
                                            GL_NEAREST);

    // Opaque alpha, or the compositor blends the view with what lies behind the window (Mesa).
    GLboolean mask[4];
    f->glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    GLfloat clear[4];
    f->glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    f->glClearColor(0.f, 0.f, 0.f, 1.f);
    f->glClear(GL_COLOR_BUFFER_BIT);
    f->glColorMask(mask[0], mask[1], mask[2], mask[3]);
    f->glClearColor(clear[0], clear[1], clear[2], clear[3]);
    if (scissor) {
        d->renderWindow->GetState()->vtkglEnable(GL_SCISSOR_TEST);
        f->glEnable(GL_SCISSOR_TEST);
    }
    d->inPaint = false;
}

void VtkOpenGLWidget::forwardMouse(QMouseEvent* event, unsigned long vtkEvent)
{
    const qreal dpr = devicePixelRatioF();
    const QPointF p = event->position() * dpr;
    const Qt::KeyboardModifiers mods = event->modifiers();
    const int repeat = event->type() == QEvent::MouseButtonDblClick ? 1 : 0;
    d->interactor->SetEventInformationFlipY(qRound(p.x()), qRound(p.y()), (mods & Qt::ControlModifier) ? 1 : 0,
                                            (mods & Qt::ShiftModifier) ? 1 : 0, 0, repeat);
    d->interactor->SetAltKey((mods & Qt::AltModifier) ? 1 : 0);
    d->interactor->InvokeEvent(vtkEvent, event);
}

void VtkOpenGLWidget::mousePressEvent(QMouseEvent* event)
{
    switch (event->button()) {
    case Qt::LeftButton:
        forwardMouse(event, vtkCommand::LeftButtonPressEvent);
        break;
    case Qt::MiddleButton:
        forwardMouse(event, vtkCommand::MiddleButtonPressEvent);
        break;
    case Qt::RightButton:
        forwardMouse(event, vtkCommand::RightButtonPressEvent);
        break;
    default:
        event->ignore();
        return;
    }
    d->vtkButtons |= event->button();
    event->accept();
}

void VtkOpenGLWidget::mouseReleaseEvent(QMouseEvent* event)
{
    if (!(d->vtkButtons & event->button())) {
        event->ignore();
        return;
    }
    d->vtkButtons &= ~event->button();
    switch (event->button()) {
    case Qt::LeftButton:
        forwardMouse(event, vtkCommand::LeftButtonReleaseEvent);
        break;
    case Qt::MiddleButton:
        forwardMouse(event, vtkCommand::MiddleButtonReleaseEvent);
        break;
    case Qt::RightButton:
        forwardMouse(event, vtkCommand::RightButtonReleaseEvent);
        break;
    default:
        break;
    }
    event->accept();
}

void VtkOpenGLWidget::mouseMoveEvent(QMouseEvent* event)
{
    forwardMouse(event, vtkCommand::MouseMoveEvent);
    event->accept();
}

void VtkOpenGLWidget::wheelEvent(QWheelEvent* event)
{
    // Touchpads send small deltas; VTK zooms one step per notch (120 units).
    d->wheelAccumulator += event->angleDelta().y();
    const qreal dpr = devicePixelRatioF();
    const QPointF p = event->position() * dpr;
    const Qt::KeyboardModifiers mods = event->modifiers();
    d->interactor->SetEventInformationFlipY(qRound(p.x()), qRound(p.y()), (mods & Qt::ControlModifier) ? 1 : 0,
                                            (mods & Qt::ShiftModifier) ? 1 : 0);
    while (d->wheelAccumulator >= 120) {
        d->wheelAccumulator -= 120;
        d->interactor->InvokeEvent(vtkCommand::MouseWheelForwardEvent, event);
    }
    while (d->wheelAccumulator <= -120) {
        d->wheelAccumulator += 120;
        d->interactor->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, event);
    }
    event->accept();
}

}  // namespace camwb::gui
