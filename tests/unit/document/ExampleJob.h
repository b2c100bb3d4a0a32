// The bundled example job and its model, loaded once for the document tests that compute on it.
#pragma once

#include "document/JobFile.h"
#include "document/JobPipeline.h"

#include <gtest/gtest.h>

#include <string>

namespace camwb::document::test {

inline const std::string kExampleJob = std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-block.camwb";

struct Example {
    Job job;
    occ::Model model;
};

inline const Example& example()
{
    static const Example loaded = [] {
        auto job = loadJob(kExampleJob);
        EXPECT_TRUE(job.ok()) << job.error().toString();
        auto model = loadJobModel(job.value());
        EXPECT_TRUE(model.ok()) << model.error().toString();
        return Example{job.value(), model.value()};
    }();
    return loaded;
}

}  // namespace camwb::document::test
