#include "sim/MeasuredTrace.h"

#include "base/AtomicFile.h"
#include "base/LineReader.h"

#include <charconv>
#include <cmath>
#include <optional>

namespace camwb::sim {

namespace {

char separatorOf(std::string_view line, char configured)
{
    if (configured != 0)
        return configured;
    if (line.find(';') != std::string_view::npos)
        return ';';
    return line.find('\t') != std::string_view::npos ? '\t' : ',';
}

struct Field {
    std::string_view text;
    int column = 0;  // 1-based character column of its start
};

std::vector<Field> split(std::string_view line, char separator)
{
    std::vector<Field> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = line.find(separator, start);
        fields.push_back(
            {line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start), int(start) + 1});
        if (end == std::string_view::npos)
            return fields;
        start = end + 1;
    }
}

// The field as a number: blanks around it dropped, a decimal comma read as a point (only where
// the separator is not a comma, so it cannot be one).
bool parseNumber(std::string_view text, bool decimalComma, double& value)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '"'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '"'))
        text.remove_suffix(1);
    std::string buffer(text);
    if (decimalComma)
        for (char& c : buffer)
            if (c == ',')
                c = '.';
    if (!buffer.empty() && buffer.front() == '+')
        buffer.erase(0, 1);
    const auto [end, error] = std::from_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return error == std::errc() && end == buffer.data() + buffer.size() && !buffer.empty() && std::isfinite(value);
}

}  // namespace

base::Result<MeasuredTrace> readMeasuredTrace(const std::string& text, const std::string& path,
                                              const TraceColumns& columns)
{
    MeasuredTrace trace;
    base::LineReader reader(text);
    char separator = columns.separator;
    while (auto line = reader.next()) {
        if (reader.lineNumber() <= columns.headerLines)
            continue;
        if (line->find_first_not_of(" \t") == std::string_view::npos)
            continue;  // blank lines (a trailing one) carry no sample
        separator = separatorOf(*line, separator);
        const std::vector<Field> fields = split(*line, separator);
        auto read = [&](int column, double scale, std::vector<double>& into) -> std::optional<base::Error> {
            if (column < 0)
                return std::nullopt;
            if (column >= int(fields.size()))
                return base::makeError("column " + std::to_string(column + 1) + " is missing (the line has " +
                                           std::to_string(fields.size()) + ")",
                                       path, reader.lineNumber(), int(line->size()) + 1);
            double v = 0;
            if (!parseNumber(fields[column].text, separator != ',', v))
                return base::makeError("expected a number, found \"" + std::string(fields[column].text) + "\"", path,
                                       reader.lineNumber(), fields[column].column);
            into.push_back(v * scale);
            return std::nullopt;
        };
        if (auto e = read(columns.time, columns.timeScale, trace.time))
            return *e;
        for (int c = 0; c < 5; ++c) {
            const double scale = c < 3 ? columns.linearScale : columns.rotaryScale;
            for (auto [cols, into] :
                 {std::pair{&columns.nominal, &trace.nominal}, std::pair{&columns.actual, &trace.actual},
                  std::pair{&columns.deviation, &trace.deviation}})
                if (auto e = read((*cols)[c], scale, (*into)[c]))
                    return *e;
        }
        if (trace.time.size() > 1 && !(trace.time.back() > trace.time[trace.time.size() - 2]))
            return base::makeError("time does not increase", path, reader.lineNumber(),
                                   columns.time >= 0 ? fields[columns.time].column : 0);
    }
    if (trace.time.empty())
        return base::makeError("no samples (a time column and one line of data at least)", path);
    return trace;
}

base::Result<MeasuredTrace> loadMeasuredTrace(const std::string& path, const TraceColumns& columns)
{
    auto text = base::readPlainTextFile(path);
    if (!text)
        return text.error();
    return readMeasuredTrace(text.value(), path, columns);
}

Trace workpieceTrace(const MeasuredTrace& m, bool actual, const kinematics::KinematicChain& chain,
                     double spindleFaceToTipMm)
{
    const auto& ch = actual ? m.actual : m.nominal;
    auto at = [&](int c, std::size_t k) { return ch[c].size() > k ? ch[c][k] : 0.0; };
    Trace trace(m.time.size());
    for (std::size_t k = 0; k < m.time.size(); ++k) {
        kinematics::MachinePose pose;
        pose.linear = {at(0, k), at(1, k), at(2, k) - spindleFaceToTipMm};
        pose.rotaryDeg = {at(3, k), at(4, k)};
        trace[k] = {m.time[k], pose.linear, pose.rotaryDeg, kinematics::forwardKinematics(chain, pose).tip};
    }
    return trace;
}

std::vector<double> deviationDistance(const Trace& nominal, const Trace& actual)
{
    std::vector<double> d(std::min(nominal.size(), actual.size()));
    for (std::size_t k = 0; k < d.size(); ++k)
        d[k] = base::distance(nominal[k].tip, actual[k].tip);
    return d;
}

}  // namespace camwb::sim
