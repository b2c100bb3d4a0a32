#include "sim/MakeStock.h"

#include "sim/HeightField.h"
#include "sim/TriDexel.h"

#include <cmath>

namespace camwb::sim {

std::unique_ptr<Stock> makeStock(const base::Box3& box, double resolutionMm, bool tilts)
{
    if (tilts)
        return std::make_unique<TriDexel>(box, resolutionMm);
    return std::make_unique<HeightField>(box, resolutionMm);
}

std::unique_ptr<Stock> makeStockFromMesh(const TriangleMesh& blank, double resolutionMm, bool tilts)
{
    if (tilts)
        return TriDexel::fromMesh(blank, resolutionMm);
    return HeightField::fromMesh(blank, resolutionMm);
}

bool anyToolTilts(const MoveList& moves)
{
    auto tilted = [](const Vec3& a) { return std::abs(a.x) > 1e-9 || std::abs(a.y) > 1e-9 || a.z <= 0; };
    for (const Move& m : moves.moves)
        if (m.moves() && (tilted(m.fromAxis) || tilted(m.toAxis)))
            return true;
    return false;
}

}  // namespace camwb::sim
