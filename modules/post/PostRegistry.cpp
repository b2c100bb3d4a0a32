#include "post/PostRegistry.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <system_error>

namespace camwb::post {

namespace fs = std::filesystem;

std::vector<base::DataDir> defaultPostDirs(const std::vector<std::string>& extraDirs)
{
    std::vector<base::DataDir> dirs;
    for (const std::string& dir : extraDirs)
        dirs.push_back({dir, false});
    for (base::DataDir& dir : base::dataDirs("CAMWB_POST_PATH", "posts", "posts"))
        dirs.push_back(std::move(dir));
    return dirs;
}

std::vector<PostEntry> listPosts(const std::vector<base::DataDir>& dirs)
{
    std::map<std::string, PostEntry> byId;
    std::vector<std::string> seenDirs;
    for (const base::DataDir& dir : dirs) {
        std::error_code ec;
        // The same folder twice (the source tree is also the installed one) is not an override.
        const std::string canonical = fs::weakly_canonical(dir.path, ec).string();
        if (std::find(seenDirs.begin(), seenDirs.end(), canonical) != seenDirs.end())
            continue;
        seenDirs.push_back(canonical);
        std::vector<fs::path> files;
        for (fs::directory_iterator it(dir.path, ec), end; !ec && it != end; it.increment(ec))
            if (it->path().extension() == ".js" && it->is_regular_file(ec))
                files.push_back(it->path());
        std::sort(files.begin(), files.end());
        for (const fs::path& file : files) {
            const std::string id = file.stem().string();
            auto [entry, added] = byId.try_emplace(id, PostEntry{id, file.string(), dir.builtIn, {}});
            if (!added)
                entry->second.shadows.push_back(file.string());
        }
    }
    std::vector<PostEntry> entries;
    for (auto& [id, entry] : byId)
        entries.push_back(std::move(entry));
    return entries;
}

base::Result<std::string> findPost(const std::string& id, const std::vector<base::DataDir>& dirs)
{
    std::vector<std::string> paths;
    for (const base::DataDir& dir : dirs)
        paths.push_back(dir.path);
    return base::findDataFile("post", id, ".js", paths);
}

base::Result<std::optional<kinematics::Machine>> machineForPost(const PostInfo& info, const std::string& requestedId,
                                                                const std::vector<std::string>& machineDirs)
{
    const std::string& id = requestedId.empty() ? info.defaultMachine : requestedId;
    if (id.empty())
        return std::optional<kinematics::Machine>();
    auto machine = kinematics::findMachine(id, machineDirs);
    if (!machine)
        return machine.error();
    return std::optional<kinematics::Machine>(std::move(machine).value());
}

}  // namespace camwb::post
