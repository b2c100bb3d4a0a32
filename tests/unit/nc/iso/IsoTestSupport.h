// Helpers of the ISO interpreter tests: run a program into a ToolpathRecorder and look at the
// records, the canonical trace or the diagnostics.
#pragma once

#include "nc/Interpreter.h"
#include "toolpath/Toolpath.h"

#include <string>
#include <string_view>
#include <vector>

namespace camwb::nc::iso::test {

struct IsoRun {
    InterpretResult result;
    toolpath::Toolpath path;
    std::string trace;  // nc::motionTrace text

    // All diagnostics as "line:column: severity: message" lines, for EXPECT_EQ with a readable diff.
    std::string diagnostics() const;
    // The records of one type, in order.
    template <class T> std::vector<T> all() const
    {
        std::vector<T> out;
        for (const auto& r : path.records())
            if (const T* t = std::get_if<T>(&r))
                out.push_back(*t);
        return out;
    }
};

// Most tests are about arcs, cycles or compensation, not the start: they start at the origin, as
// rs274 does. A test of the program start passes InterpretOptions{} (no axis known).
inline InterpretOptions fromOrigin(InterpretOptions options = {})
{
    options.start = toolpath::Vec3{};
    return options;
}

IsoRun run(std::string_view program, InterpretOptions options = fromOrigin());

}  // namespace camwb::nc::iso::test
