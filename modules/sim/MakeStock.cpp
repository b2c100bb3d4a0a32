#include "sim/MakeStock.h"

#include "base/NumberFormat.h"
#include "sim/HeightField.h"
#include "sim/TriDexel.h"

#include <cmath>

#include <unistd.h>

namespace camwb::sim {

namespace {

// Bytes a cell takes at most, measured as the growth of `camwb-cli sim`'s peak memory between two
// resolutions: the example job's height field (0.05 to 0.025 mm) 25 bytes a column (top, bottom,
// last cut, the design's heights; a block without a design holds its tops only) and 54 with --stl; the five-axis
// example's tri-dexels (0.25 to 0.125 mm) 300 bytes a ray (a vector of spans per ray, the blank's and the design's
// spans) and 460 with --stl (four unshared vertices per face). The simulator dock holds two stocks (the start and the
// one cut) and the mesh twice (its own and the view's, with 64-bit indices).
constexpr double kHeightFieldBytesPerColumn = 160;
constexpr double kTriDexelBytesPerRay = 800;

std::string gigabytes(double bytes) { return base::formatFixed(bytes / 1e9, 1) + " GB"; }

}  // namespace

StockSize stockSize(const base::Box3& box, double resolutionMm, bool tilts)
{
    const double nx = cellsAcross(box.max.x - box.min.x, resolutionMm);
    const double ny = cellsAcross(box.max.y - box.min.y, resolutionMm);
    if (!tilts)
        return {nx * ny, nx * ny * kHeightFieldBytesPerColumn};
    const double nz = cellsAcross(box.max.z - box.min.z, resolutionMm);
    const double rays = nx * ny + ny * nz + nz * nx;
    return {rays, rays * kTriDexelBytesPerRay};
}

double stockMemoryBudget()
{
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0)
        return 4e9;  // not known: what a small desktop can spare
    return 0.5 * double(pages) * double(pageSize);
}

std::optional<std::string> stockBeyondReach(const base::Box3& box)
{
    const char* axes = "xyz";
    for (int a = 0; a < 3; ++a)
        for (const auto& [corner, end] : {std::pair{box.min, "minimum"}, std::pair{box.max, "maximum"}}) {
            const double v = a == 0 ? corner.x : a == 1 ? corner.y : corner.z;
            if (!(std::abs(v) <= kStockReachMm))  // the value itself may be 300 digits long: not shown
                return std::string("the stock reaches more than 100 m from the workpiece origin (its ") + axes[a] +
                       " " + end + "): no machine holds such a workpiece; check the stock's numbers and units";
        }
    return std::nullopt;
}

std::optional<std::string> stockTooLarge(const base::Box3& box, double resolutionMm, bool tilts, double budgetBytes)
{
    const StockSize size = stockSize(box, resolutionMm, tilts);
    if (size.bytes <= budgetBytes)
        return std::nullopt;
    // The finest resolution that fits: from the area per cell the budget allows, then up a finest cell at
    // a time (cellsAcross rounds the count of cells up).
    const Vec3 d = box.max - box.min;
    const double area = tilts ? d.x * d.y + d.y * d.z + d.z * d.x : d.x * d.y;
    const double perCell = tilts ? kTriDexelBytesPerRay : kHeightFieldBytesPerColumn;
    double finest =
        std::max(kFinestCellMm, std::ceil(std::sqrt(area * perCell / budgetBytes) / kFinestCellMm) * kFinestCellMm);
    for (int step = 0; step < 100000 && stockSize(box, finest, tilts).bytes > budgetBytes; ++step)
        finest += kFinestCellMm;
    const bool fits = stockSize(box, finest, tilts).bytes <= budgetBytes;
    return std::string(tilts ? "the tri-dexel" : "the height field") + " stock of " + base::formatFixed(d.x, 1) +
           " x " + base::formatFixed(d.y, 1) + " x " + base::formatFixed(d.z, 1) + " mm at " +
           (resolutionMm >= kFinestCellMm ? base::formatFixed(resolutionMm, 4) + " mm"
                                          : base::formatFixed(kFinestCellMm, 3) + " mm (no cell is finer)") +
           " would have " + base::formatFixed(size.cells / 1e6, 1) + " million " + (tilts ? "rays" : "columns") +
           " and need about " + gigabytes(size.bytes) + " of memory, more than the " + gigabytes(budgetBytes) +
           " a stock may take here (half the computer's memory)" +
           (fits ? "; the finest resolution that fits is " + base::formatFixed(finest, 3) + " mm" : "") +
           ": choose a coarser resolution";
}

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
        if (m.moves() && (tilted(m.fromAxis()) || tilted(m.toAxis())))
            return true;
    return false;
}

}  // namespace camwb::sim
