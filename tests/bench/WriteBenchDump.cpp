// camwb-bench-dump <moves> <file.dump|file.apt>: writes the benchmark program as a FreeCAD path
// dump, so that FreeCAD's posts and ours post the same CL side by side (scripts/bench-posts.sh),
// or as APT CL source for the importer benchmark.
#include "BenchProgram.h"

#include "base/AtomicFile.h"

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: camwb-bench-dump <moves> <file.dump|file.apt>\n");
        return 2;
    }
    const long moves = std::strtol(argv[1], nullptr, 10);
    if (moves <= 0) {
        std::fprintf(stderr, "camwb-bench-dump: moves must be a positive number\n");
        return 2;
    }
    const std::string path = argv[2];
    const bool apt = path.size() > 4 && path.substr(path.size() - 4) == ".apt";
    const camwb::toolpath::Toolpath program = camwb::bench::benchProgram(static_cast<std::size_t>(moves));
    const std::string text = apt ? camwb::bench::asAptSource(program) : camwb::bench::asFreeCadDump(program);
    if (auto written = camwb::base::writeFileAtomically(path, text); !written) {
        std::fprintf(stderr, "camwb-bench-dump: %s\n", written.error().toString().c_str());
        return 1;
    }
    return 0;
}
