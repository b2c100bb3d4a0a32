#include "toolpath/ClBuilder.h"

namespace camwb::toolpath {

void ClBuilder::add(Record record, int line)
{
    if (const ToolChange* change = std::get_if<ToolChange>(&record)) {
        m_currentTool = change->tool.number;
        // The section header names the tool that cuts it, which the CL only states afterwards.
        if (inSection() && !m_sectionLoadedTool) {
            std::get<SectionBegin>(m_path.record(m_openSectionRecord)).toolNumber = change->tool.number;
            m_sectionLoadedTool = true;
        }
    }
    m_path.add(std::move(record), {m_openSection, line});
}

void ClBuilder::beginSection(SectionBegin section, int line)
{
    endSection(line);
    section.toolNumber = m_currentTool;
    m_openSection = m_sectionCount++;
    m_openSectionRecord = m_path.size();
    m_sectionLoadedTool = false;
    m_path.add(std::move(section), {m_openSection, line});
}

bool ClBuilder::endSection(int line)
{
    if (!inSection())
        return false;
    m_path.add(SectionEnd{}, {m_openSection, line});
    m_openSection = -1;
    return true;
}

void ClBuilder::warn(std::string message, int line, int column)
{
    // The same message on many lines (NX writes a PAINT statement every few lines) is one warning
    // that lists the lines, so that the one that matters is not buried, and a file with a million
    // of them holds one.
    const auto [at, fresh] = m_warningIndex.try_emplace(message, m_warnings.size());
    if (fresh) {
        m_warnings.push_back({base::warningDiagnostic(std::move(message), m_fileName, line, column), {}, 0});
        return;
    }
    Warning& repeated = m_warnings[at->second];
    if (repeated.repeats++ < kLinesListed)
        repeated.lines.push_back(line);
}

base::Error ClBuilder::error(std::string message, int line, int column) const
{
    return base::makeError(std::move(message), m_fileName, line, column);
}

ClImport ClBuilder::finish(int lastLine)
{
    endSection(lastLine);
    ClImport out;
    out.toolpath = std::move(m_path);
    for (Warning& warning : m_warnings) {
        if (warning.repeats > 0) {
            std::string list;
            for (std::size_t k = 0; k < warning.lines.size(); ++k)
                list += (k ? ", " : "") + std::to_string(warning.lines[k]);
            if (warning.repeats > kLinesListed)
                list += " and " + std::to_string(warning.repeats - kLinesListed) + " more";
            warning.first.message += " (also on line" + std::string(warning.repeats > 1 ? "s " : " ") + list + ")";
        }
        out.warnings.push_back(std::move(warning.first));
    }
    m_warnings.clear();
    m_warningIndex.clear();
    m_path = Toolpath();
    return out;
}

}  // namespace camwb::toolpath
