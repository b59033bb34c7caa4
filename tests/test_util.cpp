// The small helpers in host/util that the host's concepts share: each does what its callers'
// messages and figures rely on.

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <stdexcept>
#include <string>

#include "util/errors.hpp"
#include "util/strings.hpp"
#include "util/timing.hpp"

namespace fgr {
namespace {

TEST(UtilErrors, ErrnoMessageIsTheCLibrarysText) {
    EXPECT_EQ(errno_message(ENOENT), "No such file or directory");
    EXPECT_EQ(errno_message(EACCES), "Permission denied");
}

TEST(UtilErrors, FailWriteThrowsTheWritersOneLineMessage) {
    try {
        fail_write("out/x.png", "No space left on device");
        ADD_FAILURE() << "fail_write returned";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "cannot write 'out/x.png': No space left on device");
    }
}

// Messages quote a path as it is, between single quotes; a quote inside is not escaped.
TEST(UtilStrings, QuotedPathIsItsTextBetweenSingleQuotes) {
    EXPECT_EQ(quoted("out/mandel bulb.png"), "'out/mandel bulb.png'");
    EXPECT_EQ(quoted("it's.exr"), "'it's.exr'");
    EXPECT_EQ(quoted(""), "''");
}

// A moment set back by a known amount: the figures are at least that, in their unit, and not
// wildly more (the bound allows for a loaded machine; no test here times anything).
TEST(UtilTiming, SecondsSinceAndElapsedMsCountFromTheStartInTheirUnits) {
    using namespace std::chrono_literals;
    const auto two_seconds_ago = std::chrono::steady_clock::now() - 2s;
    const double seconds = seconds_since(two_seconds_ago);
    EXPECT_GE(seconds, 2.0);
    EXPECT_LT(seconds, 62.0);
    const double ms = elapsed_ms(two_seconds_ago);
    EXPECT_GE(ms, 2000.0);
    EXPECT_LT(ms, 62000.0);
}

}  // namespace
}  // namespace fgr
