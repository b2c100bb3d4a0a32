// Helpers shared by the CL importer tests: import text in either format, the Error it must give,
// and warnings and source references as compact text to compare whole.
#pragma once

#include "toolpath/ClImport.h"
#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>

#include <unistd.h>

namespace camwb::toolpath::test {

inline std::string clDataPath(const std::string& name)
{
    return std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/cl/" + name;
}

inline base::Result<ClImport> readAs(ClFormat format, std::string_view text)
{
    return format == ClFormat::Apt ? readAptSource(text, "t.apt") : readFreeCadDump(text, "t.dump");
}

// The import of `text`; a failed import fails the test.
inline ClImport importAs(ClFormat format, std::string_view text)
{
    auto result = readAs(format, text);
    EXPECT_TRUE(result.ok()) << result.error().toString();
    return result.ok() ? std::move(result).value() : ClImport{};
}

// The Error that importing `text` gives; an import that succeeds fails the test.
inline base::Error failureAs(ClFormat format, std::string_view text)
{
    auto result = readAs(format, text);
    EXPECT_FALSE(result.ok()) << "imported:\n" << (result.ok() ? traceOf(result->toolpath) : "");
    return result.ok() ? base::Error{} : result.error();
}

// "file:line:column: message" per warning, one a line.
inline std::string warningsText(const ClImport& imported)
{
    std::string out;
    for (const base::Diagnostic& w : imported.warnings)
        out += base::Error{w.message, w.file, w.line, w.column}.toString() + '\n';
    return out;
}

// "operationIndex:recordIndex " per record.
inline std::string sourcesText(const Toolpath& toolpath)
{
    std::string out;
    for (std::size_t i = 0; i < toolpath.size(); ++i)
        out += std::to_string(toolpath.source(i).operationIndex) + ':' +
               std::to_string(toolpath.source(i).recordIndex) + ' ';
    return out;
}

// Imports `text` from a file, read in chunks as readClFile does, and from memory: both must give
// the same records, sources and warnings, whatever falls on a chunk boundary. Returns the trace.
inline std::string sameFromFileAndText(ClFormat format, const std::string& text)
{
    const std::string path = testing::TempDir() + "camwb-cl-stream-" + std::to_string(::getpid()) +
                             (format == ClFormat::Apt ? ".apt" : ".dump");
    {
        std::ofstream(path, std::ios::binary) << text;
    }
    auto fromFile = readClFile(path, format);
    auto fromText = readAs(format, text);
    std::remove(path.c_str());
    EXPECT_TRUE(fromFile.ok()) << fromFile.error().toString();
    EXPECT_TRUE(fromText.ok()) << fromText.error().toString();
    if (!fromFile.ok() || !fromText.ok())
        return {};
    const std::string trace = traceOf(fromFile->toolpath);
    EXPECT_EQ(trace, traceOf(fromText->toolpath));
    EXPECT_EQ(sourcesText(fromFile->toolpath), sourcesText(fromText->toolpath));
    // The file's warnings name its path: compare what follows it.
    std::string fileWarnings = warningsText(fromFile.value());
    for (std::size_t at; (at = fileWarnings.find(path)) != std::string::npos;)
        fileWarnings.replace(at, path.size(), format == ClFormat::Apt ? "t.apt" : "t.dump");
    EXPECT_EQ(fileWarnings, warningsText(fromText.value()));
    return trace;
}

}  // namespace camwb::toolpath::test
