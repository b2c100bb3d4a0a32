#include "RoundTripFixture.h"

#include "LinuxCncModel.h"
#include "MotionCompare.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace camwb::external::test {

using namespace toolpath;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

post::PostContext fixedContext()
{
    post::PostContext context;
    context.programName = "ROUNDTRIP";
    context.dateEpochSeconds = 1767225600;
    context.user = "ci";
    context.version = "test";
    return context;
}

// stderr of a clean rs274 run holds only its "executing" banner.
std::string unexpectedErrors(const std::string& errors)
{
    std::istringstream in(errors);
    std::string result;
    for (std::string line; std::getline(in, line);)
        if (line != "executing" && !line.empty())
            result += line + "\n";
    return result;
}

}  // namespace

double toolLengthMm(int tool) { return 10.0 * tool + 0.5; }

void LinuxCncRoundTrip::SetUp()
{
    auto loaded = post::PostProcessor::load(std::string(CAMWB_TEST_DATA_DIR) + "/posts/linuxcnc.js");
    ASSERT_TRUE(loaded.ok()) << loaded.error().toString();
    m_post = std::move(loaded).value();

    const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name)
        if (c == '/')
            c = '_';
    // Per process and test: ctest runs tests in parallel, and two build trees may run at once.
    m_dir =
        (std::filesystem::path(testing::TempDir()) / ("camwb-linuxcnc-" + std::to_string(::getpid())) / name).string();
    std::filesystem::create_directories(m_dir);
    std::vector<Rs274Tool> tools;
    for (int n = 1; n <= 20; ++n)
        tools.push_back({n, toolLengthMm(n), 0});
    m_toolTable = m_dir + "/tools.tbl";
    const base::Status written = writeRs274ToolTable(m_toolTable, tools);
    ASSERT_TRUE(written.ok()) << written.error().toString();
}

void LinuxCncRoundTrip::TearDown()
{
    if (!HasFailure()) {
        std::error_code ignored;
        std::filesystem::remove_all(m_dir, ignored);
        std::filesystem::remove(std::filesystem::path(m_dir).parent_path(), ignored);  // only when empty
    }
}

std::optional<RoundTrip> LinuxCncRoundTrip::postAndRead(const Toolpath& cl)
{
    RoundTrip result;
    auto start = std::chrono::steady_clock::now();
    auto posted = m_post->run(cl, fixedContext());
    result.postSeconds = secondsSince(start);
    EXPECT_TRUE(posted.ok()) << posted.error().toString();
    if (!posted.ok())
        return std::nullopt;
    result.posted = std::move(posted).value();
    for (const base::Diagnostic& message : result.posted.messages)
        ADD_FAILURE() << "post warning: " << message.message << " (line " << message.line << ")";

    result.ngcPath = m_dir + "/program.ngc";
    std::ofstream(result.ngcPath, std::ios::binary) << result.posted.text;
    auto run = runRs274(CAMWB_RS274, result.ngcPath, m_toolTable, m_dir);
    EXPECT_TRUE(run.ok()) << run.error().toString();
    if (!run.ok())
        return std::nullopt;
    result.run = std::move(run).value();
    std::ofstream(m_dir + "/trace.txt", std::ios::binary) << result.run.trace;
    EXPECT_EQ(result.run.exitCode, 0) << result.ngcPath << "\n" << result.run.errors;
    EXPECT_EQ(unexpectedErrors(result.run.errors), "") << result.ngcPath;
    if (result.run.exitCode != 0)
        return std::nullopt;

    start = std::chrono::steady_clock::now();
    auto program = readRs274Trace(result.run.trace);
    result.readSeconds = secondsSince(start);
    EXPECT_TRUE(program.ok()) << program.error().toString() << " (" << m_dir << "/trace.txt)";
    if (!program.ok())
        return std::nullopt;
    result.program = std::move(program).value();
    return result;
}

void LinuxCncRoundTrip::expectRoundTrip(const Toolpath& cl)
{
    std::optional<RoundTrip> trip = postAndRead(cl);
    if (!trip)
        return;
    const auto start = std::chrono::steady_clock::now();
    const std::optional<std::string> difference = compareMotion(expectedMotion(cl), trip->program.motion);
    trip->compareSeconds = secondsSince(start);
    EXPECT_FALSE(difference) << *difference << "\n(NC: " << trip->ngcPath << ", trace: " << m_dir << "/trace.txt)";

    std::vector<double> lengths;
    for (const Record& record : cl.records())
        if (const auto* change = std::get_if<ToolChange>(&record))
            lengths.push_back(toolLengthMm(change->tool.number));
    ASSERT_EQ(trip->program.toolLengthOffsetsMm.size(), lengths.size()) << "one G43 H<n> per tool change";
    for (std::size_t i = 0; i < lengths.size(); ++i)
        EXPECT_NEAR(trip->program.toolLengthOffsetsMm[i], lengths[i], 1e-4) << "tool change " << i;
    EXPECT_TRUE(trip->program.messages.empty()) << "operator message: " << trip->program.messages.front();
    EXPECT_TRUE(trip->program.programEnd) << "no M2";
}

}  // namespace camwb::external::test
