// Importers of cutter-location files written by other CAM systems: APT CL source (CATIA V5, NX,
// Creo) and FreeCAD path dumps. They turn a file into a Toolpath that posts, the backplot and the
// simulator take like any operation's output; what the CL model cannot carry becomes a warning.
#pragma once

#include "base/Diagnostic.h"
#include "base/LineReader.h"
#include "base/Result.h"
#include "toolpath/ClFormat.h"
#include "toolpath/Toolpath.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::toolpath {

// The result of an import. Every record carries a SourceRef:
//  - operationIndex: the 0-based index of the section (SectionBegin ... SectionEnd) the record
//    belongs to, counting sections in file order; -1 for records outside any section (before the
//    first one, or between a section's end and the next one's start). A SectionEnd carries the
//    index of the section it closes.
//  - recordIndex: the 1-based line number of the statement that produced the record (its first
//    line when it is continued over several). A SectionEnd that closes a section because the next
//    one starts carries that statement's line; one that closes it at the end of input carries the
//    number of the last line.
// Feeds after a FeedModeChange to PerRevolution are in mm/rev, as ClRecords.h says.
struct ClImport {
    Toolpath toolpath;                       // records in mm, mm/min, degrees, rpm, seconds
    std::vector<base::Diagnostic> warnings;  // unknown/ignored records, with file, line (and column)
};

// Malformed input gives an Error with file, line and column and no toolpath. The dialects each
// reader accepts, and the meaning it gives them, are documented in AptReader.h and
// FreeCadDumpReader.h.
base::Result<ClImport> readAptSource(std::string_view text, const std::string& fileName);
base::Result<ClImport> readFreeCadDump(std::string_view text, const std::string& fileName);
// The same a line at a time: the readers hold one statement, never the whole file.
base::Result<ClImport> readAptSource(base::LineReader& lines, const std::string& fileName);
base::Result<ClImport> readFreeCadDump(base::LineReader& lines, const std::string& fileName);

// The reader of `format` over `lines` (a file's or a text's).
base::Result<ClImport> readCl(base::LineReader& lines, ClFormat format, const std::string& fileName);

// Reads the file in chunks as it imports it. A file that cannot be read gives an Error naming the
// path.
base::Result<ClImport> readClFile(const std::string& path, ClFormat format);

}  // namespace camwb::toolpath
