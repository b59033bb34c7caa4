// SPDX-License-Identifier: Apache-2.0
// Renders the golden set (golden_set.hpp) again and compares every case with its record.

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "golden_set.hpp"

namespace fgr::golden {
namespace {

const std::filesystem::path kRecordFile = FGR_TEST_GOLDEN_SET;

std::vector<GoldenRecord> recorded_or_none() {
    try {
        return read_records(kRecordFile);
    } catch (const std::exception&) {
        return {};  // GoldenSet.TheRecordIsReadableAndCoversEveryListedScene says why
    }
}

std::vector<std::string> figure_keys(const std::vector<std::string>& figures) {
    std::vector<std::string> keys;
    for (const std::string& figure : figures) keys.push_back(figure_key(figure));
    return keys;
}

class GoldenSet : public testing::TestWithParam<GoldenRecord> {};

}  // namespace

// Failures name the case, not the bytes of its record.
void PrintTo(const GoldenRecord& record, std::ostream* out) { *out << record.golden_case.name; }

namespace {

TEST_P(GoldenSet, RendersAsRecorded) {
    const GoldenRecord& record = GetParam();
    const Observation seen = observe(record.golden_case);
    const Observation& expected = record.observation;
    EXPECT_EQ(seen.exit_code, expected.exit_code);
    EXPECT_EQ(seen.errors, expected.errors);
    EXPECT_EQ(seen.output_hash.empty(), expected.output_hash.empty());
    if (seen.device == expected.device) {
        // The same compiler and CPU: every bit and every figure.
        EXPECT_EQ(seen.output_hash, expected.output_hash) << "the image changed";
        EXPECT_EQ(seen.figures, expected.figures);
    } else {
        // Another device rounds differently: the same figures printed, values aside.
        EXPECT_EQ(figure_keys(seen.figures), figure_keys(expected.figures));
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, GoldenSet, testing::ValuesIn(recorded_or_none()),
                         [](const testing::TestParamInfo<GoldenRecord>& param) {
                             return param.param.golden_case.name;
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GoldenSet);

TEST(GoldenSetRecord, IsReadableAndCoversEveryListedScene) {
    const std::vector<GoldenRecord> records = read_records(kRecordFile);
    std::vector<std::string> recorded;
    for (const GoldenRecord& record : records) recorded.push_back(record.golden_case.name);
    std::vector<std::string> listed;
    for (const GoldenCase& golden_case : golden_cases(listed_scene_ids())) {
        listed.push_back(golden_case.name);
    }
    EXPECT_EQ(recorded, listed) << "record the set again (tests/golden/README.md)";
}

}  // namespace
}  // namespace fgr::golden
