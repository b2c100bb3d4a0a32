// Helpers for the occ tests: a scratch folder per test binary run and small file writers.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace camwb::occ::test {

inline std::filesystem::path scratchDir()
{
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("camwb-occ-tests-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

inline std::string writeScratchFile(const std::string& name, const std::string& content)
{
    const std::filesystem::path path = scratchDir() / name;
    std::ofstream(path, std::ios::binary) << content;
    return path.string();
}

}  // namespace camwb::occ::test
