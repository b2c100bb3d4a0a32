// The stock a simulation cuts, chosen for its program: a height field where every tool stays
// vertical (exact per column and the cheapest), tri-dexels where one tilts or cuts from the side.
#pragma once

#include "sim/Stock.h"

namespace camwb::sim {

std::unique_ptr<Stock> makeStock(const base::Box3& box, double resolutionMm, bool tilts);
// A cast or forged blank filled from its mesh's inside.
std::unique_ptr<Stock> makeStockFromMesh(const TriangleMesh& blank, double resolutionMm, bool tilts);
// Whether any cutting move of `moves` has its tool off the vertical (then makeStock needs tilts).
bool anyToolTilts(const MoveList& moves);

}  // namespace camwb::sim
