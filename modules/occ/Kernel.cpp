// Finds and loads the OCCT kernel (libcamwb_occ_kernel.so) the first time a model is read or an
// example part written. Linked into the programs, OCCT's 21 libraries were loaded and relocated at
// every start, also by the commands that read no model (simulating or posting a program, tracing
// NC): `camwb-cli --version` took 42.7 ms, now 9.8 ms (docs/benchmarks.md).
#include "occ/detail/ModelImpl.h"

#include "occ/ExamplePart.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace camwb::occ {
namespace {

// The places the kernel may be: CAMWB_OCC_KERNEL when set; else installed beside the program
// (`bin/../<libdir>/camwb/`, `/usr/lib/camwb/` in the package) or, for a program run from the build
// tree, where it was built.
std::vector<std::filesystem::path> kernelCandidates()
{
    if (const char* chosen = std::getenv("CAMWB_OCC_KERNEL"); chosen && *chosen)
        return {chosen};
    std::vector<std::filesystem::path> candidates;
    std::error_code ec;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec)
        candidates.push_back((program.parent_path() / CAMWB_OCC_KERNEL_FROM_BINDIR).lexically_normal());
    candidates.emplace_back(CAMWB_OCC_KERNEL_BUILT);
    return candidates;
}

base::Result<const KernelTable*> loadKernel()
{
    const std::vector<std::filesystem::path> candidates = kernelCandidates();
    auto found = std::find_if(candidates.begin(), candidates.end(), [](const std::filesystem::path& candidate) {
        std::error_code ec;
        return std::filesystem::exists(candidate, ec);
    });
    if (found == candidates.end()) {
        std::string places;
        for (const std::filesystem::path& candidate : candidates)
            places += (places.empty() ? "" : " nor at ") + candidate.string();
        return base::makeError(
            "the OCCT kernel is not at " + places +
            " (libcamwb_occ_kernel.so reads and writes models; CAMWB_OCC_KERNEL may name where it is)");
    }
    const std::filesystem::path& path = *found;
    auto failed = [&](const std::string& why) {
        return base::makeError("the OCCT kernel " + path.string() + " could not be loaded: " + why);
    };
    // Never closed: models hold objects whose code lives in it. Its libraries' symbols are looked
    // up among the program's libraries first, which makes loading it slower than linking OCCT was
    // (docs/benchmarks.md). RTLD_DEEPBIND would look among its own first, but then OCCT binds to
    // libstdc++'s own std::cout instead of the program's copy (a copy relocation), which was never
    // constructed: the tests crashed in OCCT's message printer.
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        // dlerror() starts with the path, which the message names already.
        std::string why = dlerror();
        if (why.rfind(path.string() + ": ", 0) == 0)
            why.erase(0, path.string().size() + 2);
        return failed(why);
    }
    using Entry = const KernelTable* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(library, kKernelEntryPoint));
    if (!entry)
        return failed(std::string("it has no entry point ") + kKernelEntryPoint);
    const KernelTable* table = entry();
    if (!table || table->abi != kKernelAbi)
        return failed("it was built for another version of the program (kernel ABI " +
                      std::to_string(table ? table->abi : 0) + ", expected " + std::to_string(kKernelAbi) + ")");
    return table;
}

}  // namespace

base::Result<const KernelTable*> kernel()
{
    static const base::Result<const KernelTable*> loaded = loadKernel();
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
