#include "toolpath/ClFormat.h"

#include "toolpath/ClText.h"

#include <filesystem>

namespace camwb::toolpath {

std::optional<ClFormat> clFormatFromExtension(const std::string& path)
{
    const std::string extension = toUpper(std::filesystem::path(path).extension().string());
    if (extension == ".APT" || extension == ".APTSOURCE" || extension == ".CL" || extension == ".CLS")
        return ClFormat::Apt;
    if (extension == ".DUMP")
        return ClFormat::FreeCadDump;
    if (extension == ".TRACE")
        return ClFormat::Trace;
    return std::nullopt;
}

std::optional<ClFormat> clFormatFromName(std::string_view name)
{
    if (equalsNoCase(name, "apt"))
        return ClFormat::Apt;
    if (equalsNoCase(name, "freecad-dump"))
        return ClFormat::FreeCadDump;
    if (equalsNoCase(name, "trace"))
        return ClFormat::Trace;
    return std::nullopt;
}

const char* clFormatName(ClFormat format)
{
    switch (format) {
    case ClFormat::Apt:
        return "apt";
    case ClFormat::FreeCadDump:
        return "freecad-dump";
    case ClFormat::Trace:
        break;
    }
    return "trace";
}

}  // namespace camwb::toolpath
