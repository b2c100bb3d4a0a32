// For tests that numbers in NC, files and messages do not follow the C library's locale: puts the
// process in a locale that writes 1.5 as "1,5" for the test's scope, as Qt does from the user's
// environment in the GUI (QApplication sets LC_ALL from LANG). scripts/install-deps.sh generates
// de_DE.UTF-8; where no such locale is installed, active() is false and the test skips: a
// platform capability that is missing, not a result.
#pragma once

#include <clocale>
#include <string>

namespace camwb::test {

class DecimalCommaLocale {
public:
    DecimalCommaLocale()
    {
        if (const char* current = std::setlocale(LC_ALL, nullptr))
            m_saved = current;
        for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "de_DE", "fr_FR.UTF-8", "fr_FR.utf8", "nl_NL.UTF-8"})
            if (std::setlocale(LC_ALL, name) != nullptr && std::localeconv()->decimal_point[0] == ',') {
                m_name = name;
                return;
            }
        restore();
    }
    ~DecimalCommaLocale() { restore(); }
    DecimalCommaLocale(const DecimalCommaLocale&) = delete;
    DecimalCommaLocale& operator=(const DecimalCommaLocale&) = delete;

    bool active() const { return !m_name.empty(); }
    const std::string& name() const { return m_name; }
    // Why a test skips: `if (!comma.active()) GTEST_SKIP() << comma.missing();`
    static const char* missing()
    {
        return "no decimal-comma locale installed (scripts/install-deps.sh makes de_DE.UTF-8)";
    }

private:
    void restore() { std::setlocale(LC_ALL, m_saved.empty() ? "C" : m_saved.c_str()); }
    std::string m_saved;
    std::string m_name;
};

}  // namespace camwb::test
