// camwb-make-example: writes a bundled teaching part as a STEP file: the three-axis block
// (occ::writeExamplePart, resources/examples/example-block.step) or, with "five-axis", the part
// with inclined faces (occ::writeFiveAxisExamplePart, resources/examples/example-five-axis.step).
#include "occ/ExamplePart.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
    const bool fiveAxis = argc == 3 && std::strcmp(argv[2], "five-axis") == 0;
    if (argc != 2 && !fiveAxis) {
        std::fprintf(stderr, "usage: camwb-make-example <out.step> [five-axis]\n");
        return 2;
    }
    const camwb::base::Status status =
        fiveAxis ? camwb::occ::writeFiveAxisExamplePart(argv[1]) : camwb::occ::writeExamplePart(argv[1]);
    if (!status) {
        std::fprintf(stderr, "camwb-make-example: %s\n", status.error().toString().c_str());
        return 1;
    }
    return 0;
}
