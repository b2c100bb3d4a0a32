// Shared by the helix and drilling tests: generated hole sets, a tool controller, progress and
// cancel checks and small geometry helpers (golden traces: ../support/OpsGolden.h).
#pragma once

#include "../support/OpsGolden.h"
#include "geom/Hole.h"
#include "ops/OpCommon.h"

#include <functional>
#include <random>
#include <string>
#include <vector>

namespace camwb::ops::test {

// Holes with random centres (none overlapping), diameters in [minDiameter, maxDiameter], tops in
// [-5, 5], depths in [0.2, 25]; about half of them through.
std::vector<geom::Hole> randomHoles(std::mt19937& random, int count, double minDiameter, double maxDiameter);

ToolController toolController(double diameterMm);

// The hole `p` is in (or nearest to, by distance from its wall; the holes do not overlap).
const geom::Hole& holeAround(const std::vector<geom::Hole>& holes, base::Vec2 p);

// Runs `compute` with a progress that records its reports: one per hole and 1 at the end; then
// again with cancel set, which must fail with "<what>: cancelled".
void expectProgressAndCancel(const std::function<base::Result<OpResult>(const Progress&)>& compute,
                             std::size_t holeCount, const std::string& what);

double uniform(std::mt19937& random, double low, double high);

}  // namespace camwb::ops::test
