#include "base/DataDirs.h"

#include "camwb_version.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <system_error>

namespace camwb::base {

namespace fs = std::filesystem;

std::vector<DataDir> dataDirs(const char* envVariable, const std::string& kind, const std::string& sourceSubdir)
{
    std::vector<DataDir> dirs;
    if (const char* value = std::getenv(envVariable)) {
        const std::string list(value);
        for (std::size_t start = 0; start <= list.size();) {
            const std::size_t colon = std::min(list.find(':', start), list.size());
            if (colon > start)
                dirs.push_back({list.substr(start, colon - start), false});
            start = colon + 1;
        }
    }
    if (const char* home = std::getenv("HOME"); home && *home)
        dirs.push_back({(fs::path(home) / ".local/share/camwb" / kind).string(), false});
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec)
        dirs.push_back({(exe.parent_path().parent_path() / "share/camwb" / kind).lexically_normal().string(), true});
    dirs.push_back({std::string(CAMWB_SOURCE_DIR) + "/" + sourceSubdir, true});
    return dirs;
}

Result<std::string> findDataFile(const std::string& kind, const std::string& id, const std::string& extension,
                                 const std::vector<std::string>& dirs)
{
    if (id.empty() || id.find('/') != std::string::npos || id.find("..") != std::string::npos)
        return makeError("invalid " + kind + " id '" + id + "'");
    std::string looked;
    for (const std::string& dir : dirs) {
        const fs::path candidate = fs::path(dir) / (id + extension);
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec))
            return candidate.string();
        looked += (looked.empty() ? "" : ", ") + candidate.string();
    }
    return makeError(kind + " '" + id + "' not found (looked for " +
                     (looked.empty() ? std::string("it in no folder: none configured") : looked) + ")");
}

std::vector<std::string> dataDirPaths(const char* envVariable, const std::string& kind, const std::string& sourceSubdir)
{
    std::vector<std::string> paths;
    for (DataDir& dir : dataDirs(envVariable, kind, sourceSubdir))
        paths.push_back(std::move(dir.path));
    return paths;
}

std::vector<DataFile> listDataFiles(const std::vector<DataDir>& dirs, const std::string& extension)
{
    std::map<std::string, DataFile> byId;
    std::vector<std::string> seenDirs;
    for (const DataDir& dir : dirs) {
        std::error_code ec;
        const std::string canonical = fs::weakly_canonical(dir.path, ec).string();
        if (std::find(seenDirs.begin(), seenDirs.end(), canonical) != seenDirs.end())
            continue;
        seenDirs.push_back(canonical);
        std::vector<fs::path> files;
        for (fs::directory_iterator it(dir.path, ec), end; !ec && it != end; it.increment(ec))
            if (it->path().extension() == extension && it->is_regular_file(ec))
                files.push_back(it->path());
        std::sort(files.begin(), files.end());
        for (const fs::path& file : files) {
            const std::string id = file.stem().string();
            auto [entry, added] = byId.try_emplace(id, DataFile{id, file.string(), dir.builtIn, {}});
            if (!added)
                entry->second.shadows.push_back(file.string());
        }
    }
    std::vector<DataFile> entries;
    for (auto& [id, entry] : byId)
        entries.push_back(std::move(entry));
    return entries;
}

}  // namespace camwb::base
