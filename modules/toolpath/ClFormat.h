// The cutter-location file formats read besides NC (APT CL source, FreeCAD path dumps, our own
// trace), told apart by file extension or by name. Small on purpose: the editor and the inspector
// need the format without the importers (ClImport.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace camwb::toolpath {

enum class ClFormat { Apt, FreeCadDump, Trace };  // Trace: our own canonical trace (TraceReader.h)

// .apt .aptsource .cl .cls -> Apt; .dump -> FreeCadDump; .trace -> Trace (case-insensitive); else nullopt.
std::optional<ClFormat> clFormatFromExtension(const std::string& path);
// "apt", "freecad-dump", "trace" (case-insensitive); anything else nullopt.
std::optional<ClFormat> clFormatFromName(std::string_view name);
const char* clFormatName(ClFormat format);  // the inverse: "apt", "freecad-dump", "trace"

}  // namespace camwb::toolpath
