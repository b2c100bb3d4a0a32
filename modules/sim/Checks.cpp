#include "sim/Checks.h"

#include <algorithm>

namespace camwb::sim {

const char* checkKindName(CheckKind kind)
{
    switch (kind) {
    case CheckKind::RapidInStock:
        return "rapid-in-stock";
    case CheckKind::Gouge:
        return "gouge";
    case CheckKind::HolderCollision:
        return "holder-collision";
    case CheckKind::PlungeNotCentre:
        return "plunge-not-centre-cutting";
    case CheckKind::SpindleOffCutting:
        return "spindle-off-cutting";
    case CheckKind::MachineLimit:
        return "machine-limit";
    case CheckKind::AirCutting:
        return "air-cutting";
    case CheckKind::NoToolShape:
        return "no-tool-shape";
    case CheckKind::UnknownPosition:
        return "unknown-position";
    }
    return "?";
}

void CheckList::add(Check check)
{
    check.moves = std::max(check.moves, 1);
    const std::uint64_t key = (std::uint64_t(check.record + 1) << 4) | std::uint64_t(check.kind);
    auto it = std::lower_bound(m_index.begin(), m_index.end(), key,
                               [](const auto& entry, std::uint64_t k) { return entry.first < k; });
    if (it != m_index.end() && it->first == key && check.record >= 0) {
        Check& kept = m_checks[it->second];
        const int moves = kept.moves + check.moves;
        const double removed = kept.removedMm3 + check.removedMm3;
        // Air cutting adds up its length; the others keep their worst value.
        if (check.kind == CheckKind::AirCutting) {
            const double total = kept.valueMm + check.valueMm;
            kept.valueMm = total;
        } else if (check.valueMm > kept.valueMm) {
            kept = std::move(check);
        }
        kept.moves = moves;
        kept.removedMm3 = removed;
        return;
    }
    m_index.insert(it, {key, m_checks.size()});
    m_checks.push_back(std::move(check));
}

int CheckList::count(base::Severity severity) const
{
    return static_cast<int>(
        std::count_if(m_checks.begin(), m_checks.end(), [severity](const Check& c) { return c.severity == severity; }));
}

}  // namespace camwb::sim
