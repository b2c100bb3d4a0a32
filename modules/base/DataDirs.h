// Where CAM Workbench looks for data files of one kind (posts, machines): folders from an
// environment variable, the user's folder, the installed share folder and, for runs from the
// build tree, the source tree. Earlier folders win, so a user's file overrides a built-in one.
#pragma once

#include "base/Result.h"

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

// "<dir>/<id><extension>" in the first of `dirs` that has it. Otherwise an Error naming every place
// looked ("<kind> 'x' not found (looked for ...)"), also for an id that is not a plain file name.
Result<std::string> findDataFile(const std::string& kind, const std::string& id, const std::string& extension,
                                 const std::vector<std::string>& dirs);

// One "<id><extension>" file of the folders: the first folder's with that id, and the files it hides.
struct DataFile {
    std::string id;
    std::string path;
    bool builtIn = false;
    std::vector<std::string> shadows;  // files with the same id in later folders, which this one hides
};

// Every "<id><extension>" file in the folders, sorted by id; the first folder with an id wins (a
// folder listed twice, e.g. the source tree that is also the installed one, counts once).
std::vector<DataFile> listDataFiles(const std::vector<DataDir>& dirs, const std::string& extension);

// Just the paths of dataDirs(), in order.
std::vector<std::string> dataDirPaths(const char* envVariable, const std::string& kind,
                                      const std::string& sourceSubdir);

}  // namespace camwb::base
