// Where post scripts are looked up: "<dir>/<id>.js" over an ordered list of folders.
#pragma once

#include "base/Result.h"

#include <string>
#include <vector>

namespace camwb::post {

// $CAMWB_POST_PATH entries (':'-separated), ~/.local/share/camwb/posts, the installed
// <prefix>/share/camwb/posts (relative to the executable: ../share/camwb/posts) and
// CAMWB_SOURCE_DIR/posts for runs from the build tree, in that order (missing folders included,
// so that a failed lookup can say where it looked).
std::vector<std::string> defaultPostDirs();

// "<dir>/<id>.js", first match wins; the error lists every place it looked.
base::Result<std::string> findPost(const std::string& id, const std::vector<std::string>& dirs);

}  // namespace camwb::post
