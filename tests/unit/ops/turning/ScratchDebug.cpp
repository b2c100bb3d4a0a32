#include "GrooveTestUtil.h"
#include "ops/turning/GrooveSweeps.h"
#include "sim/TurningCheck.h"
#include <gtest/gtest.h>
#include <cstdio>
#include <cstdlib>
namespace camwb::ops::test {
TEST(Scratch, Dump)
{
    const char* e = std::getenv("GROOVE");
    if (!e) GTEST_SKIP();
    double v[13];
    std::sscanf(e, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], &v[8], &v[9], &v[10], &v[11], &v[12]);
    GrooveParams p;
    p.groove = {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9]};
    p.stepFactor = v[10]; p.infeedMm = v[11]; p.safetyMm = v[12];
    auto mv = turning::grooveMoves({sim::grooveGeometry(p.groove), v[9], v[10], v[11], v[12]}, "g", {});
    ASSERT_TRUE(mv.ok()) << mv.error().message;
    for (auto& c : mv->calls) std::printf("%s ", c.c_str());
    std::printf("\n");
    auto r = computeGroove(p, grooveTool(v[9]), 0);
    ASSERT_TRUE(r.ok()) << r.error().message;
    sim::TurningOptions o; o.insert.widthMm = v[9];
    auto rep = sim::checkTurning(r->toolpath, sim::grooveStock(p.groove), sim::grooveOffsetPart(p.groove), o);
    auto mvs = resolvedMoves(r->toolpath);
    for (auto& f : rep.findings) {
        std::printf("finding kind %d record %d value %g at Z %g X %g\n", (int)f.kind, (int)f.record, f.valueMm, f.at.z, f.at.x);
        int first = 0;
        while (first < (int)r->toolpath.size() && !std::holds_alternative<toolpath::Rapid>(r->toolpath.record(first))) ++first;
        int k = (int)f.record - first;  // index into mvs
        for (int j = std::max(0, k - 12); j <= std::min((int)mvs.size() - 1, k + 3); ++j)
            std::printf("  %s%d %s X%.4f Z%.4f\n", j == k ? ">" : " ", j, mvs[j].rapid ? "G0" : "G1", mvs[j].x, mvs[j].z);
    }
    auto g = sim::grooveGeometry(p.groove);
    std::printf("R %g %g S %g %g T %g %g U %g %g\n", g.r.x, g.r.y, g.s.x, g.s.y, g.t.x, g.t.y, g.u.x, g.u.y);
    // move index -> call: print boundaries by dumping calls count per move not available
}
}
