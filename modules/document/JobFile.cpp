#include "document/JobFile.h"

#include "base/AtomicFile.h"
#include "base/JsonRead.h"
#include "document/JobSetup.h"
#include "document/detail/OperationFile.h"
#include "document/detail/ToolFile.h"

#include <algorithm>
#include <filesystem>

namespace camwb::document {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using namespace base::jsonread;

// Version 6: the stock's shape and "from model" rule (besides its resolved min/max); version 9
// the blank ("shape": "blank" and the "blank" file, relative to the job file).
void readStockRule(const json& stock, Stock& out, const std::string& where)
{
    if (optionalMember(stock, "shape", where)) {
        const std::string shape = text(stock, "shape", where);
        if (shape != "box" && shape != "cylinder" && shape != "blank")
            throw JsonFieldError{where + ".shape: expected \"box\", \"cylinder\" or \"blank\""};
        out.shape = shape == "cylinder" ? Stock::Shape::Cylinder
                    : shape == "blank"  ? Stock::Shape::Blank
                                        : Stock::Shape::Box;
    }
    if (out.shape == Stock::Shape::Blank) {
        out.blankPath = text(stock, "blank", where);
        if (out.blankPath.empty())
            throw JsonFieldError{where + ".blank: a blank stock needs its file"};
    }
    if (const json* rule = optionalMember(stock, "fromModel", where)) {
        if (out.shape == Stock::Shape::Blank)
            throw JsonFieldError{where + ".fromModel: a blank's size is its file's, not the model's"};
        StockFromModel fromModel;
        fromModel.below = vec3(*rule, "below", where + ".fromModel");
        fromModel.above = vec3(*rule, "above", where + ".fromModel");
        out.fromModel = fromModel;
    }
}

// Version 6: the work origin and the default NC output.
void readSetup(const json& root, Job& job, const std::string& where)
{
    if (optionalMember(root, "origin", where))
        job.origin = vec3(root, "origin", where);
    if (const json* output = optionalMember(root, "output", where)) {
        if (optionalMember(*output, "name", where + ".output"))
            job.outputName = text(*output, "name", where + ".output");
        if (optionalMember(*output, "folder", where + ".output"))
            job.outputFolder = text(*output, "folder", where + ".output");
    }
}

Job readJob(const json& root)
{
    const std::string where = "job";
    if (text(root, "format", where) != "camwb-job")
        throw JsonFieldError{"not a CAM Workbench job (format is not \"camwb-job\")"};
    const int version = integer(root, "version", where);
    if (version > kJobFormatVersion)
        throw JsonFieldError{"job format version " + std::to_string(version) +
                             " is newer than this CAM Workbench understands (" + std::to_string(kJobFormatVersion) +
                             "); update CAM Workbench"};
    if (version < 1)
        throw JsonFieldError{"job format version " + std::to_string(version) + " is not valid"};

    Job job;
    job.name = text(root, "name", where);
    // A lathe job's groove needs no model: "model" may be empty, or (version 8) left out.
    if (version < 8 || optionalMember(root, "model", where))
        job.modelPath = text(root, "model", where);
    const json& stock = member(root, "stock", where);
    job.stock.min = vec3(stock, "min", where + ".stock");
    job.stock.max = vec3(stock, "max", where + ".stock");
    readStockRule(stock, job.stock, where + ".stock");
    if (const auto problem = stockProblem(job.stock))
        throw JsonFieldError{where + ".stock: " + *problem};
    job.workOffset = integer(root, "workOffset", where);
    if (job.workOffset < 1 || job.workOffset > 99)
        throw JsonFieldError{where + ".workOffset: expected 1..99"};
    job.postId = text(root, "post", where);
    if (optionalMember(root, "machine", where))
        job.machineId = text(root, "machine", where);
    if (optionalMember(root, "material", where))
        job.material = text(root, "material", where);
    if (const Json* properties = optionalMember(root, "postProperties", where))
        job.postProperties = detail::readPostProperties(*properties, where + ".postProperties");
    readSetup(root, job, where);

    const json& tools = member(root, "tools", where);
    if (!tools.is_array())
        throw JsonFieldError{where + ".tools: expected an array"};
    for (std::size_t i = 0; i < tools.size(); ++i)
        job.tools.push_back(detail::readTool(tools[i], where + ".tools[" + std::to_string(i) + "]", true));

    const json& operations = member(root, "operations", where);
    if (!operations.is_array())
        throw JsonFieldError{where + ".operations: expected an array"};
    for (std::size_t i = 0; i < operations.size(); ++i) {
        const std::string at = where + ".operations[" + std::to_string(i) + "]";
        Operation op = detail::readOperation(operations[i], at);
        if (!job.tool(op.toolNumber))
            throw JsonFieldError{at + ".tool: no tool number " + std::to_string(op.toolNumber) + " in the job"};
        job.operations.push_back(std::move(op));
    }
    return job;
}

// Version 6 fields are written only when they differ from their defaults, so older jobs stay
// readable by older CAM Workbenches.
bool usesSetupFields(const Job& job)
{
    return job.stock.shape != Stock::Shape::Box || job.stock.fromModel || !(job.origin == base::Vec3{}) ||
           !job.outputName.empty() || !job.outputFolder.empty();
}

void writeStockRule(const Stock& stock, nlohmann::ordered_json& out)
{
    if (stock.shape == Stock::Shape::Cylinder)
        out["shape"] = "cylinder";
    if (stock.shape == Stock::Shape::Blank) {
        out["shape"] = "blank";
        out["blank"] = stock.blankPath;
    }
    if (stock.fromModel)
        out["fromModel"] = {{"below", {stock.fromModel->below.x, stock.fromModel->below.y, stock.fromModel->below.z}},
                            {"above", {stock.fromModel->above.x, stock.fromModel->above.y, stock.fromModel->above.z}}};
}

void writeSetup(const Job& job, nlohmann::ordered_json& root)
{
    if (!(job.origin == base::Vec3{}))
        root["origin"] = {job.origin.x, job.origin.y, job.origin.z};
    if (job.outputName.empty() && job.outputFolder.empty())
        return;
    nlohmann::ordered_json output = nlohmann::ordered_json::object();
    if (!job.outputName.empty())
        output["name"] = job.outputName;
    if (!job.outputFolder.empty())
        output["folder"] = job.outputFolder;
    root["output"] = output;
}

}  // namespace

base::Result<Job> parseJob(const std::string& content, const std::string& path)
{
    auto root = parse(content, path);
    if (!root)
        return root.error();
    try {
        return readJob(root.value());
    } catch (const JsonFieldError& e) {
        return base::makeError(e.message, path);
    }
}

base::Result<Job> loadJob(const std::string& path)
{
    auto content = base::readTextFile(path);
    if (!content)
        return content.error();
    auto job = parseJob(content.value(), path);
    if (job) {
        job->modelPath = absoluteModelPath(job->modelPath, path);
        job->stock.blankPath = absoluteModelPath(job->stock.blankPath, path);
    }
    return job;
}

std::string serializeJob(const Job& job)
{
    // ordered_json keeps the keys in the order written here, so files diff well.
    using ojson = nlohmann::ordered_json;
    ojson root;
    root["format"] = "camwb-job";
    const bool planes = std::any_of(job.operations.begin(), job.operations.end(),
                                    [](const Operation& op) { return op.plane.mode != WorkingPlaneSpec::Mode::Flat; });
    // Version 5: a swarf operation, or an operation's own post properties (an older reader would
    // post it with the job's, e.g. another TCPM mode).
    const bool swarf = std::any_of(job.operations.begin(), job.operations.end(), [](const Operation& op) {
        return op.kind() == OperationKind::Swarf || !op.postProperties.empty();
    });
    // Version 6: a disabled operation (an older reader would post it), a stock material or tools'
    // cutting data (an older reader would drop them on save).
    const bool disabled =
        std::any_of(job.operations.begin(), job.operations.end(), [](const Operation& op) { return !op.enabled; });
    const bool cuttingData =
        !job.material.empty() ||
        std::any_of(job.tools.begin(), job.tools.end(), [](const auto& tc) { return !tc.cuttingData.empty(); });
    // Version 7: a 3D operation (pocket3d, waterline, parallel).
    const bool surface = std::any_of(job.operations.begin(), job.operations.end(),
                                     [](const Operation& op) { return isSurfaceKind(op.kind()); });
    // Version 8: a turning operation (groove); such a job may have no model.
    const bool turning = std::any_of(job.operations.begin(), job.operations.end(),
                                     [](const Operation& op) { return isTurningKind(op.kind()); });
    // Version 9: a blank stock (an older reader would take its box).
    const bool blank = job.stock.shape == Stock::Shape::Blank;
    root["version"] = blank                                             ? 9
                      : turning                                         ? 8
                      : surface                                         ? 7
                      : disabled || cuttingData || usesSetupFields(job) ? 6
                      : swarf                                           ? 5
                      : planes                                          ? 4
                                                                        : 3;
    root["name"] = job.name;
    root["model"] = job.modelPath;
    root["stock"] = {{"min", {job.stock.min.x, job.stock.min.y, job.stock.min.z}},
                     {"max", {job.stock.max.x, job.stock.max.y, job.stock.max.z}}};
    writeStockRule(job.stock, root["stock"]);
    root["workOffset"] = job.workOffset;
    root["post"] = job.postId;
    if (!job.machineId.empty())
        root["machine"] = job.machineId;
    if (!job.postProperties.empty())
        root["postProperties"] = job.postProperties;
    if (!job.material.empty())
        root["material"] = job.material;
    writeSetup(job, root);
    root["tools"] = ojson::array();
    for (const ops::ToolController& tc : job.tools)
        root["tools"].push_back(detail::writeTool(tc));
    root["operations"] = ojson::array();
    for (const Operation& op : job.operations)
        root["operations"].push_back(detail::writeOperation(op));
    return root.dump(2) + "\n";
}

base::Status saveJob(const Job& job, const std::string& path)
{
    Job onDisk = job;
    if (!onDisk.modelPath.empty())
        onDisk.modelPath = relativeModelPath(onDisk.modelPath, path);
    if (!onDisk.stock.blankPath.empty())
        onDisk.stock.blankPath = relativeModelPath(onDisk.stock.blankPath, path);
    return base::writeFileAtomically(path, serializeJob(onDisk));
}

std::string absoluteModelPath(const std::string& modelPath, const std::string& jobPath)
{
    const fs::path model(modelPath);
    if (model.is_absolute() || modelPath.empty())
        return modelPath;
    return (fs::absolute(jobPath).parent_path() / model).lexically_normal().string();
}

std::string relativeModelPath(const std::string& modelPath, const std::string& jobPath)
{
    const fs::path base = fs::absolute(jobPath).parent_path();
    const fs::path relative = fs::absolute(modelPath).lexically_normal().lexically_relative(base);
    return relative.empty() ? modelPath : relative.generic_string();
}

std::string jobOutputPath(const Job& job, const std::string& jobPath, const std::string& extension)
{
    if (job.outputName.empty())
        return {};
    fs::path name(job.outputName);
    if (!name.has_extension() && !extension.empty())
        name += "." + extension;
    const fs::path folder = absoluteModelPath(job.outputFolder.empty() ? "." : job.outputFolder, jobPath);
    return (folder / name).lexically_normal().string();
}

}  // namespace camwb::document
