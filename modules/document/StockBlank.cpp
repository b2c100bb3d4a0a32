#include "document/StockBlank.h"

#include "document/Simulate.h"
#include "occ/Model.h"

namespace camwb::document {

base::Result<sim::TriangleMesh> loadStockBlank(const Job& job, const std::string& jobPath)
{
    if (job.stock.shape != Stock::Shape::Blank)
        return sim::TriangleMesh{};
    const std::string where = "stock.blank";
    if (job.stock.blankPath.empty())
        return base::makeError(where + ": the blank stock names no file", jobPath);
    auto blank = occ::Model::load(job.stock.blankPath);
    if (!blank)
        return base::makeError(where + ": cannot read the blank " + blank.error().toString(), jobPath);
    sim::TriangleMesh mesh = designMesh(blank.value());
    if (mesh.empty())
        return base::makeError(where + ": the blank " + job.stock.blankPath + " has no surface", jobPath);
    // Moved as the model is (loadJobModel): the origin is in the files' coordinates.
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        mesh.positions[3 * i] -= static_cast<float>(job.origin.x);
        mesh.positions[3 * i + 1] -= static_cast<float>(job.origin.y);
        mesh.positions[3 * i + 2] -= static_cast<float>(job.origin.z);
    }
    return mesh;
}

void resolveStockBlank(Stock& stock, const sim::TriangleMesh& blank)
{
    if (stock.shape != Stock::Shape::Blank || blank.empty())
        return;
    const base::Box3 bounds = blank.bounds();
    stock.min = bounds.min;
    stock.max = bounds.max;
}

sim::StockSpec jobStockSpec(const Job& job, const occ::Model& model, const sim::TriangleMesh& blank,
                            double resolutionMm)
{
    sim::StockSpec spec;
    const base::Box3 box = jobStockBox(job, model);
    if (job.stock.shape == Stock::Shape::Blank && !blank.empty())
        spec.blank = blank;
    else if (job.stock.shape == Stock::Shape::Cylinder && job.stock.box())
        spec.blank = sim::cylinderMesh(box);
    else
        spec.box = box;
    spec.resolutionMm = resolutionMm > 0 ? resolutionMm : defaultStockResolution(box);
    return spec;
}

}  // namespace camwb::document
