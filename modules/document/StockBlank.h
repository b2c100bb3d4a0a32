// The job's stock as the solid it is: a blank (a cast or forged part, Stock::Shape::Blank) read
// from its mesh or STEP file into work coordinates, and what the simulator cuts for each stock
// shape (a box, a cylinder, a blank), shared by camwb-cli sim, the setup sheet and the dock.
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "sim/Simulation.h"
#include "sim/TriangleMesh.h"

#include <optional>
#include <string>

namespace camwb::occ {
class Model;
}

namespace camwb::document {

// The blank's surface in work coordinates (its file's coordinates moved by -job.origin, as the
// model is). An error names `jobPath` and the field ("stock.blank") with the file that is missing
// or cannot be read.
base::Result<sim::TriangleMesh> loadStockBlank(const Job& job, const std::string& jobPath);

// A blank stock's min/max become the bounds of `blank` (loadStockBlank's); other stocks are left.
void resolveStockBlank(Stock& stock, const sim::TriangleMesh& blank);

// What the simulator cuts for the job: its box, a cylinder as a cylinder (sim::cylinderMesh), a
// blank as its mesh (`blank`, from loadStockBlank; empty for the other shapes). A job without a
// stock box cuts the model's bounds (jobStockBox). `resolutionMm` <= 0: defaultStockResolution.
// The design model to compare with is the caller's to add.
sim::StockSpec jobStockSpec(const Job& job, const occ::Model& model, const sim::TriangleMesh& blank,
                            double resolutionMm);

}  // namespace camwb::document
