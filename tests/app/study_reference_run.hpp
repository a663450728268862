#pragma once
// One uninterrupted run of the small study (tests/app/data/small-study.json, its "render"
// settings, under the validation layer), for the tests of signstim_app_study_tests that compare
// other runs against it (study_cli_test.cpp) or read what it wrote (study_annotations_cli_test.cpp).
// Read only: a test that changes it copies it first. CTest runs the tests that use it in one
// process (tests/app/study_tests.cmake, ONE_PROCESS), so it is rendered once (18-23 s of CPU
// under gcc); a test run apart makes its own, in a folder named after it.
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace signstim::test {

inline const std::filesystem::path& smallStudyReferenceRun() {
    static const std::filesystem::path dir = [] {
        const std::string scenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();
        const std::string small = std::filesystem::path(SIGNSTIM_SOURCE_DIR).append("tests/app/data/small-study.json").string();
        const std::filesystem::path d =
            freshDir(SIGNSTIM_BINARY_DIR, "study_cli_test",
                     std::string("reference-") + ::testing::UnitTest::GetInstance()->current_test_info()->name(), false);
        const auto r = runSignstim("study " + shellQuote(small) + " --quiet --out " + shellQuote(d.string()) + " --scenes " +
                                       shellQuote(scenes),
                                   Capture::StdoutAndStderr, "SIGNSTIM_VALIDATION=1");
        EXPECT_EQ(r.status, 0) << r.output;
        EXPECT_NE(r.output.find("study complete"), std::string::npos) << r.output;
        return d;
    }();
    return dir;
}

}  // namespace signstim::test
