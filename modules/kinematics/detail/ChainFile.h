// The "kinematics" object of a machine file (format version 2): read into a KinematicChain and
// checked against the machine's axes. Used by MachineFile.cpp only.
#pragma once

#include "base/JsonRead.h"
#include "kinematics/Machine.h"

namespace camwb::kinematics::detail {

// Throws base::jsonread::JsonFieldError naming the field at fault.
KinematicChain readKinematicChain(const base::jsonread::Json& object, const std::string& where, const Machine& machine);

}  // namespace camwb::kinematics::detail
