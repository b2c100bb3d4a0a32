// Test fixture for the LinuxCNC round trip: CL toolpath -> posts/linuxcnc.js -> NC file -> rs274
// -> canonical trace -> motion, compared with what LinuxCNC should do for the CL (LinuxCncModel.h).
#pragma once

#include "Rs274Runner.h"
#include "Rs274Trace.h"

#include "post/PostProcessor.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace camwb::external::test {

// Tool n of the rs274 tool table: length 10 n + 0.5 mm, so that each G43 H<n> is told apart;
// diameter 0, so that G41/G42 leave the programmed path where it is.
double toolLengthMm(int tool);

struct RoundTrip {
    post::PostOutput posted;
    Rs274Run run;
    Rs274Program program;
    std::string ngcPath;
    double postSeconds = 0, readSeconds = 0, compareSeconds = 0;
};

class LinuxCncRoundTrip : public testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;  // keeps the NC file and trace of a failed test for reading

    // Posts `cl`, runs rs274 on it and reads the trace back. Fails the test (and returns nullopt)
    // when the post fails, rs274 reports anything or the trace cannot be read.
    std::optional<RoundTrip> postAndRead(const toolpath::Toolpath& cl);

    // postAndRead, then: the motion equals expectedMotion(cl), every tool change applied its
    // tool's length offset, no operator messages, and M2 ended the program.
    void expectRoundTrip(const toolpath::Toolpath& cl);

    std::optional<post::PostProcessor> m_post;
    std::string m_dir;        // scratch folder of this test
    std::string m_toolTable;  // tools 1..20
};

}  // namespace camwb::external::test
