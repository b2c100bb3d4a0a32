// What the simulator draws in the 3D view: the tool (cutter, shank, holder as revolved shapes)
// at its pose, the path travelled so far, the cut stock (plain, or coloured by its deviation from
// the design model with a colour bar), the path coloured by an analysed quantity with its colour
// bar and red markers at axis reversals, a measured trace's nominal path beside the program, and
// the rotary table under the stock, all of which the machine frame turns together. Owned by View3D
// (View3D::simulation()), like the task overlay; VTK stays in the .cpp, so every call also works without OpenGL (it
// keeps data).
#pragma once

#include "base/Vec.h"
#include "gui/sim/MachineFrame.h"
#include "gui/sim/RevolvedPart.h"
#include "gui/sim/Timeline.h"

#include <QObject>
#include <QString>

#include <array>
#include <cstdint>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class vtkRenderer;

namespace camwb::sim {
struct MoveList;
}

namespace camwb::gui {

class SimOverlay : public QObject {
    Q_OBJECT
public:
    ~SimOverlay() override;

    // Removes everything the simulator drew.
    void clear();

    // The path travelled so far along `moves` (kept by the caller while shown): up to `at`.
    void setPath(const sim::MoveList* moves);
    void showPathUpTo(const MovePoint& at, const base::Vec3& tip);
    int pathSegmentCount() const;  // whole moves drawn (the current part-move not counted)

    // Each tool's revolved parts (radius, height above the tip), drawn at the pose given.
    void setTools(const std::map<int, std::vector<RevolvedPart>>& tools);
    void showTool(const ToolPose& pose);
    bool hasToolActor() const;          // a tool stands at a pose now (drawn unless hidden)
    void setToolVisible(bool visible);  // hides the tool, to see the stock under its holder

    // The stock as cut so far (positions x, y, z per vertex; three indices per triangle);
    // `deviation` (one value per vertex, mm: + leftover, - gouge) colours it within +-limitMm and
    // shows its colour bar, else it is drawn plain. Triangles that are the very list shown before
    // keep the view's cells: only the points go to the GPU again.
    void showStock(std::shared_ptr<const std::vector<float>> positions,
                   std::shared_ptr<const std::vector<std::uint32_t>> triangles, const std::vector<float>* deviation,
                   double limitMm);
    bool hasStockActor() const;
    int stockTriangleCount() const;
    bool showsDeviation() const;

    // The path through `points` coloured by `values` within [low, high] with a titled colour bar,
    // and red markers at `markers`; replaces the travelled path while shown. Empty points clear it.
    void showColouredPath(const std::vector<base::Vec3>& points, const std::vector<double>& values, double low,
                          double high, const QString& title, const std::vector<base::Vec3>& markers);
    bool showsColouredPath() const;

    // A measured trace beside its program: the programmed moves (`programmed`, two points per
    // move) as thin dark lines and the nominal trace as a polyline in one colour; the actual trace
    // is the coloured path (showColouredPath, by its deviation). Empty clears both.
    void showMeasured(const std::vector<base::Vec3>& programmed, const std::vector<base::Vec3>& nominal);
    bool showsMeasured() const;

    // Magenta markers where the simulation's checks found an error (empty clears).
    void showFindings(const std::vector<base::Vec3>& at);
    int findingCount() const;
    int markerCount() const;

    // The rotary table under the stock (none removes it): it turns with the workpiece side.
    void setTable(const std::optional<RotaryTable>& table);
    bool hasTableActor() const;
    // Where the workpiece side stands: the stock, the path (travelled, coloured, measured), the
    // markers and the table move by `motion` (the machine frame); the tool does not, its pose is
    // given in the frame shown. The identity puts everything back in the workpiece frame.
    void setWorkpieceMotion(const kinematics::RigidMotion& motion);
    // The 4x4 matrices (row by row) the table's and the stock's actors are drawn with: the
    // identity while they stand in the workpiece frame (or do not exist).
    std::array<double, 16> tableMatrix() const;
    std::array<double, 16> stockMatrix() const;

private:
    friend class View3D;
    SimOverlay(vtkRenderer* renderer, std::function<void()> render, QObject* parent);

    struct Private;
    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
