// Where CAM Workbench looks for data files of one kind (posts, machines): folders from an
// environment variable, the user's folder, the installed share folder and, for runs from the
// build tree, the source tree. Earlier folders win, so a user's file overrides a built-in one.
#pragma once

#include <string>
#include <vector>

namespace camwb::base {

struct DataDir {
    std::string path;
    bool builtIn = false;  // shipped with CAM Workbench (installed or source tree), not the user's
};

// `envVariable` (':'-separated), ~/.local/share/camwb/<kind>, <prefix>/share/camwb/<kind> (next to
// the running executable) and <source tree>/<sourceSubdir>. Missing folders are listed too, so a
// failed lookup can say where it looked.
std::vector<DataDir> dataDirs(const char* envVariable, const std::string& kind, const std::string& sourceSubdir);

// Just the paths of dataDirs(), in order.
std::vector<std::string> dataDirPaths(const char* envVariable, const std::string& kind,
                                      const std::string& sourceSubdir);

}  // namespace camwb::base
