// SPDX-License-Identifier: Apache-2.0
// The small helpers in host/util that the host's concepts share: each does what its callers'
// messages and figures rely on.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "util/errors.hpp"
#include "util/files.hpp"
#include "util/installed_files.hpp"
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
    EXPECT_EQ(quoted("a\nb.png"), "'a\\nb.png'");
}

// Control characters and bytes that are not UTF-8 are escaped, so a file name cannot break a
// message into lines or send the terminal an escape; valid non-ASCII text is kept.
TEST(UtilStrings, PrintableTextEscapesControlCharactersAndBytesThatAreNotUtf8) {
    EXPECT_EQ(printable_text("plain/path-1.ifs.json"), "plain/path-1.ifs.json");
    EXPECT_EQ(printable_text("a\nb\rc\td"), "a\\nb\\rc\\td");
    EXPECT_EQ(printable_text("\x1b[31mred\x7f"), "\\x1b[31mred\\x7f");
    EXPECT_EQ(printable_text(std::string("nul\0byte", 8)), "nul\\x00byte");
    EXPECT_EQ(printable_text("fractale-\xc3\xa9t\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8c\x80"),
              "fractale-\xc3\xa9t\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8c\x80");
    // A stray continuation byte, a lead byte cut short, an overlong '/', a surrogate, past
    // U+10FFFF, a C1 control (U+009B, a terminal's CSI) and a right-to-left override.
    EXPECT_EQ(printable_text("\x80|\xc3|\xc0\xaf|\xed\xa0\x80|\xf4\x90\x80\x80"),
              "\\x80|\\xc3|\\xc0\\xaf|\\xed\\xa0\\x80|\\xf4\\x90\\x80\\x80");
    EXPECT_EQ(printable_text("a\xc2\x9b"
                             "b\xe2\x80\xae"
                             "c"),
              "a\\xc2\\x9bb\\u202ec");
    EXPECT_EQ(printable_path("/tmp/x\ny.so"), "/tmp/x\\ny.so");
}

std::filesystem::path write_bytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
}

// Every byte comes back as it is on disk (NULs, high bytes, no newline translation), into either
// container, and an empty file is no failure.
TEST(UtilFiles, ReadFileBytesReadsTheWholeFile) {
    const test::TempDir dir("fgr_util_files");
    const std::string contents("a\0b\r\n\xff\x80 end", 11);
    const auto file = write_bytes(dir.path() / "bytes.bin", contents);
    std::string text = "left over";
    EXPECT_EQ(read_file_bytes(file, text), "");
    EXPECT_EQ(text, contents);
    std::vector<unsigned char> bytes;
    EXPECT_EQ(read_file_bytes(file, bytes), "");
    EXPECT_EQ(bytes, std::vector<unsigned char>(contents.begin(), contents.end()));

    const auto empty = write_bytes(dir.path() / "empty.bin", "");
    EXPECT_EQ(read_file_bytes(empty, text), "");
    EXPECT_EQ(text, "");
}

// Each failure gives the reason its callers put in their messages, and leaves nothing read.
TEST(UtilFiles, ReadFileBytesSaysWhyAndLeavesNothingOnFailure) {
    const test::TempDir dir("fgr_util_files");
    std::string text = "left over";
    EXPECT_EQ(read_file_bytes(dir.path() / "missing.bin", text), "No such file or directory");
    EXPECT_EQ(text, "");

    const auto file = write_bytes(dir.path() / "ten.bin", "0123456789");
    std::vector<unsigned char> bytes{1, 2, 3};
    EXPECT_EQ(read_file_bytes(file, bytes, 9), "file too large (10 bytes; the limit is 9)");
    EXPECT_TRUE(bytes.empty());
    EXPECT_EQ(read_file_bytes(file, bytes, 10), "");
    EXPECT_EQ(bytes.size(), 10u);

    text = "left over";
    EXPECT_EQ(read_file_bytes(dir.path(), text), "not a regular file (a directory)");
    EXPECT_EQ(text, "");
}

// A FIFO named like a file is refused at once, never opened for a read that waits for a writer
// forever; the checks for libraries that open paths themselves say the same.
TEST(UtilFiles, FifoIsRefusedWithoutBlocking) {
    const test::TempDir dir("fgr_util_files");
    const auto fifo = dir.path() / "frame.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string text;
    EXPECT_EQ(read_file_bytes(fifo, text), "not a regular file (a FIFO)");
    std::string reason;
    EXPECT_EQ(open_regular_file(fifo, reason), nullptr);
    EXPECT_EQ(reason, "not a regular file (a FIFO)");
    EXPECT_EQ(regular_file_problem(fifo), "not a regular file (a FIFO)");
    EXPECT_EQ(regular_file_problem(dir.path()), "not a regular file (a directory)");

    const auto file = write_bytes(dir.path() / "ten.bin", "0123456789");
    EXPECT_NE(open_regular_file(file, reason), nullptr);
    EXPECT_EQ(reason, "");
    EXPECT_EQ(regular_file_problem(file, 9), "file too large (10 bytes; the limit is 9)");
    EXPECT_EQ(regular_file_problem(file), "");
}

// A moment set back by a known amount: the figures are at least that, in their unit, and not
// wildly more (the bound allows for a loaded machine; no test here times anything).
// The "$schema" fgr writes finds the schema in the build tree as in an installed one: share/ beside
// the executable's bin/ (the tests' binary sits in the build tree's bin/).
TEST(UtilInstalledFiles, SchemaReferenceIsTheFileUriOfTheSchemaBesideTheExecutable) {
    const std::filesystem::path dir = schema_dir();
    EXPECT_EQ(dir, (executable_dir() / ".." / "share" / "fgr" / "schemas").lexically_normal());
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "camera-path.schema.json")) << dir;
    EXPECT_EQ(schema_reference("camera-path.schema.json"),
              file_uri(dir / "camera-path.schema.json"));
    EXPECT_EQ(schema_reference("camera-path.schema.json").rfind("file:///", 0), 0u);
}

// RFC 8089 and 3986: a path's bytes outside the unreserved set and '/' are percent-encoded, so a
// space, '#', '%' or a non-ASCII name cannot end or change the URI.
TEST(UtilInstalledFiles, FileUriPercentEncodesWhatAPathMayHold) {
    EXPECT_EQ(file_uri("/usr/share/fgr/schemas/a.schema.json"),
              "file:///usr/share/fgr/schemas/a.schema.json");
    EXPECT_EQ(file_uri("/home/me/my fgr/#1 100%/\xc3\xbc~_-.json"),
              "file:///home/me/my%20fgr/%231%20100%25/%C3%BC~_-.json");
}

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
