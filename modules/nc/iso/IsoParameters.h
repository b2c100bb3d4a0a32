// RS274NGC parameters: numbered #1..#5399 in one flat array, named #<local> per call frame and
// #<_global> for the whole program. Names are compared without blanks and case (as LinuxCNC does).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::nc::iso {

inline constexpr int kParameterCount = 5400;  // #0 reads 0, #1..#5399 are settable
inline constexpr int kCallArguments = 30;     // #1..#30 are local to a subroutine call

// A parameter name as the program wrote it, normalised: blanks removed, lower case.
std::string normaliseName(std::string_view written);

class Parameters {
public:
    Parameters();

    double numbered(int index) const { return m_numbered[static_cast<std::size_t>(index)]; }
    void setNumbered(int index, double value) { m_numbered[static_cast<std::size_t>(index)] = value; }

    // `name` normalised. Locals live in the innermost call frame, globals start with '_'.
    std::optional<double> named(const std::string& name) const;
    void setNamed(const std::string& name, double value);
    bool exists(const std::string& name) const { return named(name).has_value(); }

    // A subroutine call: #1..#30 saved and set from the arguments, a fresh local scope.
    void pushFrame(const double* arguments, int count);
    void popFrame();
    int depth() const { return static_cast<int>(m_frames.size()); }

private:
    struct Frame {
        std::array<double, kCallArguments> savedArguments{};
        std::map<std::string, double, std::less<>> locals;
    };
    std::vector<double> m_numbered;
    std::map<std::string, double, std::less<>> m_globals;
    std::vector<Frame> m_frames;  // [0] the main program
};

}  // namespace camwb::nc::iso
