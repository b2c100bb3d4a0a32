#include "toolpath/ClBuilder.h"

#include <algorithm>

namespace camwb::toolpath {

namespace {

// The same message on many lines (NX writes a PAINT statement every few lines) is one warning
// that lists the lines, so that the one that matters is not buried.
std::vector<base::Diagnostic> mergeRepeatedWarnings(std::vector<base::Diagnostic> warnings)
{
    constexpr std::size_t kLinesListed = 8;
    std::vector<base::Diagnostic> merged;
    std::vector<std::vector<int>> repeats;  // further lines, per merged warning
    for (base::Diagnostic& warning : warnings) {
        auto same = std::find_if(merged.begin(), merged.end(),
                                 [&](const base::Diagnostic& w) { return w.message == warning.message; });
        if (same == merged.end()) {
            merged.push_back(std::move(warning));
            repeats.emplace_back();
        } else {
            repeats[static_cast<std::size_t>(same - merged.begin())].push_back(warning.line);
        }
    }
    for (std::size_t i = 0; i < merged.size(); ++i) {
        const std::vector<int>& lines = repeats[i];
        if (lines.empty())
            continue;
        std::string list;
        for (std::size_t k = 0; k < std::min(lines.size(), kLinesListed); ++k)
            list += (k ? ", " : "") + std::to_string(lines[k]);
        if (lines.size() > kLinesListed)
            list += " and " + std::to_string(lines.size() - kLinesListed) + " more";
        merged[i].message += " (also on line" + std::string(lines.size() > 1 ? "s " : " ") + list + ")";
    }
    return merged;
}

}  // namespace

void ClBuilder::add(Record record, int line)
{
    if (const ToolChange* change = std::get_if<ToolChange>(&record)) {
        m_currentTool = change->tool.number;
        // The section header names the tool that cuts it, which the CL only states afterwards.
        if (inSection() && !m_sectionLoadedTool) {
            std::get<SectionBegin>(m_records[m_openSectionRecord]).toolNumber = change->tool.number;
            m_sectionLoadedTool = true;
        }
    }
    m_records.push_back(std::move(record));
    m_sources.push_back({m_openSection, line});
}

void ClBuilder::beginSection(SectionBegin section, int line)
{
    endSection(line);
    section.toolNumber = m_currentTool;
    m_openSection = m_sectionCount++;
    m_openSectionRecord = m_records.size();
    m_sectionLoadedTool = false;
    m_records.push_back(std::move(section));
    m_sources.push_back({m_openSection, line});
}

bool ClBuilder::endSection(int line)
{
    if (!inSection())
        return false;
    m_records.push_back(SectionEnd{});
    m_sources.push_back({m_openSection, line});
    m_openSection = -1;
    return true;
}

void ClBuilder::warn(std::string message, int line, int column)
{
    m_warnings.push_back(base::warningDiagnostic(std::move(message), m_fileName, line, column));
}

base::Error ClBuilder::error(std::string message, int line, int column) const
{
    return base::makeError(std::move(message), m_fileName, line, column);
}

ClImport ClBuilder::finish(int lastLine)
{
    endSection(lastLine);
    ClImport out;
    for (std::size_t i = 0; i < m_records.size(); ++i)
        out.toolpath.add(std::move(m_records[i]), m_sources[i]);
    out.warnings = mergeRepeatedWarnings(std::move(m_warnings));
    m_records.clear();
    m_sources.clear();
    return out;
}

}  // namespace camwb::toolpath
