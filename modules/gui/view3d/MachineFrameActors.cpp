#include "gui/view3d/detail/MachineFrameActors.h"

#include "gui/view3d/detail/ModelActors.h"

#include <vtkCellArray.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

#include <cmath>

namespace camwb::gui {

namespace {

constexpr int kSides = 96;
constexpr double kTableColor[3]{0.42, 0.45, 0.50};
constexpr double kMarkColor[3]{0.95, 0.45, 0.05};

vtkSmartPointer<vtkActor> finish(vtkPolyData* data, const double color[3])
{
    auto actor = makeActor(data);
    actor->GetMapper()->ScalarVisibilityOff();
    actor->GetProperty()->SetColor(color[0], color[1], color[2]);
    actor->PickableOff();
    return actor;
}

}  // namespace

std::vector<vtkSmartPointer<vtkActor>> makeTableActors(const RotaryTable& table)
{
    const base::Vec3 n = table.normal;
    const base::Vec3 u = table.zero;
    const base::Vec3 v = n.cross(u);
    const double r = table.radiusMm;
    auto at = [&](double radius, double angle, double up) {
        return table.centre + u * (radius * std::cos(angle)) + v * (radius * std::sin(angle)) + n * up;
    };

    // The disc: top ring (its top face at the stock's bottom), bottom ring, both caps, the side.
    vtkNew<vtkPoints> points;
    for (double up : {0.0, -table.thicknessMm})
        for (int s = 0; s < kSides; ++s) {
            const base::Vec3 p = at(r, 2 * M_PI * s / kSides, up);
            points->InsertNextPoint(p.x, p.y, p.z);
        }
    vtkNew<vtkCellArray> polys;
    polys->InsertNextCell(kSides);
    for (int s = 0; s < kSides; ++s)
        polys->InsertCellPoint(s);
    polys->InsertNextCell(kSides);
    for (int s = kSides - 1; s >= 0; --s)
        polys->InsertCellPoint(kSides + s);
    for (int s = 0; s < kSides; ++s) {
        const vtkIdType a = s, b = (s + 1) % kSides;
        const vtkIdType quad[4]{a, a + kSides, b + kSides, b};
        polys->InsertNextCell(4, quad);
    }
    vtkNew<vtkPolyData> disc;
    disc->SetPoints(points);
    disc->SetPolys(polys);

    // The mark: a flat arrow on the top face's rim pointing out along C = 0, standing a little
    // above the face so that it is seen from the side and never fights the face's pixels.
    const double length = 0.3 * r, half = 0.06 * r, height = std::max(0.02 * r, 0.5);
    const base::Vec3 tipPoint = table.centre + u * r;
    const base::Vec3 back = table.centre + u * (r - length);
    const base::Vec3 outline[3]{tipPoint, back + v * half, back - v * half};
    vtkNew<vtkPoints> markPoints;
    for (double up : {height, 0.0})
        for (const base::Vec3& p : outline) {
            const base::Vec3 q = p + n * up;
            markPoints->InsertNextPoint(q.x, q.y, q.z);
        }
    vtkNew<vtkCellArray> markPolys;
    const vtkIdType top[3]{0, 1, 2};
    markPolys->InsertNextCell(3, top);
    for (vtkIdType s = 0; s < 3; ++s) {
        const vtkIdType side[4]{s, s + 3, (s + 1) % 3 + 3, (s + 1) % 3};
        markPolys->InsertNextCell(4, side);
    }
    vtkNew<vtkPolyData> mark;
    mark->SetPoints(markPoints);
    mark->SetPolys(markPolys);
    return {finish(disc, kTableColor), finish(mark, kMarkColor)};
}

vtkSmartPointer<vtkMatrix4x4> userMatrix(const kinematics::RigidMotion& motion)
{
    if (motion.rotation == kinematics::RigidMotion{}.rotation && motion.translation.x == 0 &&
        motion.translation.y == 0 && motion.translation.z == 0)
        return nullptr;
    auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
    const double t[3]{motion.translation.x, motion.translation.y, motion.translation.z};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c)
            matrix->SetElement(r, c, motion.rotation[static_cast<std::size_t>(3 * r + c)]);
        matrix->SetElement(r, 3, t[r]);
    }
    return matrix;
}

}  // namespace camwb::gui
