// camwb-make-example: writes a bundled teaching part as a STEP file: the three-axis block
// (occ::writeExamplePart, resources/examples/example-block.step), with "five-axis" the part with
// inclined faces (occ::writeFiveAxisExamplePart, resources/examples/example-five-axis.step), with
// "mould" the drafted cavity (occ::writeMouldExamplePart, resources/examples/example-mould.step), with
// "five-axis-blank" the five-axis part's cast blank (occ::writeFiveAxisExampleBlank,
// resources/examples/example-five-axis-blank.step).
#include "occ/ExamplePart.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
    const char* kind = argc == 3 ? argv[2] : "";
    const bool fiveAxis = std::strcmp(kind, "five-axis") == 0, mould = std::strcmp(kind, "mould") == 0;
    const bool blank = std::strcmp(kind, "five-axis-blank") == 0;
    if (argc != 2 && !fiveAxis && !mould && !blank) {
        std::fprintf(stderr, "usage: camwb-make-example <out.step> [five-axis|five-axis-blank|mould]\n");
        return 2;
    }
    const camwb::base::Status status = fiveAxis ? camwb::occ::writeFiveAxisExamplePart(argv[1])
                                       : blank  ? camwb::occ::writeFiveAxisExampleBlank(argv[1])
                                       : mould  ? camwb::occ::writeMouldExamplePart(argv[1])
                                                : camwb::occ::writeExamplePart(argv[1]);
    if (!status) {
        std::fprintf(stderr, "camwb-make-example: %s\n", status.error().toString().c_str());
        return 1;
    }
    return 0;
}
