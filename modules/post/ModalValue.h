// Modal output words: a value is written only when its formatted text differs from the last one
// written (or always, when forced). Qt-free; the script bindings and the C++ block templates share
// it. Comparing the formatted text, not the raw double, keeps float noise out of the NC.
#pragma once

#include <string>
#include <string_view>
#include <utility>

namespace camwb::post {

class ModalValue {
public:
    ModalValue(std::string prefix, bool force) : m_prefix(std::move(prefix)), m_force(force) {}

    // Whether `text` would be written now (changed or forced), without remembering it.
    bool wouldWrite(std::string_view text) const { return m_force || !m_known || m_last != text; }
    // Whether `text` must be written; remembers it either way.
    bool update(std::string_view text)
    {
        const bool changed = !m_known || m_last != text;
        if (changed)
            m_last.assign(text);
        m_known = true;
        return changed || m_force;
    }
    // "" when unchanged (and not forced), else prefix + text; remembers the text.
    std::string output(std::string_view text) { return update(text) ? m_prefix + std::string(text) : std::string(); }
    // Forgets the last value, so the next output is written.
    void reset() { m_known = false; }
    // Written every time from now on (an inverse-time F), or only on change again.
    void setForce(bool force) { m_force = force; }

    const std::string& prefix() const { return m_prefix; }
    bool known() const { return m_known; }
    const std::string& last() const { return m_last; }

private:
    std::string m_prefix;
    std::string m_last;
    bool m_force = false;
    bool m_known = false;
};

}  // namespace camwb::post
