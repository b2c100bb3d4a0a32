// The pocket benchmark's face and parameters, shared by the Google Benchmark (PocketBench.cpp)
// and camwb-pocket-face, which writes the same face as JSON for FreeCAD's side of the comparison
// (tests/bench/peers/freecad_pocket_face.py, scripts/bench-pocket.sh). Deterministic: no random
// numbers, so both sides and every run see the same 1000-segment outline and 20 islands.
#pragma once

#include "geom/Region.h"
#include "ops/OpCommon.h"
#include "ops/PocketOp.h"

#include <string>

namespace camwb::bench {

// A 200 x 150 mm rounded rectangle whose sides wave (about 0.6 mm deep, 5 mm period) in tangent
// arcs and short lines: exactly 1000 segments, counter-clockwise. Inside it 20 islands in a 5 x 4
// grid, clockwise: circles D6..D14 and rotated rounded rectangles, at least 12 mm from the wall
// and from each other, so that a D6 tool reaches everywhere between them.
geom::Region pocketBenchFace();

// Tool D6 flat end mill, 2 flutes, 25 mm flute length; feeds for the record only.
ops::ToolController pocketBenchTool();

// Stepover 1 mm, `levels` equal levels from Z 0 down (step-down 1: the benchmark's 10 levels end
// at Z -10), helix entry, no stock.
ops::PocketParams pocketBenchParams(ops::PocketPattern pattern, int levels = 10);

// The face and the parameters as JSON: {"toolDiameterMm", "stepoverMm", "startZ", "finalZ",
// "stepDownMm", "toleranceMm", "areaMm2", "loops": [{"role": "outer"|"island", "segments":
// [{"kind": "line"|"arc", "start": [x, y], "end": [x, y], "centre": [x, y], "ccw": bool}]}]}.
std::string pocketBenchJson(const geom::Region& face, const ops::PocketParams& params, const ops::ToolController& tc);

}  // namespace camwb::bench
