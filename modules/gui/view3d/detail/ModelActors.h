// VTK actors of the 3D view's model: shaded triangles (with each triangle's model face as the
// "face" cell array, for picking and the task panels' face selection) and feature edges.
// Private to gui/view3d.
#pragma once

#include "occ/DisplayMesh.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace camwb::gui {

inline constexpr double kModelColor[3]{0.80, 0.81, 0.83};

vtkSmartPointer<vtkActor> makeActor(vtkPolyData* data);
vtkSmartPointer<vtkActor> makeModelActor(const occ::DisplayMesh& mesh);  // null without triangles
vtkSmartPointer<vtkActor> makeEdgeActor(const occ::DisplayMesh& mesh);   // null without edges

}  // namespace camwb::gui
