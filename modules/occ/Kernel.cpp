// Finds and loads the OCCT kernel (libcamwb_occ_kernel.so) the first time a model is read or an
// example part written. Linked into the programs, OCCT's 21 libraries were loaded and relocated at
// every start, also by the commands that read no model (simulating or posting a program, tracing
// NC): `camwb-cli --version` took 42.7 ms, and 9.8 ms without them (docs/benchmarks.md).
#include "occ/detail/ModelImpl.h"

#include "occ/ExamplePart.h"

#include "base/PluginLibrary.h"

namespace camwb::occ {

base::Result<const KernelTable*> kernel()
{
    // Installed beside the program (`bin/../<libdir>/camwb/`, `/usr/lib/camwb/` in the package), or
    // where it was built for a program run from the build tree.
    static const base::Result<const KernelTable*> loaded =
        base::loadPlugin<KernelTable>({"the OCCT kernel", "libcamwb_occ_kernel.so reads and writes models",
                                       "CAMWB_OCC_KERNEL", CAMWB_OCC_KERNEL_FROM_BINDIR, CAMWB_OCC_KERNEL_BUILT},
                                      kKernelEntryPoint, kKernelAbi);
    return loaded;
}

// The example parts are built with OCCT, so the kernel writes them (ExamplePart.h).
namespace {

base::Status writeWithKernel(base::Status (*KernelTable::*writer)(const std::string&), const std::string& stepPath)
{
    const base::Result<const KernelTable*> loaded = kernel();
    if (!loaded)
        return base::makeError(loaded.error().message, stepPath);
    return (loaded.value()->*writer)(stepPath);
}

}  // namespace

base::Status writeExamplePart(const std::string& stepPath)
{
    return writeWithKernel(&KernelTable::writeExamplePart, stepPath);
}

base::Status writeFiveAxisExamplePart(const std::string& stepPath)
{
    return writeWithKernel(&KernelTable::writeFiveAxisExamplePart, stepPath);
}

base::Status writeFiveAxisExampleBlank(const std::string& stepPath)
{
    return writeWithKernel(&KernelTable::writeFiveAxisExampleBlank, stepPath);
}

base::Status writeMouldExamplePart(const std::string& stepPath)
{
    return writeWithKernel(&KernelTable::writeMouldExamplePart, stepPath);
}

}  // namespace camwb::occ
