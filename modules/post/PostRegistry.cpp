#include "post/PostRegistry.h"

#include "camwb_version.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace camwb::post {

namespace fs = std::filesystem;

std::vector<std::string> defaultPostDirs()
{
    std::vector<std::string> dirs;
    if (const char* path = std::getenv("CAMWB_POST_PATH")) {
        std::string list(path);
        std::size_t start = 0;
        while (start <= list.size()) {
            const std::size_t colon = list.find(':', start);
            const std::string entry =
                list.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
            if (!entry.empty())
                dirs.push_back(entry);
            if (colon == std::string::npos)
                break;
            start = colon + 1;
        }
    }
    if (const char* home = std::getenv("HOME"); home && *home)
        dirs.push_back((fs::path(home) / ".local/share/camwb/posts").string());
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec)
        dirs.push_back((exe.parent_path().parent_path() / "share/camwb/posts").lexically_normal().string());
    dirs.push_back(std::string(CAMWB_SOURCE_DIR) + "/posts");
    return dirs;
}

base::Result<std::string> findPost(const std::string& id, const std::vector<std::string>& dirs)
{
    if (id.empty() || id.find('/') != std::string::npos || id.find("..") != std::string::npos)
        return base::makeError("invalid post id '" + id + "'");
    std::string looked;
    for (const std::string& dir : dirs) {
        const fs::path candidate = fs::path(dir) / (id + ".js");
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec))
            return candidate.string();
        looked += "\n  " + candidate.string();
    }
    if (dirs.empty())
        looked = " (no post folders configured)";
    return base::makeError("post '" + id + "' not found; looked in:" + looked);
}

}  // namespace camwb::post
