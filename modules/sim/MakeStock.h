// The stock a simulation cuts, chosen for its program: a height field where every tool stays
// vertical (exact per column and the cheapest), tri-dexels where one tilts or cuts from the side.
// Before one is made its size is weighed against the computer's memory: a fine resolution on a
// large plate would otherwise take the program down with everything unsaved in it.
#pragma once

#include "sim/Stock.h"

#include <optional>
#include <string>

namespace camwb::sim {

std::unique_ptr<Stock> makeStock(const base::Box3& box, double resolutionMm, bool tilts);
// A cast or forged blank filled from its mesh's inside.
std::unique_ptr<Stock> makeStockFromMesh(const TriangleMesh& blank, double resolutionMm, bool tilts);
// Whether any cutting move of `moves` has its tool off the vertical (then makeStock needs tilts).
bool anyToolTilts(const MoveList& moves);

// What a stock of `resolutionMm` cells over `box` holds: columns of a height field, or rays of the
// three tri-dexel grids (`tilts`), and about how much memory it takes at most with its meshes.
struct StockSize {
    double cells = 0;
    double bytes = 0;
};
StockSize stockSize(const base::Box3& box, double resolutionMm, bool tilts);
// No machine holds a workpiece reaching farther than this from its origin (100 m): a stock that
// does is a typo or a unit mix-up, and its cells' heights (floats) would lose the resolution.
constexpr double kStockReachMm = 1e5;
// Why `box` is no workpiece (a side or corner beyond kStockReachMm, naming which); nothing when it is.
std::optional<std::string> stockBeyondReach(const base::Box3& box);
// The memory a stock may take: half of the computer's physical memory.
double stockMemoryBudget();
// Why such a stock cannot be made within `budgetBytes`, naming the finest resolution that fits;
// nothing when it can.
std::optional<std::string> stockTooLarge(const base::Box3& box, double resolutionMm, bool tilts, double budgetBytes);

}  // namespace camwb::sim
