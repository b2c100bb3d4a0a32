// Collects the records of a CL import with their SourceRef, the sections they fall in and the
// warnings. Shared by the APT and FreeCAD dump readers so that both number, open and close
// sections the same way (see ClImport.h for the SourceRef convention).
#pragma once

#include "toolpath/ClImport.h"
#include "toolpath/ClText.h"

#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace camwb::toolpath {

class ClBuilder {
public:
    explicit ClBuilder(std::string fileName) : m_fileName(std::move(fileName)) {}
    // Sizes the toolpath for a text of `bytes`: a CL statement is rarely under 32 bytes, and the
    // room a shorter file does not fill is never touched, so it costs no memory.
    void expectText(std::size_t bytes) { m_path.reserve(bytes / 32); }

    // Adds a record of the statement at `line` to the open section (or to none).
    void add(Record record, int line);
    // Closes the open section (at the same line) and opens a new one. Its toolNumber is the tool
    // loaded inside it if it loads one, else the tool active when it starts (0: none yet).
    void beginSection(SectionBegin section, int line);
    // Closes the open section; false when none is open.
    bool endSection(int line);
    bool inSection() const { return m_openSection >= 0; }

    std::size_t size() const { return m_path.size(); }
    Record& record(std::size_t index) { return m_path.record(index); }

    void warn(std::string message, int line, int column = 0);
    void warn(std::string message, TextPos pos) { warn(std::move(message), pos.line, pos.column); }
    base::Error error(std::string message, int line, int column = 0) const;
    base::Error error(std::string message, TextPos pos) const
    {
        return error(std::move(message), pos.line, pos.column);
    }

    // Closes a section still open (at `lastLine`) and hands the import over.
    ClImport finish(int lastLine);

private:
    std::string m_fileName;
    Toolpath m_path;
    struct Warning {
        base::Diagnostic first;
        std::vector<int> lines;   // of the first kLinesListed repeats
        std::size_t repeats = 0;  // all of them
    };
    static constexpr std::size_t kLinesListed = 8;
    std::vector<Warning> m_warnings;
    std::unordered_map<std::string, std::size_t> m_warningIndex;  // message -> m_warnings index
    int m_sectionCount = 0;
    int m_openSection = -1;  // index of the open section, -1 outside sections
    std::size_t m_openSectionRecord = 0;
    bool m_sectionLoadedTool = false;
    int m_currentTool = 0;
};

}  // namespace camwb::toolpath
