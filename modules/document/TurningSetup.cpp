#include "document/TurningSetup.h"

#include "geom/RegionOps.h"
#include "sim/TurningProfile.h"

namespace camwb::document {

namespace {
constexpr double kTolerance = 1e-6;
}

sim::Insert grooveInsert(const toolpath::Tool& tool)
{
    sim::Insert insert;
    insert.widthMm = tool.diameterMm;
    insert.cornerRadiusMm = tool.cornerRadiusMm;
    return insert;
}

std::optional<TurningSetup> turningSetup(const Job& job)
{
    std::vector<sim::GrooveParameters> grooves;
    std::optional<TurningSetup> setup;
    for (const Operation& op : job.operations) {
        const auto* groove = std::get_if<ops::GrooveParams>(&op.params);
        if (!groove || !op.enabled)
            continue;
        grooves.push_back(groove->groove);
        const ops::ToolController* tc = job.tool(op.toolNumber);
        if (tc)
            grooves.back().r9 = tc->tool.diameterMm;  // the file keeps the width on the tool
        if (!setup) {
            setup.emplace();
            if (tc)
                setup->insert = grooveInsert(tc->tool);
        }
    }
    if (grooves.size() == 1) {  // exactly the profiles of sim/TurningProfile.h
        setup->stock = sim::grooveStock(grooves.front());
        setup->design = sim::grooveOffsetPart(grooves.front());
        return setup;
    }
    // Several grooves: one shaft (their shafts united) less every groove's offset contour.
    sim::TurningRegion removed;
    for (const sim::GrooveParameters& g : grooves) {
        sim::TurningRegion stock = sim::grooveStock(g);
        const sim::TurningRegion cut = geom::subtract(stock, sim::grooveOffsetPart(g), kTolerance);
        removed = removed.empty() ? cut : geom::unite(removed, cut, kTolerance);
        setup->stock = setup->stock.empty() ? std::move(stock) : geom::unite(setup->stock, stock, kTolerance);
    }
    if (setup)
        setup->design = geom::subtract(setup->stock, removed, kTolerance);
    return setup;
}

}  // namespace camwb::document
