#include "gui/view3d/View3D.h"

#include "gui/sim/SimOverlay.h"
#include "gui/view3d/TaskOverlay.h"
#include "gui/view3d/VtkOpenGLWidget.h"
#include "gui/view3d/detail/MachineFrameActors.h"
#include "gui/view3d/detail/ModelActors.h"
#include "gui/view3d/detail/SetupActors.h"
#include "gui/view3d/detail/ToolpathScene.h"
#include "occ/DisplayMesh.h"
#include "toolpath/Toolpath.h"
#include "toolpath/ToolpathPolylines.h"

#include <QGuiApplication>
#include <QLabel>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QVBoxLayout>

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkIntArray.h>
#include <vtkLightKit.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace camwb::gui {

namespace {

constexpr double kChordToleranceMm = 0.01;

// A click that moves the mouse less than this (logical pixels) picks instead of rotating.
constexpr double kClickSlopPx = 4.0;

}  // namespace

struct View3D::Private {
    VtkOpenGLWidget* gl = nullptr;
    QLabel* message = nullptr;

    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkRenderer> markerRenderer;
    vtkNew<vtkAxesActor> axes;
    vtkSmartPointer<vtkActor> modelActor;
    TaskOverlay* overlay = nullptr;
    SimOverlay* simulation = nullptr;
    bool simulationShown = false;
    bool toolpathShown = true;
    vtkSmartPointer<vtkActor> edgeActor;
    vtkSmartPointer<vtkActor> stockActor;
    vtkSmartPointer<vtkAxesActor> workAxes;
    std::vector<vtkSmartPointer<vtkActor>> latheActors;
    struct ToolActors {
        int tool = 0;
        vtkSmartPointer<vtkActor> cut;
        vtkSmartPointer<vtkActor> rapid;
    };
    std::shared_ptr<const ToolpathScene> scene;
    std::vector<ToolActors> toolActors;
    std::set<int> hiddenTools;  // kept across new toolpaths of the same program
    vtkSmartPointer<vtkActor> highlightActor;
    std::vector<std::uint32_t> highlighted;
    QPointF pressPosition;
    bool pressed = false;
    Preset preset = Preset::Isometric;
    vtkSmartPointer<vtkMatrix4x4> workpiece;  // the simulator's machine frame; null: work coordinates

    void render()
    {
        if (gl != nullptr)
            gl->update();
    }
    void setupScene();
    void syncMarker();
};

void View3D::Private::setupScene()
{
    renderer->GradientBackgroundOn();
    renderer->SetBackground(0.80, 0.83, 0.88);   // bottom
    renderer->SetBackground2(0.36, 0.42, 0.52);  // top
    renderer->SetUseFXAA(false);
    renderer->RemoveAllLights();
    vtkNew<vtkLightKit> lights;  // key/fill/back lights: faces of a box get distinct shades
    lights->AddLightsToRenderer(renderer);

    axes->SetTotalLength(1.0, 1.0, 1.0);
    axes->SetShaftTypeToCylinder();
    axes->SetCylinderRadius(0.04);
    axes->SetConeRadius(0.5);
    for (vtkCaptionActor2D* caption :
         {axes->GetXAxisCaptionActor2D(), axes->GetYAxisCaptionActor2D(), axes->GetZAxisCaptionActor2D()}) {
        caption->GetCaptionTextProperty()->SetFontSize(14);
        caption->GetCaptionTextProperty()->BoldOn();
        caption->GetCaptionTextProperty()->ItalicOff();
        caption->GetCaptionTextProperty()->ShadowOff();
        caption->GetCaptionTextProperty()->SetColor(0.1, 0.1, 0.1);
        caption->GetTextActor()->SetTextScaleModeToNone();
    }
    markerRenderer->AddActor(axes);
    markerRenderer->SetViewport(0.0, 0.0, 0.2, 0.2);
    markerRenderer->SetLayer(1);
    markerRenderer->InteractiveOff();
    markerRenderer->GetActiveCamera()->SetViewAngle(30.0);
}

// The marker shows the main camera's orientation from a fixed distance around the origin.
void View3D::Private::syncMarker()
{
    vtkCamera* main = renderer->GetActiveCamera();
    double dop[3];
    main->GetDirectionOfProjection(dop);
    vtkCamera* camera = markerRenderer->GetActiveCamera();
    constexpr double kDistance = 5.5;
    camera->SetFocalPoint(0.35, 0.35, 0.35);
    camera->SetPosition(0.35 - dop[0] * kDistance, 0.35 - dop[1] * kDistance, 0.35 - dop[2] * kDistance);
    camera->SetViewUp(main->GetViewUp());
    markerRenderer->ResetCameraClippingRange();
}

View3D::View3D(QWidget* parent) : QWidget(parent), d(std::make_unique<Private>())
{
    d->setupScene();
    d->overlay = new TaskOverlay(
        d->renderer, [this] { d->render(); }, this);
    d->simulation = new SimOverlay(
        d->renderer, [this] { d->render(); }, this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);

    QString reason;
    if (openGlAvailable(&reason)) {
        d->gl = new VtkOpenGLWidget(this);
        d->gl->setObjectName(QStringLiteral("view3dGl"));
        vtkGenericOpenGLRenderWindow* window = d->gl->renderWindow();
        window->SetNumberOfLayers(2);
        window->AddRenderer(d->renderer);
        window->AddRenderer(d->markerRenderer);
        connect(d->gl, &VtkOpenGLWidget::aboutToRender, this, [this] {
            d->syncMarker();
            emit frameRendered();
        });
        d->gl->installEventFilter(this);
        layout->addWidget(d->gl);
    } else {
        d->message = new QLabel(tr("3D view unavailable: %1").arg(reason), this);
        d->message->setObjectName(QStringLiteral("noOpenGlMessage"));
        d->message->setAlignment(Qt::AlignCenter);
        d->message->setWordWrap(true);
        layout->addWidget(d->message);
    }
    setViewPreset(Preset::Isometric);
}

View3D::~View3D()
{
    // The GL widget releases VTK's graphics resources while its context still exists.
    delete d->gl;
}

void View3D::setDefaultSurfaceFormat() { QSurfaceFormat::setDefaultFormat(VtkOpenGLWidget::vtkSurfaceFormat()); }

bool View3D::openGlAvailable(QString* reason)
{
    auto fail = [reason](const QString& why) {
        if (reason != nullptr)
            *reason = why;
        return false;
    };
    if (qEnvironmentVariableIntValue("CAMWB_NO_OPENGL") == 1)
        return fail(tr("OpenGL is disabled (CAMWB_NO_OPENGL=1)"));
    if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr)
        return fail(tr("no GUI application"));
    const QString platform = QGuiApplication::platformName();
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal"))
        return fail(tr("the '%1' platform has no OpenGL display").arg(platform));

    QOpenGLContext* previous = QOpenGLContext::currentContext();
    QSurface* previousSurface = previous != nullptr ? previous->surface() : nullptr;
    const QSurfaceFormat format = VtkOpenGLWidget::vtkSurfaceFormat();
    bool ok = false;
    QString why;
    {
        QOffscreenSurface surface;
        surface.setFormat(format);
        surface.create();
        QOpenGLContext context;
        context.setFormat(format);
        if (!surface.isValid())
            why = tr("cannot create an offscreen OpenGL surface");
        else if (!context.create())
            why = tr("cannot create an OpenGL 3.2 core context");
        else if (!context.makeCurrent(&surface))
            why = tr("cannot make an OpenGL 3.2 core context current");
        else {
            const QSurfaceFormat actual = context.format();
            if (context.isOpenGLES())
                why = tr("only OpenGL ES is available");
            else if (actual.version() < qMakePair(3, 2))
                why = tr("OpenGL %1.%2 found, 3.2 needed").arg(actual.majorVersion()).arg(actual.minorVersion());
            else
                ok = true;
            context.doneCurrent();
        }
    }
    if (previous != nullptr && previousSurface != nullptr)
        previous->makeCurrent(previousSurface);
    if (!ok)
        return fail(why);
    if (reason != nullptr)
        reason->clear();
    return true;
}

bool View3D::hasOpenGl() const { return d->gl != nullptr; }

void View3D::setModel(const occ::DisplayMesh& mesh)
{
    clearModel();
    d->modelActor = makeModelActor(mesh);
    d->edgeActor = makeEdgeActor(mesh);
    if (d->modelActor) {
        d->renderer->AddActor(d->modelActor);
        d->overlay->setModel(d->modelActor);
    }
    if (d->edgeActor)
        d->renderer->AddActor(d->edgeActor);
    applyVisibility();
    fitAll();
}

void View3D::clearModel()
{
    if (d->modelActor)
        d->renderer->RemoveActor(d->modelActor);
    if (d->edgeActor)
        d->renderer->RemoveActor(d->edgeActor);
    d->modelActor = nullptr;
    d->edgeActor = nullptr;
    d->overlay->setModel(nullptr);
    d->render();
}

void View3D::setToolpath(const toolpath::Toolpath& toolpath) { setPreparedToolpath(prepareToolpath(toolpath)); }

std::shared_ptr<const ToolpathScene> View3D::prepareToolpath(const toolpath::Toolpath& toolpath,
                                                             const std::vector<bool>& recordsInError)
{
    return ToolpathScene::build(toolpath, kChordToleranceMm, recordsInError);
}

void View3D::setPreparedToolpath(std::shared_ptr<const ToolpathScene> scene)
{
    if (scene && scene == d->scene)
        return;  // shown already: keep the actors and what the GPU holds
    const bool fitAfter = !d->modelActor && !hasToolpathActor();
    clearToolpath();
    if (!scene || scene->polylines().empty())
        return;
    d->scene = std::move(scene);
    showScene();
    if (fitAfter)
        fitAll();
    else
        d->renderer->ResetCameraClippingRange();
    d->render();
}

// Rapids go in first: where a cycle's feed and its rapid retract coincide, the feed drawn later
// wins the depth test (VTK tests less-or-equal) and shows green, as on the control's graphics.
void View3D::showScene()
{
    for (const ToolpathScene::Part& part : d->scene->parts()) {
        Private::ToolActors actors{part.tool, nullptr, nullptr};
        const bool visible = d->hiddenTools.count(part.tool) == 0;
        if (part.rapid) {
            actors.rapid = makeActor(part.rapid);
            actors.rapid->GetMapper()->ScalarVisibilityOff();
            actors.rapid->GetProperty()->SetColor(kRapidColor[0], kRapidColor[1], kRapidColor[2]);
            actors.rapid->GetProperty()->SetLineWidth(1.0f);
            actors.rapid->GetProperty()->LightingOff();
            actors.rapid->SetVisibility(visible);
            d->renderer->AddActor(actors.rapid);
        }
        if (part.cut) {
            actors.cut = makeActor(part.cut);
            actors.cut->GetMapper()->SetScalarModeToUseCellData();
            actors.cut->GetMapper()->SetColorModeToDirectScalars();
            actors.cut->GetProperty()->SetLineWidth(2.0f);
            actors.cut->GetProperty()->LightingOff();
            actors.cut->SetVisibility(visible);
            d->renderer->AddActor(actors.cut);
        }
        d->toolActors.push_back(actors);
    }
    applyVisibility();
}

void View3D::clearToolpath()
{
    for (const Private::ToolActors& actors : d->toolActors) {
        if (actors.cut)
            d->renderer->RemoveActor(actors.cut);
        if (actors.rapid)
            d->renderer->RemoveActor(actors.rapid);
    }
    d->toolActors.clear();
    if (d->highlightActor)
        d->renderer->RemoveActor(d->highlightActor);
    d->highlightActor = nullptr;
    d->highlighted.clear();
    d->scene = nullptr;
    d->render();
}

void View3D::setJobSetup(const std::optional<base::Box3>& stock, bool cylinder,
                         std::shared_ptr<const sim::TriangleMesh> blank)
{
    if (d->stockActor)
        d->renderer->RemoveActor(d->stockActor);
    if (d->workAxes)
        d->renderer->RemoveActor(d->workAxes);
    d->stockActor = !stock                     ? nullptr
                    : blank && !blank->empty() ? makeStockActor(*blank)
                                               : makeStockActor(*stock, cylinder);
    // Axes a third of the stock's largest size long (20 mm without stock): seen, not in the way.
    double length = 20;
    if (stock) {
        const base::Vec3 size = stock->max - stock->min;
        length = std::max({size.x, size.y, size.z}) / 3;
    }
    d->workAxes = makeWorkAxes(length);
    if (d->stockActor)
        d->renderer->AddActor(d->stockActor);  // translucent: VTK draws it after the opaque model
    d->renderer->AddActor(d->workAxes);
    applyVisibility();
    d->render();
}

bool View3D::hasStockActor() const { return d->stockActor != nullptr; }

void View3D::setLatheSection(const std::optional<LatheSection>& section)
{
    for (const auto& actor : d->latheActors)
        d->renderer->RemoveActor(actor);
    d->latheActors = section ? makeLatheActors(*section) : std::vector<vtkSmartPointer<vtkActor>>{};
    for (const auto& actor : d->latheActors)
        d->renderer->AddActor(actor);
    applyVisibility();
    d->render();
}

bool View3D::hasLatheSection() const { return !d->latheActors.empty(); }

bool View3D::hasWorkAxes() const { return d->workAxes != nullptr; }

bool View3D::hasModelActor() const { return d->modelActor != nullptr || d->edgeActor != nullptr; }

bool View3D::hasToolpathActor() const { return !d->toolActors.empty(); }

int View3D::toolpathSegmentCount() const
{
    return d->scene ? static_cast<int>(d->scene->polylines().segments().size()) : 0;
}

const toolpath::ToolpathPolylines* View3D::toolpathPolylines() const
{
    return d->scene ? &d->scene->polylines() : nullptr;
}

std::vector<int> View3D::toolpathTools() const { return d->scene ? d->scene->tools() : std::vector<int>{}; }

void View3D::setToolVisible(int tool, bool visible)
{
    if (visible)
        d->hiddenTools.erase(tool);
    else
        d->hiddenTools.insert(tool);
    applyVisibility();
    d->render();
}

void View3D::applyVisibility()
{
    for (const Private::ToolActors& actors : d->toolActors) {
        const bool visible = !d->simulationShown && d->toolpathShown && d->hiddenTools.count(actors.tool) == 0;
        if (actors.cut)
            actors.cut->SetVisibility(visible);
        if (actors.rapid)
            actors.rapid->SetVisibility(visible);
    }
    // The simulator shows its own stock: the job's translucent one would hide the cut.
    for (vtkActor* actor : {d->modelActor.Get(), d->edgeActor.Get(), d->stockActor.Get()})
        if (actor != nullptr)
            actor->SetVisibility(!d->simulationShown);
    for (const auto& actor : d->latheActors)
        actor->SetVisibility(!d->simulationShown);
    std::vector<vtkProp3D*> placed{d->modelActor, d->edgeActor, d->stockActor, d->workAxes, d->highlightActor};
    for (const Private::ToolActors& actors : d->toolActors)
        placed.insert(placed.end(), {actors.cut, actors.rapid});
    for (vtkProp3D* prop : placed)
        if (prop != nullptr)
            prop->SetUserMatrix(d->workpiece);
}

void View3D::setWorkpieceMotion(const kinematics::RigidMotion& motion)
{
    d->simulation->setWorkpieceMotion(motion);
    d->workpiece = userMatrix(motion);
    applyVisibility();
    d->render();
}

void View3D::setToolpathShown(bool shown)
{
    d->toolpathShown = shown;
    applyVisibility();
    d->render();
}

bool View3D::isToolpathShown() const { return d->toolpathShown; }

SimOverlay& View3D::simulation() const { return *d->simulation; }

void View3D::setSimulationShown(bool shown)
{
    d->simulationShown = shown;
    applyVisibility();
    d->render();
}

bool View3D::isSimulationShown() const { return d->simulationShown; }

bool View3D::isToolVisible(int tool) const { return d->hiddenTools.count(tool) == 0; }

int View3D::visibleSegmentCount() const
{
    if (!d->scene)
        return 0;
    std::size_t count = 0;
    for (const ToolpathScene::Part& part : d->scene->parts())
        if (isToolVisible(part.tool))
            count += part.cutSegments.size() + part.rapidSegments.size();
    return static_cast<int>(count);
}

void View3D::setHighlightedRecords(const std::vector<std::size_t>& records)
{
    if (d->highlightActor)
        d->renderer->RemoveActor(d->highlightActor);
    d->highlightActor = nullptr;
    d->highlighted.clear();
    if (d->scene) {
        const toolpath::ToolpathPolylines& polylines = d->scene->polylines();
        for (std::size_t record : records) {
            const auto [begin, end] =
                polylines.segmentsOfRecords(static_cast<std::uint32_t>(record), static_cast<std::uint32_t>(record));
            for (std::size_t s = begin; s < end; ++s)
                d->highlighted.push_back(static_cast<std::uint32_t>(s));
        }
    }
    if (!d->highlighted.empty()) {
        d->highlightActor = makeActor(d->scene->subset(d->highlighted));
        d->highlightActor->GetMapper()->ScalarVisibilityOff();
        // Drawn over the backplot's own lines at the same place.
        d->highlightActor->GetMapper()->SetRelativeCoincidentTopologyLineOffsetParameters(-4.0, -8.0);
        d->highlightActor->GetProperty()->SetColor(kHighlightColor[0], kHighlightColor[1], kHighlightColor[2]);
        // Wide lines are not in the OpenGL core profile: VTK draws them as tubes (imposters).
        d->highlightActor->GetProperty()->SetRenderLinesAsTubes(true);
        d->highlightActor->GetProperty()->SetLineWidth(6.0f);
        d->highlightActor->GetProperty()->LightingOff();
        d->highlightActor->PickableOff();
        d->highlightActor->SetUserMatrix(d->workpiece);
        d->renderer->AddActor(d->highlightActor);
    }
    d->render();
}

const std::vector<std::uint32_t>& View3D::highlightedSegments() const { return d->highlighted; }

namespace {

// `workpiece` (the machine frame's motion, may be null) first: a point of the backplot is drawn there.
ScreenProjection projectionOf(vtkRenderer* renderer, double width, double height, vtkMatrix4x4* workpiece = nullptr)
{
    ScreenProjection projection;
    projection.width = width;
    projection.height = height;
    const double aspect = height > 0 ? width / height : 1.0;
    vtkMatrix4x4* matrix = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
    vtkNew<vtkMatrix4x4> moved;
    if (workpiece != nullptr) {
        vtkMatrix4x4::Multiply4x4(matrix, workpiece, moved);
        matrix = moved;
    }
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            projection.m[4 * r + c] = matrix->GetElement(r, c);
    return projection;
}

}  // namespace

std::optional<QPointF> View3D::projectToWidget(const base::Vec3& point) const
{
    if (d->gl == nullptr)
        return std::nullopt;
    const ScreenProjection projection = projectionOf(d->renderer, d->gl->width(), d->gl->height());
    double x = 0, y = 0;
    if (!projection.project(point, x, y))
        return std::nullopt;
    return QPointF(x, y) + QPointF(d->gl->mapTo(this, QPoint(0, 0)));
}

int View3D::pickSegment(const QPointF& widgetPosition, double tolerancePx) const
{
    if (d->gl == nullptr || !d->scene)
        return -1;
    const QPointF local = widgetPosition - QPointF(d->gl->mapTo(this, QPoint(0, 0)));
    return d->scene->nearestSegment(projectionOf(d->renderer, d->gl->width(), d->gl->height(), d->workpiece), local.x(),
                                    local.y(), tolerancePx, d->hiddenTools);
}

TaskOverlay& View3D::overlay() const { return *d->overlay; }

int View3D::pickFace(const QPointF& widgetPosition, base::Vec3* point) const
{
    if (d->gl == nullptr || !d->modelActor)
        return 0;
    // VTK's display coordinates: device pixels, origin at the bottom left.
    const QPointF local = widgetPosition - QPointF(d->gl->mapTo(this, QPoint(0, 0)));
    const double ratio = d->gl->devicePixelRatioF();
    vtkNew<vtkCellPicker> picker;
    picker->SetTolerance(1e-4);
    picker->PickFromListOn();
    picker->AddPickList(d->modelActor);
    if (picker->Pick(local.x() * ratio, (d->gl->height() - local.y()) * ratio, 0.0, d->renderer) == 0)
        return 0;
    auto* data = vtkPolyData::SafeDownCast(d->modelActor->GetMapper()->GetInput());
    auto* faceOf = data ? vtkIntArray::SafeDownCast(data->GetCellData()->GetArray("face")) : nullptr;
    const vtkIdType cell = picker->GetCellId();
    if (point != nullptr) {
        // Back into work coordinates where the simulator's machine frame moved the model.
        double at[4]{0, 0, 0, 1};
        std::copy_n(picker->GetPickPosition(), 3, at);
        if (d->workpiece) {
            vtkNew<vtkMatrix4x4> back;
            vtkMatrix4x4::Invert(d->workpiece, back);
            back->MultiplyPoint(at, at);
        }
        *point = {at[0], at[1], at[2]};
    }
    return faceOf != nullptr && cell >= 0 && cell < faceOf->GetNumberOfTuples() ? faceOf->GetValue(cell) : 0;
}

bool View3D::eventFilter(QObject* watched, QEvent* event)
{
    if (d->gl == nullptr || watched != d->gl)
        return QWidget::eventFilter(watched, event);
    if (event->type() == QEvent::MouseButtonPress) {
        auto* mouse = static_cast<QMouseEvent*>(event);
        d->pressed = mouse->button() == Qt::LeftButton;
        d->pressPosition = mouse->position();
    } else if (event->type() == QEvent::MouseButtonRelease && d->pressed) {
        auto* mouse = static_cast<QMouseEvent*>(event);
        d->pressed = false;
        const QPointF moved = mouse->position() - d->pressPosition;
        if (mouse->button() == Qt::LeftButton && std::abs(moved.x()) + std::abs(moved.y()) <= kClickSlopPx) {
            const QPointF at = mouse->position() + QPointF(d->gl->mapTo(this, QPoint(0, 0)));
            const int segment = pickSegment(at);
            if (segment >= 0)
                emit segmentPicked(segment, static_cast<int>(d->scene->polylines().segments()[segment].record));
            else {
                base::Vec3 point;
                const int face = pickFace(at, &point);
                d->overlay->clickFace(face, mouse->modifiers().testFlag(Qt::ControlModifier));
                d->overlay->setPickedPoint(face > 0 ? std::optional<base::Vec3>(point) : std::nullopt);
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

void View3D::setViewPreset(Preset preset)
{
    d->preset = preset;
    vtkCamera* camera = d->renderer->GetActiveCamera();
    camera->SetFocalPoint(0, 0, 0);
    switch (preset) {
    case Preset::Isometric:
        camera->SetPosition(1, -1, 1);
        camera->SetViewUp(0, 0, 1);
        break;
    case Preset::Top:
        camera->SetPosition(0, 0, 1);
        camera->SetViewUp(0, 1, 0);
        break;
    case Preset::Front:
        camera->SetPosition(0, -1, 0);
        camera->SetViewUp(0, 0, 1);
        break;
    case Preset::Right:
        camera->SetPosition(1, 0, 0);
        camera->SetViewUp(0, 0, 1);
        break;
    case Preset::LatheXZ:  // from +Y looking along -Y: Z to the right, X (the radius) up
        camera->SetPosition(0, 1, 0);
        camera->SetViewUp(1, 0, 0);
        break;
    }
    camera->OrthogonalizeViewUp();
    fitAll();
}

View3D::Preset View3D::viewPreset() const { return d->preset; }

void View3D::fitAll()
{
    d->renderer->ResetCamera();
    d->renderer->ResetCameraClippingRange();
    d->render();
}

QImage View3D::grabImage()
{
    if (d->gl == nullptr)
        return {};
    return d->gl->grabFramebuffer();
}

}  // namespace camwb::gui
