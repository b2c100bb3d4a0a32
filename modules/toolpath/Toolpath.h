// A toolpath: CL records in order, each with the source reference of the operation that made it.
#pragma once

#include "toolpath/ClRecords.h"

#include <cstddef>
#include <vector>

namespace camwb::toolpath {

class Toolpath {
public:
    void add(Record record, SourceRef source = {});
    void append(const Toolpath& other);
    // Room for `records` in all, so that a reader of a large file does not regrow and copy them.
    void reserve(std::size_t records);

    std::size_t size() const { return m_records.size(); }
    bool empty() const { return m_records.empty(); }
    const Record& record(std::size_t i) const { return m_records[i]; }
    // For builders that complete a record after the fact (an importer's section header).
    Record& record(std::size_t i) { return m_records[i]; }
    const SourceRef& source(std::size_t i) const { return m_sources[i]; }
    const std::vector<Record>& records() const { return m_records; }

private:
    std::vector<Record> m_records;
    std::vector<SourceRef> m_sources;
};

// Counts by kind, for reports ("12 lines, 4 arcs").
struct ToolpathStats {
    std::size_t rapids = 0, lines = 0, arcs = 0, helices = 0, cycles = 0, toolChanges = 0;
    std::size_t fiveAxis = 0;  // ToolAxisMove, rapid or feed
};
ToolpathStats statistics(const Toolpath& toolpath);

}  // namespace camwb::toolpath
