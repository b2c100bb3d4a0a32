#include "gui/sim/SimOverlay.h"

#include "gui/view3d/detail/MachineFrameActors.h"
#include "gui/view3d/detail/ModelActors.h"
#include "gui/view3d/detail/ToolpathScene.h"
#include "sim/Moves.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

namespace camwb::gui {

namespace {

constexpr int kToolSides = 32;
constexpr double kStockColor[3]{0.78, 0.70, 0.55};
constexpr double kDoneFeedColor[3]{kFeedRgb[0] / 255.0, kFeedRgb[1] / 255.0, kFeedRgb[2] / 255.0};
constexpr double kMarkerColor[3]{0.9, 0.0, 0.0};
// Where a check found an error (gouge, rapid in stock, holder): magenta, apart from the reversals.
constexpr double kFindingColor[3]{0.85, 0.0, 0.85};
// A measured trace: the program thin and dark, the nominal trace black (the actual is coloured).
constexpr double kProgrammedColor[3]{0.35, 0.35, 0.38};
constexpr double kNominalColor[3]{0.0, 0.0, 0.0};

vtkSmartPointer<vtkPolyData> emptyLines()
{
    auto data = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    data->SetPoints(points);
    vtkNew<vtkCellArray> lines;
    data->SetLines(lines);
    return data;
}

vtkSmartPointer<vtkActor> lineActor(vtkPolyData* data, const double color[3], float width)
{
    auto actor = makeActor(data);
    actor->GetMapper()->ScalarVisibilityOff();
    actor->GetMapper()->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -6.0);
    actor->GetProperty()->SetColor(color[0], color[1], color[2]);
    actor->GetProperty()->SetLineWidth(width);
    actor->GetProperty()->LightingOff();
    actor->PickableOff();
    return actor;
}

// A surface of revolution about +Z: the outline's points turned in kToolSides steps, capped by
// the outline itself where it meets the axis.
vtkSmartPointer<vtkPolyData> revolve(const RevolvedPart& part)
{
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> quads;
    const auto& profile = part.profile;
    for (const auto& [r, z] : profile)
        for (int s = 0; s < kToolSides; ++s) {
            const double a = 2 * M_PI * s / kToolSides;
            points->InsertNextPoint(r * std::cos(a), r * std::sin(a), z);
        }
    for (std::size_t i = 0; i + 1 < profile.size(); ++i)
        for (int s = 0; s < kToolSides; ++s) {
            const vtkIdType a = static_cast<vtkIdType>(i * kToolSides + s);
            const vtkIdType b = static_cast<vtkIdType>(i * kToolSides + (s + 1) % kToolSides);
            const vtkIdType quad[4]{a, b, b + kToolSides, a + kToolSides};
            quads->InsertNextCell(4, quad);
        }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(quads);
    return data;
}

// Points drawn as spheres of `sizePx`, on top of nothing in particular (they are not picked).
vtkSmartPointer<vtkActor> markerActor(const std::vector<base::Vec3>& at, const double color[3], float sizePx)
{
    auto data = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> vertices;
    for (const base::Vec3& p : at) {
        const vtkIdType id = points->InsertNextPoint(p.x, p.y, p.z);
        vertices->InsertNextCell(1, &id);
    }
    data->SetPoints(points);
    data->SetVerts(vertices);
    auto actor = makeActor(data);
    actor->GetMapper()->ScalarVisibilityOff();
    actor->GetProperty()->SetColor(color[0], color[1], color[2]);
    actor->GetProperty()->SetPointSize(sizePx);
    actor->GetProperty()->SetRenderPointsAsSpheres(true);
    actor->PickableOff();
    return actor;
}

vtkSmartPointer<vtkScalarBarActor> scalarBar(vtkLookupTable* table, double x)
{
    auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
    bar->SetLookupTable(table);
    bar->SetNumberOfLabels(5);
    bar->SetPosition(x, 0.12);
    bar->SetWidth(0.08);
    bar->SetHeight(0.7);
    bar->SetLabelFormat("%-#6.3g");
    for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
        text->SetColor(0.05, 0.05, 0.05);
        text->ShadowOff();
        text->ItalicOff();
        text->SetFontSize(13);
    }
    bar->UnconstrainedFontSizeOn();
    return bar;
}

// Gouges red, on the model green, material left blue; beyond the limits darker.
void fillDeviationTable(vtkLookupTable* table, double limit)
{
    constexpr int kColours = 256;
    table->SetNumberOfTableValues(kColours);
    table->SetTableRange(-limit, limit);
    for (int i = 0; i < kColours; ++i) {
        const double t = 2.0 * i / (kColours - 1) - 1.0;  // -1 gouge .. +1 leftover
        const double g = 1.0 - std::abs(t);
        table->SetTableValue(i, t < 0 ? 0.85 - 0.1 * g : 0.2 * g, 0.3 + 0.45 * g, t > 0 ? 0.9 - 0.15 * g : 0.2 * g);
    }
    table->SetBelowRangeColor(0.55, 0.0, 0.0, 1.0);
    table->SetAboveRangeColor(0.05, 0.05, 0.55, 1.0);
    table->UseBelowRangeColorOn();
    table->UseAboveRangeColorOn();
    table->Build();
}

}  // namespace

struct SimOverlay::Private {
    vtkRenderer* renderer = nullptr;
    std::function<void()> render;

    const sim::MoveList* moves = nullptr;
    std::size_t drawnMoves = 0;
    vtkSmartPointer<vtkPolyData> feedDone, rapidDone, current;
    vtkSmartPointer<vtkActor> feedActor, rapidActor, currentActor;
    bool currentRapid = false;

    std::map<int, std::vector<vtkSmartPointer<vtkActor>>> tools;
    int toolShown = -1;
    bool toolVisible = true;

    vtkSmartPointer<vtkActor> stock;
    vtkSmartPointer<vtkPolyData> stockData;
    vtkSmartPointer<vtkFloatArray> stockPoints;
    std::shared_ptr<const std::vector<std::uint32_t>> stockCells;
    vtkNew<vtkLookupTable> deviationTable;
    vtkSmartPointer<vtkScalarBarActor> deviationBar;
    bool deviationShown = false;
    int stockTriangles = 0;

    vtkSmartPointer<vtkActor> coloured, markers, findings;
    vtkSmartPointer<vtkActor> programmed, nominal;
    int findingCount = 0;
    vtkNew<vtkLookupTable> quantityTable;
    vtkSmartPointer<vtkScalarBarActor> quantityBar;
    int markerCount = 0;

    std::vector<vtkSmartPointer<vtkActor>> table;
    vtkSmartPointer<vtkMatrix4x4> workpiece;  // the machine frame's motion; null: workpiece frame

    // A prop of the workpiece side takes the machine frame's motion (a tool's does not).
    void add(vtkProp* prop, bool visible = true, bool workpieceSide = true)
    {
        prop->SetVisibility(visible);
        if (auto* placed = vtkProp3D::SafeDownCast(prop); placed != nullptr && workpieceSide)
            placed->SetUserMatrix(workpiece);
        if (renderer != nullptr)
            renderer->AddViewProp(prop);
    }
    template <typename T> void remove(vtkSmartPointer<T>& prop)
    {
        if (prop && renderer != nullptr)
            renderer->RemoveViewProp(prop);
        prop = nullptr;
    }
    void clearPath();
    void appendMove(const sim::Move& move);
    void showPathActors(bool visible);
};

SimOverlay::SimOverlay(vtkRenderer* renderer, std::function<void()> render, QObject* parent) :
    QObject(parent),
    d(std::make_unique<Private>())
{
    d->renderer = renderer;
    d->render = std::move(render);
    d->deviationBar = scalarBar(d->deviationTable, 0.9);
    d->deviationBar->SetTitle("mm");
    d->add(d->deviationBar, false);
    d->quantityBar = scalarBar(d->quantityTable, 0.02);
    d->add(d->quantityBar, false);
}

SimOverlay::~SimOverlay() = default;

void SimOverlay::clear()
{
    d->clearPath();
    d->moves = nullptr;
    for (auto& [number, actors] : d->tools)
        for (auto& actor : actors)
            d->remove(actor);
    d->tools.clear();
    d->toolShown = -1;
    d->remove(d->stock);
    d->stockData = nullptr;
    d->stockPoints = nullptr;
    d->stockCells = nullptr;
    d->stockTriangles = 0;
    d->deviationShown = false;
    d->deviationBar->SetVisibility(false);
    showColouredPath({}, {}, 0, 1, {}, {});
    showFindings({});
    showMeasured({}, {});
    setTable(std::nullopt);
    setWorkpieceMotion({});
}

void SimOverlay::Private::clearPath()
{
    remove(feedActor);
    remove(rapidActor);
    remove(currentActor);
    feedDone = rapidDone = current = nullptr;
    drawnMoves = 0;
}

void SimOverlay::setPath(const sim::MoveList* moves)
{
    d->clearPath();
    d->moves = moves;
    if (moves == nullptr)
        return;
    d->feedDone = emptyLines();
    d->rapidDone = emptyLines();
    d->current = emptyLines();
    d->feedActor = lineActor(d->feedDone, kDoneFeedColor, 2.0f);
    d->rapidActor = lineActor(d->rapidDone, kRapidColor, 1.0f);
    d->currentActor = lineActor(d->current, kDoneFeedColor, 2.0f);
    d->add(d->feedActor, !d->coloured);
    d->add(d->rapidActor, !d->coloured);
    d->add(d->currentActor, !d->coloured);
}

void SimOverlay::Private::appendMove(const sim::Move& move)
{
    if (!move.moves() || !move.positionKnown)
        return;
    vtkPolyData* data = move.kind == sim::MoveKind::Rapid ? rapidDone : feedDone;
    vtkPoints* points = data->GetPoints();
    const vtkIdType a = points->InsertNextPoint(move.from.x, move.from.y, move.from.z);
    const vtkIdType b = points->InsertNextPoint(move.to.x, move.to.y, move.to.z);
    const vtkIdType ids[2]{a, b};
    data->GetLines()->InsertNextCell(2, ids);
}

void SimOverlay::showPathUpTo(const MovePoint& at, const base::Vec3& tip)
{
    if (d->moves == nullptr || !d->feedDone)
        return;
    const auto& moves = d->moves->moves;
    const std::size_t upTo = std::min(at.move, moves.size());
    if (upTo < d->drawnMoves) {  // back: draw again from the start
        const sim::MoveList* keep = d->moves;
        setPath(keep);
    }
    for (; d->drawnMoves < upTo; ++d->drawnMoves)
        d->appendMove(moves[d->drawnMoves]);
    d->feedDone->Modified();
    d->rapidDone->Modified();

    // The move under way, from its start to the tool.
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    if (upTo < moves.size() && moves[upTo].moves() && moves[upTo].positionKnown) {
        const sim::Move& move = moves[upTo];
        points->InsertNextPoint(move.from.x, move.from.y, move.from.z);
        points->InsertNextPoint(tip.x, tip.y, tip.z);
        const vtkIdType ids[2]{0, 1};
        lines->InsertNextCell(2, ids);
        const double* color = move.kind == sim::MoveKind::Rapid ? kRapidColor : kDoneFeedColor;
        d->currentActor->GetProperty()->SetColor(color[0], color[1], color[2]);
    }
    d->current->SetPoints(points);
    d->current->SetLines(lines);
    d->render();
}

int SimOverlay::pathSegmentCount() const
{
    if (!d->feedDone)
        return 0;
    return static_cast<int>(d->feedDone->GetNumberOfLines() + d->rapidDone->GetNumberOfLines());
}

void SimOverlay::setTools(const std::map<int, std::vector<RevolvedPart>>& tools)
{
    for (auto& [number, actors] : d->tools)
        for (auto& actor : actors)
            d->remove(actor);
    d->tools.clear();
    d->toolShown = -1;
    for (const auto& [number, parts] : tools) {
        auto& actors = d->tools[number];
        for (const RevolvedPart& part : parts) {
            auto actor = makeActor(revolve(part));
            actor->GetProperty()->SetColor(part.rgb[0], part.rgb[1], part.rgb[2]);
            actor->PickableOff();
            d->add(actor, false, false);
            actors.push_back(actor);
        }
    }
}

void SimOverlay::showTool(const ToolPose& pose)
{
    const int shown = pose.known && d->tools.count(pose.tool) ? pose.tool : -1;
    d->toolShown = shown;
    for (auto& [number, actors] : d->tools)
        for (auto& actor : actors)
            actor->SetVisibility(number == shown && d->toolVisible);
    if (shown < 0) {
        d->render();
        return;
    }
    // The tool's +Z along the axis, its tip at the tip: columns x, y, axis, tip.
    const base::Vec3 z = pose.axis.normalized();
    const base::Vec3 helper = std::abs(z.z) < 0.9 ? base::Vec3{0, 0, 1} : base::Vec3{1, 0, 0};
    const base::Vec3 x = helper.cross(z).normalized();
    const base::Vec3 y = z.cross(x);
    vtkNew<vtkMatrix4x4> matrix;
    const base::Vec3 columns[4]{x, y, z, pose.tip};
    for (int c = 0; c < 4; ++c) {
        matrix->SetElement(0, c, columns[c].x);
        matrix->SetElement(1, c, columns[c].y);
        matrix->SetElement(2, c, columns[c].z);
    }
    for (auto& actor : d->tools[shown])
        actor->SetUserMatrix(matrix);
    d->render();
}

bool SimOverlay::hasToolActor() const { return d->toolShown >= 0; }

void SimOverlay::setToolVisible(bool visible)
{
    d->toolVisible = visible;
    for (auto& [number, actors] : d->tools)
        for (auto& actor : actors)
            actor->SetVisibility(number == d->toolShown && visible);
    d->render();
}

void SimOverlay::showStock(std::shared_ptr<const std::vector<float>> positions,
                           std::shared_ptr<const std::vector<std::uint32_t>> triangles,
                           const std::vector<float>* deviation, double limitMm)
{
    if (!positions || !triangles)
        return;
    const vtkIdType vertices = static_cast<vtkIdType>(positions->size() / 3);
    const bool sameCells = d->stock && triangles == d->stockCells && d->stockPoints->GetNumberOfTuples() == vertices;
    if (!sameCells) {
        d->stockPoints = vtkSmartPointer<vtkFloatArray>::New();
        d->stockPoints->SetNumberOfComponents(3);
        d->stockPoints->SetNumberOfTuples(vertices);
    }
    std::copy(positions->begin(), positions->end(), d->stockPoints->GetPointer(0));
    d->stockPoints->Modified();
    vtkPolyData* data = d->stockData;
    if (!sameCells) {
        vtkNew<vtkPoints> points;
        points->SetData(d->stockPoints);
        vtkNew<vtkCellArray> cells;
        cells->AllocateExact(static_cast<vtkIdType>(triangles->size() / 3), static_cast<vtkIdType>(triangles->size()));
        for (std::size_t t = 0; t + 2 < triangles->size(); t += 3) {
            const vtkIdType ids[3]{(*triangles)[t], (*triangles)[t + 1], (*triangles)[t + 2]};
            cells->InsertNextCell(3, ids);
        }
        d->stockData = vtkSmartPointer<vtkPolyData>::New();
        d->stockData->SetPoints(points);
        d->stockData->SetPolys(cells);
        d->stockCells = std::move(triangles);
        data = d->stockData;
    } else {
        data->GetPoints()->Modified();
    }
    d->deviationShown = deviation != nullptr && static_cast<vtkIdType>(deviation->size()) == vertices;
    if (d->deviationShown) {
        vtkNew<vtkFloatArray> values;
        values->SetName("deviation");
        values->SetNumberOfTuples(vertices);
        std::copy(deviation->begin(), deviation->end(), values->GetPointer(0));
        data->GetPointData()->SetScalars(values);
        fillDeviationTable(d->deviationTable, std::max(limitMm, 1e-6));
    } else {
        data->GetPointData()->SetScalars(nullptr);
    }
    if (!d->stock) {
        d->stock = makeActor(data);
        d->stock->GetProperty()->SetColor(kStockColor[0], kStockColor[1], kStockColor[2]);
        d->stock->PickableOff();
        d->add(d->stock);
    } else if (!sameCells) {
        static_cast<vtkPolyDataMapper*>(d->stock->GetMapper())->SetInputData(data);
    }
    vtkMapper* mapper = d->stock->GetMapper();
    mapper->SetScalarVisibility(d->deviationShown);
    mapper->SetLookupTable(d->deviationTable);
    mapper->UseLookupTableScalarRangeOn();
    d->deviationBar->SetVisibility(d->deviationShown);
    d->stockTriangles = static_cast<int>(d->stockCells->size() / 3);
    d->render();
}

bool SimOverlay::hasStockActor() const { return d->stock != nullptr; }

int SimOverlay::stockTriangleCount() const { return d->stockTriangles; }

bool SimOverlay::showsDeviation() const { return d->deviationShown; }

void SimOverlay::showColouredPath(const std::vector<base::Vec3>& points, const std::vector<double>& values, double low,
                                  double high, const QString& title, const std::vector<base::Vec3>& markers)
{
    d->remove(d->coloured);
    d->remove(d->markers);
    d->markerCount = 0;
    d->quantityBar->SetVisibility(false);
    const bool show = points.size() >= 2 && values.size() == points.size();
    d->showPathActors(!show);
    if (!show) {
        d->render();
        return;
    }
    vtkNew<vtkPoints> pathPoints;
    pathPoints->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
    vtkNew<vtkDoubleArray> scalars;
    scalars->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        pathPoints->SetPoint(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
        scalars->SetValue(static_cast<vtkIdType>(i), values[i]);
    }
    vtkNew<vtkCellArray> line;
    line->InsertNextCell(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        line->InsertCellPoint(static_cast<vtkIdType>(i));
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(pathPoints);
    data->SetLines(line);
    data->GetPointData()->SetScalars(scalars);

    d->quantityTable->SetHueRange(0.667, 0.0);  // blue (low) to red (high)
    d->quantityTable->SetTableRange(low, high > low ? high : low + 1e-9);
    d->quantityTable->Build();
    d->coloured = makeActor(data);
    d->coloured->GetMapper()->SetLookupTable(d->quantityTable);
    d->coloured->GetMapper()->UseLookupTableScalarRangeOn();
    d->coloured->GetProperty()->SetLineWidth(3.0f);
    // Over the program's lines where it runs on them (a measured trace on its nominal path).
    d->coloured->GetMapper()->SetRelativeCoincidentTopologyLineOffsetParameters(-4.0, -12.0);
    d->coloured->GetProperty()->LightingOff();
    d->coloured->PickableOff();
    d->add(d->coloured);
    const QByteArray titleUtf8 = title.toUtf8();
    d->quantityBar->SetTitle(titleUtf8.constData());
    d->quantityBar->SetVisibility(true);

    if (!markers.empty()) {
        d->markers = markerActor(markers, kMarkerColor, 11.0f);
        d->add(d->markers);
        d->markerCount = static_cast<int>(markers.size());
    }
    d->render();
}

void SimOverlay::showMeasured(const std::vector<base::Vec3>& programmed, const std::vector<base::Vec3>& nominal)
{
    d->remove(d->programmed);
    d->remove(d->nominal);
    if (programmed.size() >= 2) {
        auto data = emptyLines();
        for (std::size_t i = 0; i + 1 < programmed.size(); i += 2) {
            const vtkIdType ids[2]{
                data->GetPoints()->InsertNextPoint(programmed[i].x, programmed[i].y, programmed[i].z),
                data->GetPoints()->InsertNextPoint(programmed[i + 1].x, programmed[i + 1].y, programmed[i + 1].z)};
            data->GetLines()->InsertNextCell(2, ids);
        }
        d->programmed = lineActor(data, kProgrammedColor, 1.0f);
        d->add(d->programmed);
    }
    if (nominal.size() >= 2) {
        auto data = emptyLines();
        data->GetLines()->InsertNextCell(static_cast<vtkIdType>(nominal.size()));
        for (const base::Vec3& p : nominal)
            data->GetLines()->InsertCellPoint(data->GetPoints()->InsertNextPoint(p.x, p.y, p.z));
        d->nominal = lineActor(data, kNominalColor, 1.5f);
        d->add(d->nominal);
    }
    d->render();
}

bool SimOverlay::showsMeasured() const { return d->nominal != nullptr; }

void SimOverlay::showFindings(const std::vector<base::Vec3>& at)
{
    d->remove(d->findings);
    d->findingCount = static_cast<int>(at.size());
    if (!at.empty()) {
        d->findings = markerActor(at, kFindingColor, 14.0f);
        d->add(d->findings);
    }
    d->render();
}

int SimOverlay::findingCount() const { return d->findingCount; }

void SimOverlay::Private::showPathActors(bool visible)
{
    for (vtkActor* actor : {feedActor.Get(), rapidActor.Get(), currentActor.Get()})
        if (actor != nullptr)
            actor->SetVisibility(visible);
}

bool SimOverlay::showsColouredPath() const { return d->coloured != nullptr; }

int SimOverlay::markerCount() const { return d->markerCount; }

void SimOverlay::setTable(const std::optional<RotaryTable>& table)
{
    for (auto& actor : d->table)
        d->remove(actor);
    d->table.clear();
    if (table && table->radiusMm > 0)
        for (auto& actor : makeTableActors(*table)) {
            d->add(actor);
            d->table.push_back(actor);
        }
    d->render();
}

bool SimOverlay::hasTableActor() const { return !d->table.empty(); }

void SimOverlay::setWorkpieceMotion(const kinematics::RigidMotion& motion)
{
    d->workpiece = userMatrix(motion);
    std::vector<vtkActor*> side{d->feedActor, d->rapidActor, d->currentActor, d->stock,  d->coloured,
                                d->markers,   d->findings,   d->programmed,   d->nominal};
    for (auto& actor : d->table)
        side.push_back(actor);
    for (vtkActor* actor : side)
        if (actor != nullptr)
            actor->SetUserMatrix(d->workpiece);
    d->render();
}

namespace {

std::array<double, 16> matrixOf(vtkActor* actor)
{
    std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    if (actor != nullptr && actor->GetUserMatrix() != nullptr)
        for (int i = 0; i < 16; ++i)
            m[static_cast<std::size_t>(i)] = actor->GetUserMatrix()->GetElement(i / 4, i % 4);
    return m;
}

}  // namespace

std::array<double, 16> SimOverlay::tableMatrix() const { return matrixOf(d->table.empty() ? nullptr : d->table[0]); }

std::array<double, 16> SimOverlay::stockMatrix() const { return matrixOf(d->stock); }

}  // namespace camwb::gui
