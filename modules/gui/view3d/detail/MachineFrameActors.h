// VTK side of the simulator's machine frame (gui/sim/MachineFrame): the rotary table's actors (the
// disc and the mark at C = 0 that shows its turning) and the user matrix that moves the workpiece
// side. Private to gui (SimOverlay.cpp, View3D.cpp): VTK stays out of the headers others include.
#pragma once

#include "gui/sim/MachineFrame.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace camwb::gui {

// The disc first, then the mark; not pickable.
std::vector<vtkSmartPointer<vtkActor>> makeTableActors(const RotaryTable& table);
// A prop's user matrix for `motion`; null for the identity (VTK then skips the multiplication).
// A new matrix each time: VTK sees a new user matrix, not one changed behind its back.
vtkSmartPointer<vtkMatrix4x4> userMatrix(const kinematics::RigidMotion& motion);

}  // namespace camwb::gui
