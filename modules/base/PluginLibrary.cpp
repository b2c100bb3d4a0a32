#include "base/PluginLibrary.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

namespace camwb::base {
namespace {

std::vector<std::filesystem::path> candidates(const PluginPlace& place)
{
    if (const char* chosen = std::getenv(place.envVariable); chosen && *chosen)
        return {chosen};
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec)
        out.push_back((program.parent_path() / place.fromBinDir).lexically_normal());
    out.emplace_back(place.built);
    return out;
}

}  // namespace

Result<const void*> loadPluginTable(const PluginPlace& place, const char* entryPoint, int abi)
{
    const std::vector<std::filesystem::path> places = candidates(place);
    auto found = std::find_if(places.begin(), places.end(), [](const std::filesystem::path& candidate) {
        std::error_code ec;
        return std::filesystem::exists(candidate, ec);
    });
    if (found == places.end()) {
        std::string looked;
        for (const std::filesystem::path& candidate : places)
            looked += (looked.empty() ? "" : " nor at ") + candidate.string();
        return makeError(place.name + " is not at " + looked + " (" + place.role + "; " + place.envVariable +
                         " may name where it is)");
    }
    const std::filesystem::path& path = *found;
    auto failed = [&](const std::string& why) {
        return makeError(place.name + " " + path.string() + " could not be loaded: " + why);
    };
    // Its symbols are looked up among the program's libraries first, which makes loading a large
    // one slower than linking it was (docs/benchmarks.md). RTLD_DEEPBIND would look among its own
    // first, but then OCCT bound to libstdc++'s own std::cout instead of the program's copy (a copy
    // relocation), which was never constructed: the tests crashed in OCCT's message printer.
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        // dlerror() starts with the path, which the message names already.
        std::string why = dlerror();
        if (why.rfind(path.string() + ": ", 0) == 0)
            why.erase(0, path.string().size() + 2);
        return failed(why);
    }
    using Entry = const void* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(library, entryPoint));
    if (!entry)
        return failed(std::string("it has no entry point ") + entryPoint);
    const void* table = entry();
    const int built = table ? *static_cast<const int*>(table) : 0;  // the table's first member
    if (built != abi)
        return failed("it was built for another version of the program (ABI " + std::to_string(built) + ", expected " +
                      std::to_string(abi) + ")");
    return table;
}

}  // namespace camwb::base
