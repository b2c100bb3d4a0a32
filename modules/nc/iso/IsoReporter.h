// Collects the diagnostics of one ISO interpretation: file, line, column, severity, keeping at most
// InterpretOptions::maxDiagnostics and counting the rest, so that a broken million-line program
// cannot fill memory with messages.
#pragma once

#include "nc/Diagnostic.h"

#include <cstddef>
#include <string>
#include <vector>

namespace camwb::nc::iso {

class Reporter {
public:
    Reporter(std::vector<Diagnostic>& out, std::size_t& dropped, std::string file, std::size_t maxKept) :
        m_out(out),
        m_dropped(dropped),
        m_file(std::move(file)),
        m_maxKept(maxKept)
    {
    }

    void report(Severity severity, int line, int column, std::string message)
    {
        if (severity == Severity::Error)
            m_errors = true;
        if (m_out.size() >= m_maxKept) {
            ++m_dropped;
            return;
        }
        m_out.push_back({severity, m_file, line, column, std::move(message)});
    }
    void error(int line, int column, std::string message) { report(Severity::Error, line, column, std::move(message)); }
    void warning(int line, int column, std::string message)
    {
        report(Severity::Warning, line, column, std::move(message));
    }
    bool hadErrors() const { return m_errors; }
    void setFile(std::string file) { m_file = std::move(file); }

private:
    std::vector<Diagnostic>& m_out;
    std::size_t& m_dropped;
    std::string m_file;
    std::size_t m_maxKept;
    bool m_errors = false;
};

}  // namespace camwb::nc::iso
