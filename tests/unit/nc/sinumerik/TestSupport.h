// Helpers of the SINUMERIK interpreter tests: run a program from text (subprograms from a map),
// collect the records, and look at moves and diagnostics.
#pragma once

#include "nc/Interpreter.h"
#include "nc/MotionTrace.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace camwb::nc::sinumerik::test {

struct NcRun {
    InterpretResult result;
    toolpath::Toolpath path;

    // Records of one kind, in order.
    template <typename T> std::vector<T> all() const
    {
        std::vector<T> out;
        for (const auto& r : path.records())
            if (const T* t = std::get_if<T>(&r))
                out.push_back(*t);
        return out;
    }
    std::string trace() const { return motionTrace(path, result.files, TraceFormat::Text); }
    std::string diagnostics() const
    {
        std::string out;
        for (const Diagnostic& d : result.diagnostics)
            out += formatDiagnostic(d) + '\n';
        return out;
    }
    int errors() const
    {
        int n = 0;
        for (const Diagnostic& d : result.diagnostics)
            n += d.severity == Severity::Error;
        return n;
    }
    int warnings() const
    {
        int n = 0;
        for (const Diagnostic& d : result.diagnostics)
            n += d.severity == Severity::Warning;
        return n;
    }
    // The first diagnostic whose message contains `text`, or nullptr.
    const Diagnostic* find(const std::string& text) const
    {
        for (const Diagnostic& d : result.diagnostics)
            if (d.message.find(text) != std::string::npos)
                return &d;
        return nullptr;
    }
};

// Most tests are about arcs, cycles or compensation, not the start: they start at the origin, as
// rs274 does. A test of the program start passes InterpretOptions{} (no axis known).
inline InterpretOptions fromOrigin(InterpretOptions options = {})
{
    options.start = toolpath::Vec3{};
    return options;
}

inline NcRun run(const std::string& text, const std::map<std::string, std::string>& subprograms = {},
                 InterpretOptions options = fromOrigin())
{
    options.dialect = Dialect::Sinumerik;
    if (options.fileName.empty())
        options.fileName = "MAIN.MPF";
    if (!options.resolveProgram)
        options.resolveProgram = [subprograms](std::string_view name) -> std::optional<ProgramSource> {
            auto it = subprograms.find(std::string(name));
            if (it == subprograms.end())
                return std::nullopt;
            return ProgramSource{it->first + ".SPF", it->second};
        };
    toolpath::ToolpathRecorder recorder;
    NcRun r;
    r.result = interpret(text, options, recorder);
    r.path = recorder.take();
    return r;
}

inline std::string readFile(const std::string& path)
{
    std::string text;
    if (FILE* f = std::fopen(path.c_str(), "rb")) {
        char buffer[65536];
        std::size_t n;
        while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0)
            text.append(buffer, n);
        std::fclose(f);
    }
    return text;
}

inline std::string dataDir() { return std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/nc/seed-001"; }

}  // namespace camwb::nc::sinumerik::test
