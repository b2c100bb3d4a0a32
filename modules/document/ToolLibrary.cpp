#include "document/ToolLibrary.h"

#include "base/AtomicFile.h"
#include "base/JsonRead.h"
#include "document/detail/ToolFile.h"

#include <algorithm>

namespace camwb::document {

using nlohmann::json;
using namespace base::jsonread;

namespace {

ToolLibrary readLibrary(const json& root)
{
    const std::string where = "library";
    if (text(root, "format", where) != "camwb-tools")
        throw JsonFieldError{"not a CAM Workbench tool library (format is not \"camwb-tools\")"};
    const int version = integer(root, "version", where);
    if (version > kToolLibraryFormatVersion)
        throw JsonFieldError{"tool library version " + std::to_string(version) +
                             " is newer than this CAM Workbench understands (" +
                             std::to_string(kToolLibraryFormatVersion) + "); update CAM Workbench"};
    if (version < 1)
        throw JsonFieldError{"tool library version " + std::to_string(version) + " is not valid"};
    ToolLibrary library;
    if (optionalMember(root, "name", where))
        library.name = text(root, "name", where);
    const json& tools = member(root, "tools", where);
    if (!tools.is_array())
        throw JsonFieldError{where + ".tools: expected an array"};
    for (std::size_t i = 0; i < tools.size(); ++i)
        library.tools.push_back(detail::readTool(tools[i], where + ".tools[" + std::to_string(i) + "]", false));
    return library;
}

}  // namespace

base::Result<ToolLibrary> parseToolLibrary(const std::string& text, const std::string& path)
{
    auto root = parse(text, path);
    if (!root)
        return root.error();
    try {
        return readLibrary(root.value());
    } catch (const JsonFieldError& e) {
        return base::makeError(e.message, path);
    }
}

base::Result<ToolLibrary> loadToolLibrary(const std::string& path)
{
    auto content = base::readTextFile(path);
    if (!content)
        return content.error();
    return parseToolLibrary(content.value(), path);
}

std::string serializeToolLibrary(const ToolLibrary& library)
{
    nlohmann::ordered_json root;
    root["format"] = "camwb-tools";
    root["version"] = kToolLibraryFormatVersion;
    root["name"] = library.name;
    root["tools"] = nlohmann::ordered_json::array();
    for (const ops::ToolController& tc : library.tools)
        root["tools"].push_back(detail::writeTool(tc));
    return root.dump(2) + "\n";
}

base::Status saveToolLibrary(const ToolLibrary& library, const std::string& path)
{
    return base::writeFileAtomically(path, serializeToolLibrary(library));
}

int nextFreeToolNumber(const std::vector<ops::ToolController>& tools, int wanted)
{
    int number = std::max(wanted, 1);
    while (std::any_of(tools.begin(), tools.end(), [&](const auto& tc) { return tc.tool.number == number; }))
        ++number;
    return number;
}

std::vector<std::string> addToolsToJob(Job& job, const std::vector<ops::ToolController>& tools)
{
    std::vector<std::string> notes;
    for (ops::ToolController tc : tools) {
        const int wanted = tc.tool.number;
        tc.tool.number = nextFreeToolNumber(job.tools, wanted);
        if (tc.tool.number != wanted)
            notes.push_back("T" + std::to_string(wanted) + " \"" + tc.tool.name + "\" added as T" +
                            std::to_string(tc.tool.number) + ": T" + std::to_string(wanted) + " is taken");
        job.tools.push_back(std::move(tc));
    }
    return notes;
}

}  // namespace camwb::document
