// VTK actors of the job setup in the 3D view: the stock, translucent (a box, or a cylinder along
// Z inside its box), and the work coordinate system's axes at the program zero.
// Private to gui/view3d.
#pragma once

#include "base/Vec.h"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkSmartPointer.h>

namespace camwb::gui {

vtkSmartPointer<vtkActor> makeStockActor(const base::Box3& box, bool cylinder);
// Axes of `length` mm at the origin (the view shows work coordinates), labelled X, Y, Z.
vtkSmartPointer<vtkAxesActor> makeWorkAxes(double length);

}  // namespace camwb::gui
