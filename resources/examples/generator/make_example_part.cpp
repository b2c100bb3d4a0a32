// camwb-make-example: writes a bundled teaching part as a STEP file: the three-axis block
// (occ::writeExamplePart, resources/examples/example-block.step), with "five-axis" the part with
// inclined faces (occ::writeFiveAxisExamplePart, resources/examples/example-five-axis.step), with
// "mould" the drafted cavity (occ::writeMouldExamplePart, resources/examples/example-mould.step).
#include "occ/ExamplePart.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
    const char* kind = argc == 3 ? argv[2] : "";
    const bool fiveAxis = std::strcmp(kind, "five-axis") == 0, mould = std::strcmp(kind, "mould") == 0;
    if (argc != 2 && !fiveAxis && !mould) {
        std::fprintf(stderr, "usage: camwb-make-example <out.step> [five-axis|mould]\n");
        return 2;
    }
    const camwb::base::Status status = fiveAxis ? camwb::occ::writeFiveAxisExamplePart(argv[1])
                                       : mould  ? camwb::occ::writeMouldExamplePart(argv[1])
                                                : camwb::occ::writeExamplePart(argv[1]);
    if (!status) {
        std::fprintf(stderr, "camwb-make-example: %s\n", status.error().toString().c_str());
        return 1;
    }
    return 0;
}
