// Which machines a post serves (post.machines, post.controls) and what a job's property values
// become when the job changes post: kept only with the same name and type and a valid value.
#include "post/PostSwitch.h"
#include "PostTestSupport.h"

namespace camwb::post::test {
namespace {

PostInfo loadBundled(const std::string& id)
{
    auto post = PostProcessor::load(kPostsDir + "/" + id + ".js");
    EXPECT_TRUE(post.ok()) << post.error().toString();
    return post.ok() ? post->info() : PostInfo{};
}

kinematics::Machine machine(const std::string& id, const std::string& control)
{
    kinematics::Machine m;
    m.id = id;
    m.control = control;
    return m;
}

TEST(PostControls, BundledPostsDeclareTheControlsOfTheirMachines)
{
    EXPECT_EQ(loadBundled("sinumerik828d-emco").controls, std::vector<std::string>{"sinumerik-828d"});
    EXPECT_EQ(loadBundled("heidenhain-itnc530").controls, std::vector<std::string>{"heidenhain-itnc530"});
    EXPECT_EQ(loadBundled("sinumerik840d").controls, std::vector<std::string>{"sinumerik-840d"});
    EXPECT_EQ(loadBundled("linuxcnc").controls, std::vector<std::string>{"linuxcnc"});
    // Each bundled post's default machine (resources/machines) runs the control it declares.
    for (const char* id : {"sinumerik828d-emco", "heidenhain-itnc530", "sinumerik840d"}) {
        const PostInfo info = loadBundled(id);
        auto found =
            kinematics::findMachine(info.defaultMachine, {std::string(CAMWB_TEST_DATA_DIR) + "/resources/machines"});
        ASSERT_TRUE(found.ok()) << id << ": " << found.error().toString();
        EXPECT_TRUE(servesMachine(info, found.value())) << id << " and " << found->control;
    }
}

TEST(PostControls, AMalformedControlsListIsALoadErrorAtItsLine)
{
    auto post = PostProcessor::load(
        writeScript("badcontrols.js", "var post = {\n  description: \"x\",\n  controls: \"linuxcnc\"\n};\n"));
    ASSERT_FALSE(post.ok());
    EXPECT_NE(post.error().message.find("post.controls must be an array"), std::string::npos);
    EXPECT_EQ(post.error().line, 3);
}

TEST(PostControls, APostServesItsMachinesElseItsControls)
{
    PostInfo byControl;
    byControl.id = "by-control";
    byControl.controls = {"sinumerik-828d", "sinumerik-840d"};
    EXPECT_TRUE(servesMachine(byControl, machine("any828", "sinumerik-828d")));
    EXPECT_TRUE(servesMachine(byControl, machine("any840", "sinumerik-840d")));
    EXPECT_FALSE(servesMachine(byControl, machine("tnc", "heidenhain-itnc530")));
    EXPECT_TRUE(servesMachine(byControl, machine("test", "any")));  // a machine of no particular control
    EXPECT_TRUE(servesMachine(byControl, machine("unknown", "")));

    PostInfo anyControl;
    EXPECT_TRUE(servesMachine(anyControl, machine("tnc", "heidenhain-itnc530")));

    // A post that lists its machines drives only those, whatever their control: the kernel
    // refuses the others.
    PostInfo byMachine = byControl;
    byMachine.machines = {"emco"};
    EXPECT_TRUE(servesMachine(byMachine, machine("emco", "sinumerik-828d")));
    EXPECT_FALSE(servesMachine(byMachine, machine("any828", "sinumerik-828d")));
    EXPECT_TRUE(servesControl(byMachine, "sinumerik-828d"));
    EXPECT_FALSE(servesControl(byMachine, "linuxcnc"));
}

TEST(PostSwitch, KeepsSameNameAndTypeWithAValidValueAndSaysWhyTheOthersAreDropped)
{
    const PostInfo emco = loadBundled("sinumerik828d-emco");
    const PostInfo itnc = loadBundled("heidenhain-itnc530");
    ASSERT_FALSE(emco.properties.empty());
    ASSERT_FALSE(itnc.properties.empty());

    // units is an enum in both, G710 is not one of the iTNC's; sequenceStep exists only on the 828D.
    PostSwitch moved = switchPost({{"units", "G710"}, {"sequenceStep", "5"}}, emco, itnc);
    EXPECT_TRUE(moved.kept.empty());
    ASSERT_EQ(moved.dropped.size(), 2u);
    EXPECT_EQ(moved.dropped[0].name, "sequenceStep");
    EXPECT_EQ(moved.dropped[0].value, "5");
    EXPECT_EQ(moved.dropped[0].reason, "heidenhain-itnc530 has no property 'sequenceStep'");
    EXPECT_EQ(moved.dropped[1].name, "units");
    EXPECT_NE(moved.dropped[1].reason.find("one of mm, inch, not 'G710'"), std::string::npos)
        << moved.dropped[1].reason;

    // The same post on both sides keeps every valid value.
    moved = switchPost({{"units", "G700"}, {"sequenceStep", "5"}}, emco, emco);
    EXPECT_EQ(moved.kept, (std::map<std::string, std::string>{{"units", "G700"}, {"sequenceStep", "5"}}));
    EXPECT_TRUE(moved.dropped.empty());
}

TEST(PostSwitch, ATypeChangeDropsEvenAValueTheNewTypeWouldAccept)
{
    PostInfo from;
    from.id = "from";
    from.properties = {{"units", "", "", PropertyType::Enum, "mm", {}, {}, {"mm", "inch"}},
                       {"numbers", "", "", PropertyType::Bool, "true"},
                       {"text", "", "", PropertyType::String, "a"}};
    PostInfo to = from;
    to.id = "to";
    to.properties[0].type = PropertyType::String;  // "inch" is a valid string, but it means something else
    to.properties[1].perOperation = true;
    const std::map<std::string, std::string> values{{"units", "inch"}, {"numbers", "false"}, {"text", "b"}};

    PostSwitch moved = switchPost(values, from, to);
    EXPECT_EQ(moved.kept, (std::map<std::string, std::string>{{"numbers", "false"}, {"text", "b"}}));
    ASSERT_EQ(moved.dropped.size(), 1u);
    EXPECT_EQ(moved.dropped[0].reason, "'units' is string in to, enum in from");

    // An operation's values: only what the new post takes per operation.
    moved = switchPost(values, from, to, true);
    EXPECT_EQ(moved.kept, (std::map<std::string, std::string>{{"numbers", "false"}}));
    ASSERT_EQ(moved.dropped.size(), 2u);
    EXPECT_EQ(moved.dropped[0].reason, "to does not take 'text' per operation");

    // Without the old post's definitions (it could not be loaded) the new post alone decides.
    moved = switchPost(values, PostInfo{}, to);
    EXPECT_EQ(moved.kept, values);
}

TEST(PostSwitch, AnIntegerOutsideTheNewRangeIsDropped)
{
    PostInfo from;
    from.id = "from";
    from.properties = {{"step", "", "", PropertyType::Integer, "10", 1.0, 1000.0}};
    PostInfo to = from;
    to.id = "to";
    to.properties[0].max = 100;
    PostSwitch moved = switchPost({{"step", "500"}}, from, to);
    EXPECT_TRUE(moved.kept.empty());
    ASSERT_EQ(moved.dropped.size(), 1u);
    EXPECT_NE(moved.dropped[0].reason.find("must be in 1..100"), std::string::npos) << moved.dropped[0].reason;
}

}  // namespace
}  // namespace camwb::post::test
