// Loads one of the program's own libraries the first time a command needs it: the parts that
// bring large libraries only some commands use (OCCT for models, Qt Qml for the post scripts, Qt
// Gui for the setup sheet's pictures), so that every other command starts without loading and
// relocating them. A library exports one C function returning a table of entry points that starts
// with its ABI number; camwb_add_plugin (cmake/CamwbModule.cmake) builds it.
#pragma once

#include "base/Result.h"

#include <string>
#include <type_traits>

namespace camwb::base {

struct PluginPlace {
    std::string name;         // for messages: "the OCCT kernel"
    std::string role;         // for messages: "libcamwb_occ_kernel.so reads and writes models"
    const char* envVariable;  // names another library when set
    std::string fromBinDir;   // where the package installs it, relative to the program's folder
    std::string built;        // where the build put it
};

// The table of the first of the places that exists (the variable's alone when it is set), with
// `abi` as its first member. Errors name every place looked at, or why the library was refused.
// Never unloaded: the objects it makes live as long as the program.
Result<const void*> loadPluginTable(const PluginPlace& place, const char* entryPoint, int abi);

template <class Table> Result<const Table*> loadPlugin(const PluginPlace& place, const char* entryPoint, int abi)
{
    static_assert(std::is_standard_layout_v<Table> && std::is_same_v<decltype(Table::abi), int>,
                  "a plugin's table starts with its int abi");
    Result<const void*> table = loadPluginTable(place, entryPoint, abi);
    if (!table)
        return table.error();
    return static_cast<const Table*>(table.value());
}

}  // namespace camwb::base
