// What the job setup panel asks of a job's stock and machine without widgets: whether the stock
// is one at all, the stock's corners and centres a work origin can be put on, and whether the
// machine's linear travels can take the stock at all.
#pragma once

#include "base/Vec.h"
#include "document/Job.h"
#include "kinematics/Machine.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::document {

// Why the stock's box cannot be machined: a max not above its min on some axis (a typo the post
// and the simulator would otherwise take for "no stock"), or a box beyond any machine's reach.
// Nothing when it is a box, or when there is none (min and max all zero: a lathe job's).
// The job file and the setup panel refuse such a stock with this reason.
std::optional<std::string> stockProblem(const Stock& stock);

// Points of the stock box a work origin is commonly put on (front = min y, left = min x).
enum class StockAnchor { TopFrontLeft, BottomFrontLeft, TopCentre, Centre, BottomCentre };

// The anchor on the stock's resolved box, in work coordinates.
base::Vec3 stockAnchor(const Stock& stock, StockAnchor anchor);

// Moves the job's program zero to `origin` (model file coordinates) and keeps everything where it
// is on the part: an explicit stock and the operations' height overrides (work coordinates) shift
// by the difference. A "from model" stock is resolved again by whoever reloads the model.
void moveOrigin(Job& job, const base::Vec3& origin);

// One line per linear axis (X, Y, Z) whose travel is shorter than the stock's size along it,
// e.g. "Y: stock 420 mm, travel 400 mm". Empty when it fits, or when there is no stock box.
// Axes the machine does not have are not checked (a lathe has no Y).
std::vector<std::string> travelShortfalls(const kinematics::Machine& machine, const Stock& stock);

}  // namespace camwb::document
