// The job: what the user edits and saves (.camwb). Derived data (model shape, toolpaths, NC)
// is never stored here; JobPipeline recomputes it.
#pragma once

#include "base/Vec.h"
#include "ops/ContourOp.h"
#include "ops/DrillOp.h"
#include "ops/GrooveOp.h"
#include "ops/HelixOp.h"
#include "ops/ParallelOp.h"
#include "ops/Pocket3dOp.h"
#include "ops/PocketOp.h"
#include "ops/SwarfOp.h"
#include "ops/WaterlineOp.h"

#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace camwb::document {

// The rule "stock = the model's bounds grown by these offsets" (mm, each >= 0 in use): `below`
// is taken off the minimum corner, `above` added to the maximum corner, per axis.
struct StockFromModel {
    base::Vec3 below;
    base::Vec3 above;

    bool operator==(const StockFromModel&) const = default;
};

// The raw material, in work coordinates (the model moved by -Job::origin). min/max are always the
// resolved bounding box every consumer uses; a cylinder stands along Z inside it (diameter = its
// x size = its y size). With `fromModel` set, min/max are recomputed from the model's bounds
// whenever the model is (re)loaded (resolve), so the GUI and camwb-cli post the same stock.
// A blank (a cast or forged part, Shape::Blank) is the solid in `blankPath`, a mesh or STEP file
// in the model file's coordinates (moved by -origin like the model); min/max are its bounds,
// re-resolved whenever it is loaded (document/StockBlank.h). It has no `fromModel` rule.
struct Stock {
    enum class Shape { Box, Cylinder, Blank };
    base::Vec3 min;
    base::Vec3 max;
    Shape shape = Shape::Box;
    std::optional<StockFromModel> fromModel;
    std::string blankPath;  // Shape::Blank: as the model path (absolute in memory, relative in the file)

    bool operator==(const Stock&) const = default;

    // Sets min/max from the model's bounds (work coordinates) when `fromModel` is set; a cylinder
    // takes the larger of the grown x and y sizes as its diameter, about the bounds' centre.
    void resolve(const base::Vec3& modelMin, const base::Vec3& modelMax);

    // The box, when the job gives one (min below max on every axis); none for a job without stock.
    std::optional<base::Box3> box() const
    {
        if (!(max.x > min.x && max.y > min.y && max.z > min.z))
            return std::nullopt;
        return base::Box3{min, max, false};
    }
};

// What an operation cuts, as references into the loaded model (indices are stable for a file:
// OCCT's map order, 1-based). Resolved to geometry by OperationGeometry.h.
struct GeometryRefs {
    std::vector<int> faces;  // planar faces: contour = their outer wires, pocket = face with islands;
                             // swarf: the one ruled face it follows
    std::vector<int> edges;  // edge chains (contour), open or closed; circular edges (helix); swarf:
                             // the drive edge (none: the face's lowest edge across its rulings)
    std::vector<int> holes;  // holes by their cylindrical face (helix, drilling)
};

// Heights the user set; the others are derived from the model and stock when the job is computed.
struct HeightOverrides {
    std::optional<double> clearanceZ, safeZ, startZ, finalZ;
};

// 3+2 machining: the plane an operation is computed in. Flat: the workpiece's XY, the tool along
// +Z (drilling then finds each hole's own axis, and holes of several directions are drilled one
// plane after another). Face: the tool along a planar face's outward normal. Angles: the spatial
// angles A, B, C of toolpath/PlaneFrames.h. The plane turns about the workpiece zero.
struct WorkingPlaneSpec {
    enum class Mode { Flat, Face, Angles } mode = Mode::Flat;
    int face = 0;
    double aDeg = 0, bDeg = 0, cDeg = 0;

    bool operator==(const WorkingPlaneSpec&) const = default;
};

// Pocket3d, Waterline and Parallel are the 3D operations: they cut the model's surface as a mesh
// (the selected faces, if any, bound the area) rather than planar faces and edges. Groove is the
// lathe's: a parametric groove (no model, no geometry references) cut in the XZ plane.
enum class OperationKind { Contour, Pocket, Helix, Drill, Swarf, Pocket3d, Waterline, Parallel, Groove };
using OperationParams =
    std::variant<ops::ContourParams, ops::PocketParams, ops::HelixParams, ops::DrillParams, ops::SwarfParams,
                 ops::Pocket3dParams, ops::WaterlineParams, ops::ParallelParams, ops::GrooveParams>;
// The 3D operations (Pocket3d, Waterline, Parallel).
inline bool isSurfaceKind(OperationKind kind)
{
    return kind >= OperationKind::Pocket3d && kind <= OperationKind::Parallel;
}
// The turning operations (Groove): they need no model, and write their own spindle start (G96).
inline bool isTurningKind(OperationKind kind) { return kind == OperationKind::Groove; }

// One operation of the job. `params.heights` is filled from `heights` and the model on compute;
// what is stored in the file is the overrides, so derived heights follow model changes.
struct Operation {
    int toolNumber = 1;
    GeometryRefs geometry;
    HeightOverrides heights;
    OperationParams params;
    WorkingPlaneSpec plane;
    // The operation's own values of post properties the post takes per operation (the iTNC's
    // tcpm), as text over the job's: they ride on its CL section (SectionBegin::postProperties).
    std::map<std::string, std::string> postProperties;
    // A disabled operation stays in the job but is neither computed nor posted (the user keeps
    // it for later); the others keep their indices, so messages still name the right one.
    bool enabled = true;

    OperationKind kind() const { return static_cast<OperationKind>(params.index()); }
    const std::string& name() const;
    void setName(const std::string& name);
};

// What the operator sets work offset `offset` (1-based) as on the control the post `postId`
// writes for, as the bundled posts write it: SINUMERIK G54..G57 then G505..G599, Heidenhain the
// preset number, ISO (LinuxCNC and others) G54..G59 then G59.1..G59.3; "offset N" past those.
std::string workOffsetName(int offset, const std::string& postId);

// "contour", "pocket", "helix", "drill", "swarf", "pocket3d", "waterline", "parallel", "groove":
// the operation's type in the file.
const char* kindName(OperationKind kind);
// The word messages name it by, as the operations do: "contour", "pocket", "helix", "drilling",
// "3D pocket", "waterline", "parallel", "groove roughing".
const char* kindLabel(OperationKind kind);

struct Job {
    std::string name;
    std::string modelPath;  // as written in the file: relative to the job file's folder
    Stock stock;
    int workOffset = 1;  // 1 = G54
    std::vector<ops::ToolController> tools;
    std::vector<Operation> operations;
    std::string postId = "sinumerik828d-emco";
    std::map<std::string, std::string> postProperties;  // values as text, by property name
    std::string machineId;                              // empty: the post's default machine
    std::string material;  // the stock material tools' cutting data is chosen by; empty: none given
    // Program zero, in the model file's coordinates: the model (and so every operation, toolpath
    // and the NC) is worked on moved by -origin. Stock coordinates are work coordinates.
    base::Vec3 origin;
    // Where the NC program goes by default (Save NC Program, `camwb-cli run` without -o):
    // file name (the post's extension added when it has none) in a folder relative to the job
    // file (empty: the job file's folder). Empty name: no default.
    std::string outputName;
    std::string outputFolder;

    const ops::ToolController* tool(int number) const;
};

}  // namespace camwb::document
