// What "Simulate" simulates: the NC inspector's trace of the editor's program, on the machine it
// was traced on; with the job's stock and model when the editor holds the job's own posted
// program (an NC file opened apart may be for another part: it plays without a stock).
#pragma once

#include "gui/sim/SimRun.h"

#include <QString>

#include <optional>

namespace camwb::gui {

class NcInspector;
class Workbench;

// nullopt (and `why`) when there is nothing to simulate yet.
std::optional<SimRunRequest> simulationRequest(const NcInspector& inspector, const Workbench& workbench,
                                               bool editorShowsPostedProgram, double resolutionMm, QString* why);

}  // namespace camwb::gui
