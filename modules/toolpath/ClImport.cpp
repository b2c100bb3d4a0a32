#include "toolpath/ClImport.h"

#include "toolpath/ClText.h"
#include "toolpath/TraceReader.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

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
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        return base::makeError("cannot read CL file '" + path + "': it is a directory", path);
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int error = errno;
        return base::makeError("cannot read CL file '" + path + "': " + std::strerror(error), path);
    }
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad())
        return base::makeError("cannot read CL file '" + path + "': read error", path);
    const std::string text = buffer.str();
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
