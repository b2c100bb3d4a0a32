#include "toolpath/ClBuilder.h"

namespace camwb::toolpath {

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
    m_warnings.push_back(base::makeError(std::move(message), m_fileName, line, column));
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
    out.warnings = std::move(m_warnings);
    m_records.clear();
    m_sources.clear();
    return out;
}

}  // namespace camwb::toolpath
