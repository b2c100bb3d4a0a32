// The op tests' check of feed kinds: every feed move an operation writes says which of its
// section's feeds it uses, and its feed is that one, so a post may write the feed as a parameter.
#pragma once

#include "toolpath/Toolpath.h"

#include <string>
#include <vector>

namespace camwb::ops::test {

// Fails the calling test for a feed move with no kind, one outside a section, or one whose feed
// differs from its section's feed of its kind (naming the record).
void expectFeedKindsAgreeWithSections(const toolpath::Toolpath& toolpath);

// The kind of every feed move (Linear, Arc) in order.
std::vector<toolpath::FeedKind> feedKinds(const toolpath::Toolpath& toolpath);

using toolpath::feedKindOf;

}  // namespace camwb::ops::test
