// Reading a post's output back with its companion files: the interpreter finds a called program
// `NAME` as the companion NAME.SPF, as the control finds it beside the main program.
#pragma once

#include "nc/Interpreter.h"
#include "post/PostProcessor.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::post::test {

inline nc::ProgramResolver companionResolver(std::vector<CompanionFile> files)
{
    return [files = std::move(files)](std::string_view name) -> std::optional<nc::ProgramSource> {
        for (const CompanionFile& f : files)
            if (f.name == std::string(name) + ".SPF")
                return nc::ProgramSource{f.name, f.text};
        return std::nullopt;
    };
}

}  // namespace camwb::post::test
