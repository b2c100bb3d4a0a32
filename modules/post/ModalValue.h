// Modal output words: a value is written only when its formatted text differs from the last one
// written (or always, when forced). Qt-free; the script bindings and later C++ block templates
// share it. Comparing the formatted text, not the raw double, keeps float noise out of the NC.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace camwb::post {

class ModalValue {
public:
    ModalValue(std::string prefix, bool force) : m_prefix(std::move(prefix)), m_force(force) {}

    // "" when unchanged (and not forced), else prefix + text; remembers the text.
    std::string output(const std::string& text)
    {
        if (!m_force && m_last && *m_last == text)
            return {};
        m_last = text;
        return m_prefix + text;
    }
    // Forgets the last value, so the next output is written.
    void reset() { m_last.reset(); }
    const std::optional<std::string>& last() const { return m_last; }

private:
    std::string m_prefix;
    bool m_force = false;
    std::optional<std::string> m_last;
};

}  // namespace camwb::post
