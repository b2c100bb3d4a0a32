// VTK actors of the job setup in the 3D view: the stock, translucent (a box, a cylinder along
// Z inside its box, or a blank's solid), a lathe job's half-section in the XZ plane, and the work coordinate system's
// axes at the program zero.
// Private to gui/view3d.
#pragma once

#include "base/Vec.h"
#include "gui/view3d/View3D.h"
#include "sim/TriangleMesh.h"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace camwb::gui {

vtkSmartPointer<vtkActor> makeStockActor(const base::Box3& box, bool cylinder);
// A blank stock's solid (its mesh), in the same translucent colour.
vtkSmartPointer<vtkActor> makeStockActor(const sim::TriangleMesh& solid);
// The stock's loops filled (translucent, in the stock's colour, a hair behind Y = 0 so that the
// lines on the plane stay in front of it) with their outlines, the part contour (dark) and the
// offset contour (blue). Points off the plane's finite range are left out.
std::vector<vtkSmartPointer<vtkActor>> makeLatheActors(const LatheSection& section);
// Axes of `length` mm at the origin (the view shows work coordinates), labelled X, Y, Z.
vtkSmartPointer<vtkAxesActor> makeWorkAxes(double length);

}  // namespace camwb::gui
