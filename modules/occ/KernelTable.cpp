// The OCCT kernel's one exported symbol: the table of its entry points that Kernel.cpp looks up
// after loading the library (occ/detail/ModelImpl.h).
#include "occ/detail/ModelData.h"

extern "C" __attribute__((visibility("default"))) const camwb::occ::KernelTable* camwb_occ_kernel_table()
{
    using namespace camwb::occ;
    static const KernelTable table{kKernelAbi,
                                   &occt::load,
                                   &occt::writeExamplePart,
                                   &occt::writeFiveAxisExamplePart,
                                   &occt::writeFiveAxisExampleBlank,
                                   &occt::writeMouldExamplePart};
    return &table;
}
