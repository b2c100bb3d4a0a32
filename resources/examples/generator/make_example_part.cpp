// camwb-make-example: writes the bundled teaching part (occ::writeExamplePart) as a STEP file.
// Used to regenerate resources/examples/example-block.step.
#include "occ/ExamplePart.h"

#include <cstdio>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: camwb-make-example <out.step>\n");
        return 2;
    }
    const camwb::base::Status status = camwb::occ::writeExamplePart(argv[1]);
    if (!status) {
        std::fprintf(stderr, "camwb-make-example: %s\n", status.error().toString().c_str());
        return 1;
    }
    return 0;
}
