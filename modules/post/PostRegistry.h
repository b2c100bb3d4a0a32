// Where post scripts are found and which one an id means: "<dir>/<id>.js" over an ordered list of
// folders (--post-path, $CAMWB_POST_PATH, the user's folder, then the built-in ones). The first
// folder that has an id wins, so a user's post overrides a built-in one with the same id.
#pragma once

#include "base/DataDirs.h"
#include "base/Result.h"
#include "kinematics/Machine.h"
#include "post/PostInfo.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::post {

// `extraDirs` (from --post-path) first, then base::dataDirs("CAMWB_POST_PATH", "posts", "posts").
std::vector<base::DataDir> defaultPostDirs(const std::vector<std::string>& extraDirs = {});

using PostEntry = base::DataFile;

// Every "<id>.js" in the folders, sorted by id; the first folder with an id wins.
std::vector<PostEntry> listPosts(const std::vector<base::DataDir>& dirs);

// "<dir>/<id>.js", first match wins; the error lists every place it looked.
base::Result<std::string> findPost(const std::string& id, const std::vector<base::DataDir>& dirs);

// The machine a run of the post uses: `requestedId`, else the post's default machine; none when
// neither names one (the run then checks no machine limits).
base::Result<std::optional<kinematics::Machine>> machineForPost(const PostInfo& info, const std::string& requestedId,
                                                                const std::vector<std::string>& machineDirs);

}  // namespace camwb::post
