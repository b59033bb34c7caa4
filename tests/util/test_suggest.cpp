// SPDX-License-Identifier: Apache-2.0
// "Did you mean": the edit distance the suggestions rank by, and which names are near enough to
// offer.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "util/suggest.hpp"

namespace fgr {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(edit_distance("", ""), 0u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
    EXPECT_EQ(edit_distance("abc", ""), 3u);
    EXPECT_EQ(edit_distance("render", "render"), 0u);
    EXPECT_EQ(edit_distance("rendr", "render"), 1u);           // an insertion
    EXPECT_EQ(edit_distance("renderr", "render"), 1u);         // a deletion
    EXPECT_EQ(edit_distance("pxth", "path"), 1u);              // a substitution
    EXPECT_EQ(edit_distance("mandlebulb", "mandelbulb"), 1u);  // a swap of neighbours
    EXPECT_EQ(edit_distance("--widht", "--width"), 1u);
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(edit_distance("ca", "abc"), 3u);  // the restricted form: no edit after a swap
    EXPECT_EQ(edit_distance("Mandelbulb", "mandelbulb"), 0u);  // ASCII case is no edit
    EXPECT_EQ(edit_distance("abc", "xyz"), edit_distance("xyz", "abc"));
}

TEST(ClosestName, OffersTheNearestNameWithinAThirdOfItsLength) {
    const std::vector<std::string> scenes = {"mandelbox", "mandelbulb", "menger", "julia"};
    EXPECT_EQ(closest_name("mandlebulb", scenes), "mandelbulb");
    EXPECT_EQ(closest_name("mandelbux", scenes), "mandelbox");
    EXPECT_EQ(closest_name("Menger", scenes), "menger");      // only its case differs
    EXPECT_EQ(closest_name("mandel", scenes), std::nullopt);  // four letters short of either
    EXPECT_EQ(closest_name("zzz", scenes), std::nullopt);
    EXPECT_EQ(closest_name("julia", scenes), std::nullopt);  // no suggestion for a known name
    const std::vector<std::string> modes = {"shaded", "path", "brute"};
    EXPECT_EQ(closest_name("pth", modes), "path");
    EXPECT_EQ(closest_name("p", modes), std::nullopt);  // one letter is no name to correct
    EXPECT_EQ(closest_name("", modes), std::nullopt);
    EXPECT_EQ(closest_name("anything", {}), std::nullopt);
    // Ties go to the first candidate.
    EXPECT_EQ(closest_name("cat", {"bat", "hat"}), "bat");
}

TEST(DidYouMean, EndsAnUnknownNameMessage) {
    const std::vector<std::string> colours = {"point", "planes", "axes", "iterations"};
    EXPECT_EQ(did_you_mean("iteratons", colours), "; did you mean 'iterations'?");
    EXPECT_EQ(did_you_mean("rainbow", colours), "");
    EXPECT_EQ(unknown_name_message("unknown colour 'iteratons'", "iteratons", colours, " (see X)"),
              "unknown colour 'iteratons'; did you mean 'iterations'?");
    EXPECT_EQ(unknown_name_message("unknown colour 'rainbow'", "rainbow", colours, " (see X)"),
              "unknown colour 'rainbow' (see X)");
}

}  // namespace
}  // namespace fgr
