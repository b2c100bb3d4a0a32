// Reading and writing .camwb job files: versioned JSON, atomic saves, clear errors with the
// file name (and line/column for malformed JSON). A newer format version is refused, not guessed.
#pragma once

#include "base/Result.h"
#include "document/Job.h"

#include <string>

namespace camwb::document {

// Version 2 added the optional "machine" and "postProperties"; version 3 the operation kinds
// (contour, pocket, helix, drill) with geometry references, height overrides and parameters;
// version 4 an operation's "workingPlane" (3+2); version 5 the swarf operation and an operation's
// own "postProperties"; version 6 an operation's "enabled": false, the job's stock "material", a
// tool's "cuttingData" (per material, from a tool library), the stock's "shape" and "fromModel"
// rule, the work "origin" and the default NC "output" (name, folder); version 7 the 3D operations
// ("pocket3d", "waterline", "parallel"); version 8 the turning operation "groove" (its parameters
// also read by the thesis' R names) and a job without "model"; version 9 the stock "shape":
// "blank" with its "blank" file (relative like the model). Versions 1-8 are still read (a
// "profile" becomes an outside contour); writing gives 9 when the stock is a blank, else 8 when
// the job has a groove operation,
// else 7 when the job has a 3D operation, else 6 when one of version
// 6's fields is used, else 5 when the job has a swarf operation or an operation's own post properties, else 4
// when an operation has a working plane, else 3, so that a CAM Workbench that knows neither
// refuses a job it would compute otherwise.
inline constexpr int kJobFormatVersion = 9;

// In memory a job's model path is absolute; in the file it is relative to the job file's folder.
// loadJob resolves it, saveJob makes it relative again, so jobs can be moved with their models.
base::Result<Job> loadJob(const std::string& path);
base::Status saveJob(const Job& job, const std::string& path);

// The file text as is (model path exactly as written), for tests and tools.
base::Result<Job> parseJob(const std::string& text, const std::string& pathForMessages);
std::string serializeJob(const Job& job);

// `modelPath` resolved against the folder of `jobPath` (absolute paths stay as they are).
std::string absoluteModelPath(const std::string& modelPath, const std::string& jobPath);
// `modelPath` made relative to the folder of `jobPath`.
std::string relativeModelPath(const std::string& modelPath, const std::string& jobPath);

// Where the job's NC program goes by default: outputName in outputFolder (relative to the folder
// of `jobPath`, or absolute), with `.extension` added when the name has none. Empty when the job
// names no output.
std::string jobOutputPath(const Job& job, const std::string& jobPath, const std::string& extension);

}  // namespace camwb::document
