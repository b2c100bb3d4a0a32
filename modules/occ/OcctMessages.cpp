#include "occ/detail/OcctMessages.h"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Message_PrinterOStream.hxx>

#include <mutex>

namespace camwb::occ::detail {
namespace {

thread_local OcctMessageCapture* t_capture = nullptr;

std::string trimmed(const std::string& text)
{
    // OCCT pads its messages with stars, blanks and line breaks ("**** ERR StepFile : ...").
    const char* const padding = " \t\r\n*";
    const std::size_t first = text.find_first_not_of(padding);
    if (first == std::string::npos)
        return {};
    std::string out = text.substr(first, text.find_last_not_of(padding) - first + 1);
    for (char& c : out)
        if (c == '\n' || c == '\r')
            c = ' ';
    return out;
}

// Messages with no capture on their thread (OCCT's own background work) are dropped: nobody asked.
class CapturePrinter : public Message_Printer {
protected:
    void send(const TCollection_AsciiString& text, const Message_Gravity gravity) const override
    {
        if (t_capture == nullptr || gravity < Message_Warning)
            return;
        t_capture->add(gravity >= Message_Fail, text.ToCString());
    }
};

void installPrinter()
{
    static std::once_flag once;
    std::call_once(once, [] {
        const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
        messenger->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
        messenger->AddPrinter(new CapturePrinter);
    });
}

}  // namespace

OcctMessageCapture::OcctMessageCapture() : m_previous(t_capture)
{
    installPrinter();
    t_capture = this;
}

OcctMessageCapture::~OcctMessageCapture() { t_capture = m_previous; }

void OcctMessageCapture::add(bool failure, std::string text)
{
    text = trimmed(text);
    if (!text.empty())
        (failure ? m_failures : m_warnings).push_back(std::move(text));
}

std::string OcctMessageCapture::failureNote() const
{
    return m_failures.empty() ? std::string() : " (OCCT: " + m_failures.front() + ")";
}

}  // namespace camwb::occ::detail
