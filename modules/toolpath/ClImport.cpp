#include "toolpath/ClImport.h"

#include "toolpath/TraceReader.h"

namespace camwb::toolpath {

base::Result<ClImport> readCl(base::LineReader& lines, ClFormat format, const std::string& fileName)
{
    switch (format) {
    case ClFormat::Apt:
        return readAptSource(lines, fileName);
    case ClFormat::FreeCadDump:
        return readFreeCadDump(lines, fileName);
    case ClFormat::Trace:
        break;
    }
    return readTrace(lines, fileName);
}

base::Result<ClImport> readClFile(const std::string& path, ClFormat format)
{
    auto lines = base::LineReader::open(path);
    if (!lines)
        return lines.error();
    return readCl(lines.value(), format, path);
}

}  // namespace camwb::toolpath
