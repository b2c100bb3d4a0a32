// Helpers of the Klartext interpreter tests: run a program text into a recorded toolpath and
// pick out records and diagnostics.
#pragma once

#include "nc/Interpreter.h"
#include "nc/MotionTrace.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace camwb::nc::heidenhain::test {

struct Traced {
    toolpath::Toolpath path;
    InterpretResult result;

    std::string trace() const { return motionTrace(path, result.files, TraceFormat::Text); }

    template <class T> std::vector<T> all() const
    {
        std::vector<T> out;
        for (const toolpath::Record& r : path.records()) {
            if (const T* t = std::get_if<T>(&r))
                out.push_back(*t);
        }
        return out;
    }
    template <class T> std::vector<int> lines() const
    {
        std::vector<int> out;
        for (std::size_t i = 0; i < path.size(); ++i) {
            if (std::holds_alternative<T>(path.record(i)))
                out.push_back(path.source(i).line);
        }
        return out;
    }
    // Diagnostics as "line:column: severity: message" for readable failures.
    std::vector<std::string> diagnostics() const
    {
        std::vector<std::string> out;
        for (const Diagnostic& d : result.diagnostics)
            out.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + severityName(d.severity) +
                          ": " + d.message);
        return out;
    }
    std::size_t count(Severity s) const
    {
        std::size_t n = 0;
        for (const Diagnostic& d : result.diagnostics)
            n += d.severity == s ? 1 : 0;
        return n;
    }
    bool has(Severity s, int line, std::string_view text) const
    {
        for (const Diagnostic& d : result.diagnostics) {
            if (d.severity == s && d.line == line && d.message.find(text) != std::string::npos)
                return true;
        }
        return false;
    }
};

// Most tests are about arcs, cycles or compensation, not the start: they start at the origin, as
// rs274 does. A test of the program start passes InterpretOptions{} (no axis known).
inline InterpretOptions fromOrigin(InterpretOptions options = {})
{
    options.start = toolpath::Vec3{};
    return options;
}

inline Traced run(std::string_view text, InterpretOptions options = fromOrigin())
{
    options.dialect = Dialect::Heidenhain;
    if (options.fileName.empty())
        options.fileName = "test.h";
    toolpath::ToolpathRecorder recorder;
    Traced r;
    r.result = interpret(text, options, recorder);
    r.path = recorder.take();
    return r;
}

// A program of `body` after BEGIN PGM and a TOOL CALL: block "n" of the body is on line n + 1.
inline std::string program(std::string_view body)
{
    return "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S3000\n" + std::string(body) + "99 END PGM T MM\n";
}

inline void expectNear(const base::Vec3& a, const base::Vec3& b, double tolerance = 1e-9)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

}  // namespace camwb::nc::heidenhain::test
