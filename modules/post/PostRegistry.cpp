#include "post/PostRegistry.h"

namespace camwb::post {

std::vector<base::DataDir> defaultPostDirs(const std::vector<std::string>& extraDirs)
{
    std::vector<base::DataDir> dirs;
    for (const std::string& dir : extraDirs)
        dirs.push_back({dir, false});
    for (base::DataDir& dir : base::dataDirs("CAMWB_POST_PATH", "posts", "posts"))
        dirs.push_back(std::move(dir));
    return dirs;
}

std::vector<PostEntry> listPosts(const std::vector<base::DataDir>& dirs) { return base::listDataFiles(dirs, ".js"); }

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
