// The small helpers in host/util that the host's concepts share: each does what its callers'
// messages and figures rely on.

#include <gtest/gtest.h>

#include <cerrno>
#include <string>

#include "util/errors.hpp"

namespace fgr {
namespace {

TEST(UtilErrors, ErrnoMessageIsTheCLibrarysText) {
    EXPECT_EQ(errno_message(ENOENT), "No such file or directory");
    EXPECT_EQ(errno_message(EACCES), "Permission denied");
}

}  // namespace
}  // namespace fgr
