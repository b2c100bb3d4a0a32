// The JSON file inside a zip archive, for Fusion 360's .tools libraries (a zip holding one
// tools.json). Read with minizip, whose headers stay in ZipJson.cpp.
#pragma once

#include "base/Result.h"

#include <string>

namespace camwb::document::detail {

// The text of the archive's .json entry (the first, when there are several). Errors name the
// file: not a zip archive that can be read, no .json inside, an entry that is damaged (its
// checksum does not match) or larger than a tool library can be (256 MiB).
base::Result<std::string> readJsonFromZip(const std::string& path);

}  // namespace camwb::document::detail
