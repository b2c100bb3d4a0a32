#include "BenchProgram.h"

#include "base/NumberFormat.h"

#include <fstream>
#include <string>
#include <variant>

namespace camwb::bench {

using namespace toolpath;

Toolpath benchProgram(std::size_t moves)
{
    Toolpath program;
    program.add(SectionBegin{"Benchmark", "profile", 1, {900, 300, 0, 0, 0}});
    program.add(ToolChange{Tool{1, "Flat D6", "flat", 6, 0, 20, 45, 3}});
    program.add(Spindle{4000, true});
    program.add(Rapid{{0, 0, 5}});
    Vec3 at{0, 0, 2};
    program.add(Linear{at, 300});
    for (std::size_t i = 0; i < moves; i += 4) {
        // Ten groups to the right, then the same ten back: the path stays in its field.
        const std::size_t group = i / 4;
        const double radius = 2 + static_cast<double>(group % 10 % 4);
        const double dx = group % 20 < 10 ? 1.0 : -1.0;
        // Line, quarter arc, line, quarter arc (both clockwise going right, counter-clockwise back).
        Vec3 next = at + Vec3{dx * 0.5, 0.5, 0};
        program.add(Linear{next, 900});
        at = next;
        Vec3 center = at + Vec3{0, -radius, 0};
        next = center + Vec3{dx * radius, 0, 0};
        program.add(Arc{next, center, {0, 0, 1}, dx > 0, 0, 900});
        at = next;
        next = at + Vec3{0, -0.5, i % 200 == 0 ? -0.01 : 0};
        program.add(Linear{next, 900});
        at = next;
        center = at + Vec3{dx * radius, 0, 0};
        next = center + Vec3{0, radius, 0};
        program.add(Arc{next, center, {0, 0, 1}, dx > 0, 0, 900});
        at = next;
    }
    program.add(Rapid{{at.x, at.y, 5}});
    program.add(SectionEnd{});
    return program;
}

std::string asFreeCadDump(const Toolpath& program)
{
    const base::NumberFormat f{6, true};
    std::string out = "(This output produced with the dump post processor)\n(Path: Benchmark)\n";
    Vec3 at;
    auto xyz = [&](const Vec3& p) { return "X:" + f.format(p.x) + " Y:" + f.format(p.y) + " Z:" + f.format(p.z); };
    for (const Record& record : program.records()) {
        if (const auto* r = std::get_if<Rapid>(&record)) {
            out += "Command G0 [ " + xyz(r->to) + " ]\n";
            at = r->to;
        } else if (const auto* l = std::get_if<Linear>(&record)) {
            out += "Command G1 [ F:" + f.format(l->feedMmPerMin / 60) + " " + xyz(l->to) + " ]\n";
            at = l->to;
        } else if (const auto* a = std::get_if<Arc>(&record)) {
            out += std::string("Command ") + (a->clockwise ? "G2" : "G3") + " [ F:" + f.format(a->feedMmPerMin / 60) +
                   " I:" + f.format(a->center.x - at.x) + " J:" + f.format(a->center.y - at.y) + " K:0 " + xyz(a->to) +
                   " ]\n";
            at = a->to;
        } else if (const auto* t = std::get_if<ToolChange>(&record)) {
            out += "Command M6 [ T:" + std::to_string(t->tool.number) + " ]\n";
        } else if (const auto* s = std::get_if<Spindle>(&record)) {
            out += "Command M3 [ S:" + f.format(s->rpm) + " ]\n";
        }
    }
    return out;
}

std::string asAptSource(const Toolpath& program)
{
    const base::NumberFormat f{6, true};
    std::string out = "PARTNO/BENCH\nUNITS/MM\n";
    Vec3 at;
    double feed = -1;
    auto xyz = [&](const Vec3& p) { return f.format(p.x) + "," + f.format(p.y) + "," + f.format(p.z); };
    auto fedrat = [&](double mmPerMin) {
        if (mmPerMin != feed)
            out += "FEDRAT/" + f.format(mmPerMin) + ",MMPM\n";
        feed = mmPerMin;
    };
    for (const Record& record : program.records()) {
        if (const auto* r = std::get_if<Rapid>(&record)) {
            out += "RAPID\nGOTO/" + xyz(r->to) + "\n";
            at = r->to;
        } else if (const auto* l = std::get_if<Linear>(&record)) {
            fedrat(l->feedMmPerMin);
            out += "GOTO/" + xyz(l->to) + "\n";
            at = l->to;
        } else if (const auto* a = std::get_if<Arc>(&record)) {
            fedrat(a->feedMmPerMin);
            // NX: counter-clockwise about (i,j,k), so k = -1 for a clockwise arc seen from +Z.
            out += "CIRCLE/" + xyz(a->center) + ",0,0," + (a->clockwise ? "-1" : "1") + "," +
                   f.format((at - a->center).length()) + "\nGOTO/" + xyz(a->to) + "\n";
            at = a->to;
        } else if (const auto* t = std::get_if<ToolChange>(&record)) {
            out += "CUTTER/" + f.format(t->tool.diameterMm) + "\nLOADTL/" + std::to_string(t->tool.number) + "\n";
        } else if (const auto* s = std::get_if<Spindle>(&record)) {
            out += "SPINDL/" + f.format(s->rpm) + ",RPM,CLW\n";
        } else if (const auto* b = std::get_if<SectionBegin>(&record)) {
            out += "TOOL PATH/" + b->operationName + ",TOOL,Flat D6\n";
        } else if (std::holds_alternative<SectionEnd>(record)) {
            out += "END-OF-PATH\n";
        }
    }
    return out + "FINI\n";
}

long currentRssKb()
{
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0)
            return std::stol(line.substr(6));
    return 0;
}

}  // namespace camwb::bench
