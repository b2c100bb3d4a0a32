#include "toolpath/ClImport.h"

#include "base/AtomicFile.h"
#include "toolpath/ClText.h"
#include "toolpath/TraceReader.h"

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

base::Result<ClImport> readClFile(const std::string& path, ClFormat format)
{
    auto content = base::readTextFile(path);
    if (!content)
        return content.error();
    const std::string& text = content.value();
    switch (format) {
    case ClFormat::Apt:
        return readAptSource(text, path);
    case ClFormat::FreeCadDump:
        return readFreeCadDump(text, path);
    case ClFormat::Trace:
        break;
    }
    return readTrace(text, path);
}

}  // namespace camwb::toolpath
