// The five-axis example job (resources/examples/example-five-axis.camwb) and its model, loaded once
// per test binary, for the tests of its 3+2 and swarf operations.
#pragma once

#include "document/JobFile.h"
#include "document/JobPipeline.h"

#include <gtest/gtest.h>

#include <string>

namespace camwb::document::test {

inline const std::string kFiveAxisJob =
    std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-five-axis.camwb";

struct LoadedJob {
    Job job;
    occ::Model model;
};

inline const LoadedJob& fiveAxis()
{
    static const LoadedJob loaded = [] {
        auto job = loadJob(kFiveAxisJob);
        EXPECT_TRUE(job.ok()) << job.error().toString();
        auto model = loadJobModel(job.value());
        EXPECT_TRUE(model.ok()) << model.error().toString();
        return LoadedJob{job.value(), model.value()};
    }();
    return loaded;
}

// The job with its stock as a plain box (the example's is a blank, file version 9): for the tests
// of which version the operations themselves need.
inline Job withBoxStock(Job job)
{
    job.stock.shape = Stock::Shape::Box;
    job.stock.blankPath.clear();
    return job;
}

}  // namespace camwb::document::test
