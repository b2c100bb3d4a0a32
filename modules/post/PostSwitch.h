// Which machines a post serves (by its machine ids and the controls it declares), and what becomes
// of a job's post property values when the job changes to another post: a value is kept only where
// the new post has a property of the same name and type that accepts it. Qt-free, so the CLI, the
// document and the GUI share one rule.
#pragma once

#include "kinematics/Machine.h"
#include "post/PostInfo.h"

#include <map>
#include <string>
#include <vector>

namespace camwb::post {

// Whether `info` writes for `control`: the post names no controls, the control is unknown (empty or
// "any", a test machine), or it is one of the post's.
bool servesControl(const PostInfo& info, const std::string& control);
// Whether the post can post for `machine`: a post that lists its machines drives only those (the
// kernel refuses the others); otherwise its controls decide.
bool servesMachine(const PostInfo& info, const kinematics::Machine& machine);

struct DroppedProperty {
    std::string name;
    std::string value;   // the value as the job had it
    std::string reason;  // "heidenhain-itnc530 has no property 'sequenceStep'", ...
};

struct PostSwitch {
    std::map<std::string, std::string> kept;  // the values the new post takes, by name
    std::vector<DroppedProperty> dropped;     // by name
};

// The job's property values (text by name, as in Job::postProperties) moved from post `from` to
// post `to`: kept when `to` has a property of that name, of the same type as in `from` (not
// checked when `from` does not declare it, e.g. a post that could not be loaded) and the value is
// valid for it. `perOperationOnly`: an operation's values, which `to` must take per operation.
PostSwitch switchPost(const std::map<std::string, std::string>& values, const PostInfo& from, const PostInfo& to,
                      bool perOperationOnly = false);

}  // namespace camwb::post
