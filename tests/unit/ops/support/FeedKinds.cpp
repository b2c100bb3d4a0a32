#include "FeedKinds.h"

#include "toolpath/RecordNames.h"

#include <gtest/gtest.h>

#include <optional>

namespace camwb::ops::test {

using namespace camwb::toolpath;

std::vector<FeedKind> feedKinds(const Toolpath& toolpath)
{
    std::vector<FeedKind> kinds;
    for (const Record& r : toolpath.records())
        if (std::holds_alternative<Linear>(r) || std::holds_alternative<Arc>(r))
            kinds.push_back(feedKindOf(r));
    return kinds;
}

void expectFeedKindsAgreeWithSections(const Toolpath& toolpath)
{
    std::optional<SectionFeeds> feeds;
    for (std::size_t i = 0; i < toolpath.size(); ++i) {
        const Record& r = toolpath.record(i);
        if (const auto* begin = std::get_if<SectionBegin>(&r))
            feeds = begin->feeds;
        else if (std::holds_alternative<SectionEnd>(r))
            feeds.reset();
        if (!std::holds_alternative<Linear>(r) && !std::holds_alternative<Arc>(r))
            continue;
        const FeedKind kind = feedKindOf(r);
        const double feed =
            std::holds_alternative<Linear>(r) ? std::get<Linear>(r).feedMmPerMin : std::get<Arc>(r).feedMmPerMin;
        ASSERT_TRUE(feeds.has_value()) << "record " << i << ": a feed move outside a section";
        ASSERT_NE(kind, FeedKind::Unspecified) << "record " << i << " (" << recordName(r) << "): no feed kind";
        EXPECT_GT(feeds->of(kind), 0) << "record " << i << ": the section has no " << name(kind) << " feed";
        EXPECT_EQ(feed, feeds->of(kind)) << "record " << i << " (" << recordName(r) << ", " << name(kind)
                                         << "): its feed is not the section's " << name(kind) << " feed";
    }
}

}  // namespace camwb::ops::test
