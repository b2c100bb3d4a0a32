// Private: what OpenCASCADE says while it reads a file. OCCT prints through its global messenger
// (a STEP syntax error comes out as "**** ERR StepFile ..." on stdout, coloured, from every
// program that loads a model); instead, its stream printers are replaced once by a printer that
// hands each message to the capture active on the calling thread, so a failed load can say why.
#pragma once

#include <string>
#include <vector>

namespace camwb::occ::detail {

class OcctMessageCapture {
public:
    OcctMessageCapture();  // routes this thread's OCCT messages here until destroyed
    ~OcctMessageCapture();
    OcctMessageCapture(const OcctMessageCapture&) = delete;
    OcctMessageCapture& operator=(const OcctMessageCapture&) = delete;

    // Failures and warnings, as OCCT worded them (trimmed, one line each), in order.
    const std::vector<std::string>& failures() const { return m_failures; }
    const std::vector<std::string>& warnings() const { return m_warnings; }
    // " (OCCT: first failure)" or "" when OCCT reported none: the tail of a load error.
    std::string failureNote() const;

    void add(bool failure, std::string text);

private:
    OcctMessageCapture* m_previous;
    std::vector<std::string> m_failures;
    std::vector<std::string> m_warnings;
};

}  // namespace camwb::occ::detail
