// Shared helpers for the post tests: a fixed context, toolpath building and script files.
#pragma once

#include "post/PostProcessor.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace camwb::post::test {

inline const std::string kPostsDir = std::string(CAMWB_TEST_DATA_DIR) + "/posts";
inline const std::string kEmcoPost = kPostsDir + "/sinumerik828d-emco.js";

inline PostContext fixedContext()
{
    PostContext context;
    context.programName = "PART1";
    context.dateEpochSeconds = 1526418586;  // 15.05.2018 21:09:46 UTC, the seed-004 oracle's time
    context.user = "tester";
    context.version = "0.1.0";
    return context;
}

inline std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        result.push_back(line);
    return result;
}

// The line without its "N<n> " block number.
inline std::string words(const std::string& line)
{
    if (line.size() > 1 && line[0] == 'N') {
        const std::size_t space = line.find(' ');
        if (space != std::string::npos)
            return line.substr(space + 1);
    }
    return line;
}

inline std::vector<std::string> wordLines(const std::string& text)
{
    std::vector<std::string> result;
    for (const std::string& line : lines(text))
        result.push_back(words(line));
    return result;
}

// Writes a script into this test process's temp folder and returns its path. The folder is per
// process because ctest runs tests in parallel and a post's file name is its id.
inline std::string writeScript(const std::string& name, const std::string& source)
{
    const std::filesystem::path dir =
        std::filesystem::path(testing::TempDir()) / ("camwb-post-tests-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / name;
    std::ofstream(path, std::ios::binary) << source;
    return path.string();
}

// Loads the post `source` (saved as `name`) and runs it on `path` with the fixed context; a failure
// to load or run is a test failure and gives an empty output.
inline PostOutput runSource(const std::string& name, const std::string& source, const toolpath::Toolpath& path)
{
    auto post = PostProcessor::load(writeScript(name, source));
    EXPECT_TRUE(post.ok()) << post.error().toString();
    if (!post.ok())
        return {};
    auto output = post->run(path, fixedContext());
    EXPECT_TRUE(output.ok()) << output.error().toString();
    return output.ok() ? output.value() : PostOutput{};
}

}  // namespace camwb::post::test
