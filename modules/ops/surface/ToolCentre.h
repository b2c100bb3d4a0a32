// Where the tool centre may stand at a level without touching the part: the complement of the
// model's material at and above the level, grown by the tool's true shape (the radius at which its
// lower surface reaches each height above the tip: a flat end mill its full radius at once, a ball
// or bull-nose less near the tip) and by the stock to leave (side radially, bottom axially): the
// area z-level roughing clears at each level.
#pragma once

#include "geom/Region.h"
#include "ops/OpCommon.h"
#include "ops/surface/SurfaceInput.h"
#include "sim/TriangleMesh.h"
#include "toolpath/ClRecords.h"

#include <memory>
#include <vector>

namespace camwb::ops::surface {

class MeshShadow;

struct ToolCentreSettings {
    double sideStockMm = 0;
    double bottomStockMm = 0;
    double toleranceMm = 0.01;
};

// Built once per operation (the model's material sorted by height), asked per level.
class ToolCentreRegions {
public:
    ToolCentreRegions(const sim::TriangleMesh& model, const toolpath::Tool& tool, const ToolCentreSettings& settings);
    ~ToolCentreRegions();

    // Where the tool centre with the tip at `z` stays clear of the model (grown by the stocks),
    // within `area` (the stock or the boundary the tool centre may use).
    std::vector<geom::Region> at(double z, const std::vector<geom::Region>& area) const;
    // The model's material as the tool sees it at `z`: the tool centre must stay outside.
    std::vector<geom::Region> obstacle(double z) const;
    // How far above its tip the cutter reaches its full radius (0: a flat end mill; a ball's radius,
    // a bull-nose's corner radius).
    double fullRadiusHeightMm() const;

private:
    struct Data;
    std::unique_ptr<Data> m_data;
};

// Where the tool centre may go: the boundary, else the stock box seen from above.
std::vector<geom::Region> toolCentreArea(const SurfaceInput& input);
// The model and the area are there ("3D pocket \"P\": no model to rough ..."; `verb`: "rough").
base::Status checkSurfaceInput(const std::string& what, const SurfaceInput& input, const std::string& verb);

}  // namespace camwb::ops::surface
