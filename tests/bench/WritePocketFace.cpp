// camwb-pocket-face <file.json> [offset|zigzag]: writes the pocket benchmark's face (1000-segment
// wavy outline, 20 islands) and its parameters as JSON, so that FreeCAD's pocket runs on exactly
// the face our benchmark pockets (tests/bench/peers/freecad_pocket_face.py, scripts/bench-pocket.sh).
#include "PocketBenchFace.h"

#include "base/AtomicFile.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: camwb-pocket-face <file.json> [offset|zigzag]\n");
        return 2;
    }
    using camwb::ops::PocketPattern;
    const PocketPattern pattern =
        argc == 3 && std::strcmp(argv[2], "zigzag") == 0 ? PocketPattern::ZigZag : PocketPattern::Offset;
    const camwb::geom::Region face = camwb::bench::pocketBenchFace();
    const std::string json =
        camwb::bench::pocketBenchJson(face, camwb::bench::pocketBenchParams(pattern), camwb::bench::pocketBenchTool());
    if (auto written = camwb::base::writeFileAtomically(argv[1], json); !written) {
        std::fprintf(stderr, "camwb-pocket-face: %s\n", written.error().toString().c_str());
        return 1;
    }
    std::size_t arcs = 0;
    for (const auto& s : face.outer.segments)
        arcs += s.isArc();
    std::printf("outer: %zu segments (%zu arcs, %zu lines); islands: %zu\n", face.outer.segments.size(), arcs,
                face.outer.segments.size() - arcs, face.holes.size());
    return 0;
}
