#include "nc/iso/IsoParameters.h"

namespace camwb::nc::iso {

std::string normaliseName(std::string_view written)
{
    std::string name;
    name.reserve(written.size());
    for (char c : written) {
        if (c == ' ' || c == '\t' || c == '\r')
            continue;
        name += (c >= 'A' && c <= 'Z') ? static_cast<char>(c + ('a' - 'A')) : c;
    }
    return name;
}

Parameters::Parameters() : m_numbered(kParameterCount, 0.0), m_frames(1) {}

std::optional<double> Parameters::named(const std::string& name) const
{
    const auto& scope = !name.empty() && name[0] == '_' ? m_globals : m_frames.back().locals;
    const auto it = scope.find(name);
    if (it == scope.end())
        return std::nullopt;
    return it->second;
}

void Parameters::setNamed(const std::string& name, double value)
{
    auto& scope = !name.empty() && name[0] == '_' ? m_globals : m_frames.back().locals;
    scope.insert_or_assign(name, value);
}

void Parameters::pushFrame(const double* arguments, int count)
{
    Frame frame;
    for (int i = 0; i < kCallArguments; ++i) {
        frame.savedArguments[static_cast<std::size_t>(i)] = m_numbered[static_cast<std::size_t>(i + 1)];
        m_numbered[static_cast<std::size_t>(i + 1)] = i < count ? arguments[i] : 0.0;
    }
    m_frames.push_back(std::move(frame));
}

void Parameters::popFrame()
{
    if (m_frames.size() <= 1)
        return;
    for (int i = 0; i < kCallArguments; ++i)
        m_numbered[static_cast<std::size_t>(i + 1)] = m_frames.back().savedArguments[static_cast<std::size_t>(i)];
    m_frames.pop_back();
}

}  // namespace camwb::nc::iso
