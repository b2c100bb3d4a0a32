// A lathe job's turning setup for the simulator and the setup sheet: the shaft before turning
// and the contour that must stay, both revolved profiles in XZ (X a radius) built from the job's
// groove operations (sim::grooveStock, sim::grooveOffsetPart), and the insert they cut with.
#pragma once

#include "document/Job.h"
#include "sim/TurningStock.h"

#include <optional>

namespace camwb::document {

struct TurningSetup {
    sim::TurningRegion stock;   // the shaft: every groove's shaft united
    sim::TurningRegion design;  // the shaft less each groove's offset contour (allowances stay)
    sim::Insert insert;         // the first groove operation's tool: width = its diameter
};

// None when the job has no enabled groove operation.
std::optional<TurningSetup> turningSetup(const Job& job);

// A grooving tool as the turning simulation's insert (width = diameter, its corner radius).
sim::Insert grooveInsert(const toolpath::Tool& tool);

}  // namespace camwb::document
