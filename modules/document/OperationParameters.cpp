#include "document/OperationParameters.h"

#include "base/JsonRead.h"
#include "document/detail/OperationFile.h"
#include "toolpath/ClText.h"

#include <algorithm>

namespace camwb::document {

base::Result<int> findOperation(const Job& job, const std::string& nameOrNumber)
{
    for (std::size_t i = 0; i < job.operations.size(); ++i)
        if (job.operations[i].name() == nameOrNumber)
            return static_cast<int>(i);
    const bool digits = !nameOrNumber.empty() && std::all_of(nameOrNumber.begin(), nameOrNumber.end(),
                                                             [](char c) { return c >= '0' && c <= '9'; });
    if (digits && nameOrNumber.size() < 6) {
        const int number = std::stoi(nameOrNumber);
        if (number >= 1 && number <= static_cast<int>(job.operations.size()))
            return number - 1;
    }
    std::string known;
    for (std::size_t i = 0; i < job.operations.size(); ++i)
        known += (i ? ", " : "") + std::to_string(i + 1) + " \"" + job.operations[i].name() + "\"";
    return base::makeError("no operation \"" + nameOrNumber + "\" in the job" +
                           (known.empty() ? std::string(" (it has none)") : " (operations: " + known + ")"));
}

std::vector<std::string> parameterNames(const Operation& op)
{
    std::vector<std::string> names = detail::operationParamNames(op);
    if (op.kind() == OperationKind::Groove)
        names.push_back("R9");
    return names;
}

base::Status setOperationParameter(Job& job, int index, const std::string& parameter, const std::string& value)
{
    Operation& op = job.operations.at(index);
    const std::string where = kindLabel(op.kind()) + std::string(" \"") + op.name() + "\"";
    const std::vector<std::string> names = parameterNames(op);
    if (std::find(names.begin(), names.end(), parameter) == names.end()) {
        std::string list;
        for (const std::string& name : names)
            list += (list.empty() ? "" : ", ") + name;
        return base::makeError(where + ": no parameter \"" + parameter + "\" (parameters: " + list + ")");
    }
    // The text as the file would hold it: a number or true/false, else an enum's name.
    base::jsonread::Json json;
    if (const std::optional<double> number = toolpath::parseNumber(value))
        json = *number == static_cast<int>(*number) && value.find_first_of(".eE") == std::string::npos
                   ? base::jsonread::Json(static_cast<int>(*number))
                   : base::jsonread::Json(*number);
    else if (value == "true" || value == "false")
        json = value == "true";
    else
        json = value;
    if (parameter == "R9") {
        // The insert width is the tool's: the operation's tool controller in the job.
        if (!json.is_number())
            return base::makeError(where + ".R9: expected a number (the insert width, mm), got \"" + value + "\"");
        for (ops::ToolController& tc : job.tools)
            if (tc.tool.number == op.toolNumber)
                tc.tool.diameterMm = json.get<double>();
        return {};
    }
    try {
        detail::readOperationParams(op, base::jsonread::Json{{parameter, json}}, where);
    } catch (const base::jsonread::JsonFieldError& e) {
        std::string message = e.message;
        if (!json.is_number() && !json.is_boolean())
            message += " (got \"" + value + "\")";
        return base::makeError(message);
    }
    return {};
}

}  // namespace camwb::document
