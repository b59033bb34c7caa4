// SPDX-License-Identifier: Apache-2.0
// The one JSON reading path every file format goes through: what it refuses, how it says so, and
// that no document, however deep or large, can crash or stall it.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "child_process.hpp"
#include "test_files.hpp"
#include "util/json_fields.hpp"

namespace fgr {
namespace {

using nlohmann::json;

// The message parse_document throws for `text`, or "" when it parses.
std::string refusal(const std::string& text) {
    try {
        json_fields::parse_document(text, "view 'v.json'");
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

std::string nested_arrays(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

TEST(JsonDocument, ParsesAWellFormedDocument) {
    const json document = json_fields::parse_document(R"({"a": [1, {"b": "c"}], "d": null})", "x");
    EXPECT_EQ(document.at("a").at(1).at("b"), "c");
}

// Deep nesting is refused before the JSON library sees it; the limit's own depth parses.
TEST(JsonDocument, RefusesNestingDeeperThanTheLimitBeforeParsing) {
    const int limit = json_fields::kMaxDocumentDepth;
    EXPECT_EQ(refusal(R"({"version": )" + nested_arrays(limit - 1) + "}"), "");
    EXPECT_EQ(refusal(R"({"version": )" + nested_arrays(limit) + "}"),
              "view 'v.json': arrays and objects nest deeper than 64 levels");
    // The reproducer that crashed the camera-path reader through a dump of the whole value.
    EXPECT_EQ(refusal(R"({"format": "fgr-camera-path", "version": )" + nested_arrays(100000) + "}"),
              "view 'v.json': arrays and objects nest deeper than 64 levels");
    // Brackets inside strings are text.
    EXPECT_EQ(refusal(R"({"name": ")" + std::string(1000, '[') + R"("})"), "");
}

// A second copy of a key would silently win: refused, in nested objects too, while the same key in
// sibling objects is fine.
TEST(JsonDocument, RefusesAKeyTwiceInOneObject) {
    EXPECT_EQ(refusal(R"({"a": 1, "a": 2})"),
              "view 'v.json': the key \"a\" appears twice in one object");
    EXPECT_EQ(refusal(R"({"x": [{"b": 1, "c": 2, "b": 3}]})"),
              "view 'v.json': the key \"b\" appears twice in one object");
    EXPECT_EQ(refusal(R"({"x": {"a": 1}, "y": {"a": 2}, "a": {"a": 3}})"), "");
}

// The JSON library stops at a NUL as at the end of the text, so bytes after one would pass unread.
TEST(JsonDocument, RefusesANulByteAndAnythingAfterTheValue) {
    EXPECT_EQ(refusal(std::string("{\"a\": 1}\0{\"b\": 2}", 17)),
              "view 'v.json': a NUL byte at offset 8 (a JSON file is text)");
    EXPECT_NE(refusal(R"({"a": 1} {"b": 2})"), "");
    EXPECT_NE(refusal(R"({"a": 1} x)"), "");
    EXPECT_EQ(refusal("{\"a\": 1}\n  \n"), "") << "trailing white space is no value";
    EXPECT_NE(refusal(""), "");
}

// Syntax errors name the file and stay one short line, whatever the token they quote.
TEST(JsonDocument, SyntaxErrorsAreOneBoundedLine) {
    const std::string message = refusal("{\"a\": \"" + std::string(100000, 'x') + "\n\"}");
    ASSERT_TRUE(message.starts_with("view 'v.json': parse error at line ")) << message;
    EXPECT_LE(message.size(), 200u);
    EXPECT_EQ(message.find('\n'), std::string::npos);
    EXPECT_EQ(message.find("json.exception"), std::string::npos);
}

// A shown value is a bounded excerpt: huge and deep values cost no more than small ones.
TEST(JsonDocument, ShownValuesAreShortWhateverTheirSize) {
    EXPECT_EQ(json_fields::shown(json("abc")), "\"abc\"");
    EXPECT_EQ(json_fields::shown(json::array({1, 2})), "[1,2]");
    EXPECT_EQ(json_fields::shown(json::object({{"k", true}})), "{\"k\":true}");
    EXPECT_EQ(json_fields::shown(json(std::string(1000, 'y'))),
              "\"" + std::string(39, 'y') + "...");
    json deep = json::array();
    for (int i = 0; i < 100000; ++i) deep = json::array({std::move(deep)});
    EXPECT_EQ(json_fields::shown(deep), std::string(40, '[') + "...");
    json wide = json::array();
    for (int i = 0; i < 1000000; ++i) wide.push_back(i);
    EXPECT_EQ(json_fields::shown(wide), "[0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,1...");
}

TEST(JsonDocument, ReadDocumentRefusesWhatIsNoRegularFileOrTooLarge) {
    const test::TempDir dir("fgr_json_document");
    const auto file = dir.path() / "a.json";
    test::write_text(file, R"({"a": 1})");
    EXPECT_EQ(json_fields::read_document(file, 100, "scene 'a.json'").at("a"), 1);
    EXPECT_THROW(
        {
            try {
                json_fields::read_document(file, 3, "scene 'a.json'");
            } catch (const std::runtime_error& error) {
                EXPECT_STREQ(error.what(),
                             "scene 'a.json': file too large (8 bytes; the limit is 3)");
                throw;
            }
        },
        std::runtime_error);
    EXPECT_THROW(json_fields::read_document(dir.path(), 100, "scene"), std::runtime_error);
}

}  // namespace
}  // namespace fgr
