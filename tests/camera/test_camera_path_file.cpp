// SPDX-License-Identifier: Apache-2.0
// Camera path JSON files: what the viewer saves is what `fgr render --camera-path FILE` reads back,
// and every malformed file is refused with a one-line reason.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "camera/camera.hpp"
#include "camera/camera_path_file.hpp"
#include "fuzz_rng.hpp"
#include "json_mutation.hpp"
#include "util/installed_files.hpp"

namespace fgr {
namespace {

CameraPathFile sample_path() {
    CameraPathFile file;
    file.scene = "mandelbulb";
    file.path.name = "recorded";
    file.path.keyframes = {{0.0f, {{2.0f, -2.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, {0, 0, 1}, 60.0f}},
                           {2.0f, {{0.5f, -3.0f, 0.25f}, {0.1f, 0.0f, 0.0f}, {0, 0, 1}, 45.5f}},
                           {5.5f, {{-1.0f, 1.0f, 2.0f}, {0.0f, 0.2f, 0.0f}, {0, 1, 0}, 30.0f}}};
    return file;
}

std::string keyframes_json(const std::string& keyframes) {
    return R"({"format": "fgr-camera-path", "version": 1, "scene": "s", "name": "n", )"
           R"("keyframes": )" +
           keyframes + "}";
}

constexpr const char* kKeyframe0 = R"({"time": 0, "position": [1, 0, 0], "target": [0, 0, 0]})";

std::string two_keyframes(const std::string& second) {
    return keyframes_json(std::string("[") + kKeyframe0 + ", " + second + "]");
}

TEST(CameraPathFile, JsonRoundTripKeepsEveryKeyframeExactly) {
    const CameraPathFile original = sample_path();
    const CameraPathFile parsed = parse_camera_path_json(camera_path_json(original));
    EXPECT_EQ(parsed.scene, "mandelbulb");
    EXPECT_EQ(parsed.path.name, "recorded");
    ASSERT_EQ(parsed.path.keyframes.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        const Keyframe& a = original.path.keyframes[i];
        const Keyframe& b = parsed.path.keyframes[i];
        EXPECT_EQ(a.time, b.time);
        EXPECT_EQ(a.view.position, b.view.position);
        EXPECT_EQ(a.view.target, b.view.target);
        EXPECT_EQ(a.view.up, b.view.up);
        EXPECT_EQ(a.view.fov_degrees, b.view.fov_degrees);
    }
    // The parsed path evaluates like the original.
    const CameraView mid = evaluate_camera_path(parsed.path, 3.0f);
    const CameraView expected = evaluate_camera_path(original.path, 3.0f);
    EXPECT_EQ(mid.position, expected.position);
}

// A deep zoom's keyframes differ by less than float's step: written and read back, positions and
// targets keep every bit of their double values, and the path evaluates to the same views.
TEST(CameraPathFile, JsonRoundTripKeepsDoublePrecision) {
    CameraPathFile original;
    original.scene = "mandelbulb";
    original.path.name = "deep";
    const glm::dvec3 near_surface(0.1234567890123456, -0.6543210987654321, 0.3141592653589793);
    const glm::dvec3 step(1e-12, -3e-13, 7.77e-12);
    for (int key = 0; key < 3; ++key) {
        const CameraView view{near_surface + step * double(key),
                              near_surface + glm::dvec3(0.0, 0.0, 2e-6) + step * double(key),
                              {0, 1, 0},
                              0.125f};
        original.path.keyframes.push_back({float(key), view});
    }
    // Float cannot tell these keyframes apart.
    ASSERT_EQ(glm::vec3(original.path.keyframes[0].view.position),
              glm::vec3(original.path.keyframes[1].view.position));
    const CameraPathFile parsed = parse_camera_path_json(camera_path_json(original));
    ASSERT_EQ(parsed.path.keyframes.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(parsed.path.keyframes[i].view.position, original.path.keyframes[i].view.position);
        EXPECT_EQ(parsed.path.keyframes[i].view.target, original.path.keyframes[i].view.target);
    }
    for (double t : {0.25, 1.0, 1.6}) {
        EXPECT_EQ(evaluate_camera_path(parsed.path, t).position,
                  evaluate_camera_path(original.path, t).position);
    }
    // Through a file too.
    const auto dir = std::filesystem::temp_directory_path() / "fgr_camera_path_file_deep_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    write_camera_path_file(dir / "deep.json", original);
    const CameraPathFile from_file = read_camera_path_file(dir / "deep.json");
    std::filesystem::remove_all(dir);
    EXPECT_EQ(from_file.path.keyframes[2].view.position, original.path.keyframes[2].view.position);
    EXPECT_EQ(from_file.path.keyframes[2].view.target, original.path.keyframes[2].view.target);
}

TEST(CameraPathFile, MissingUpAndFovTakeDefaults) {
    const CameraPathFile file = parse_camera_path_json(
        two_keyframes(R"({"time": 1, "position": [0, 1, 0], "target": [0, 0, 0]})"));
    EXPECT_EQ(file.path.keyframes[1].view.up, glm::vec3(0, 0, 1));
    EXPECT_EQ(file.path.keyframes[1].view.fov_degrees, 60.0f);
}

TEST(CameraPathFile, MalformedFilesAreRefusedWithTheReason) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"{not json", "not valid JSON"},
        {"[1, 2]", "must be a JSON object"},
        {R"({"format": "other", "version": 1})", "\"format\""},
        // Not a string: was a JSON type_error that escaped as an exception of another kind.
        {R"({"format": 3, "version": 1})", "\"format\""},
        {R"({"version": 1})", "\"format\""},
        {R"({"format": "fgr-camera-path", "version": 2, "keyframes": []})", "version"},
        {keyframes_json("{}"), "\"keyframes\" must be an array"},
        {keyframes_json(std::string("[") + kKeyframe0 + "]"), "at least two keyframes"},
        {two_keyframes(R"({"time": 0, "position": [0, 1, 0], "target": [0, 0, 0]})"),
         "keyframe 1 \"time\" must be after"},
        {two_keyframes(R"({"time": 1, "position": [0, 1], "target": [0, 0, 0]})"),
         "keyframe 1 \"position\" must be an array of 3 numbers"},
        {two_keyframes(R"({"time": 1, "target": [0, 0, 0]})"),
         "keyframe 1 \"position\" is missing"},
        {two_keyframes(R"({"time": 1, "position": [0, "a", 0], "target": [0, 0, 0]})"),
         "must be a number"},
        {two_keyframes(R"({"time": 1, "position": [0, 1e39, 0], "target": [0, 0, 0]})"),
         "must be finite"},
        {two_keyframes(R"({"time": 1, "position": [0, 0, 0], "target": [0, 0, 0]})"),
         "keyframe 1: position equals target"},
        {two_keyframes(R"({"time": 1, "position": [0, 1, 0], "target": [0, 0, 0], "fov": 180})"),
         "keyframe 1: fov 180 outside (0, 180)"},
        {two_keyframes(R"({"time": 1, "position": [0, 1, 0], "target": [0, 0, 0], "up": [0,0,0]})"),
         "keyframe 1: up is zero or parallel to the view direction"},
        {two_keyframes(R"({"position": [0, 1, 0], "target": [0, 0, 0]})"), "\"time\" is missing"},
        // A misspelt key never passes silently, at the top level or in a keyframe.
        {keyframes_json(std::string("[") + kKeyframe0 + ", " + kKeyframe0 + "], \"nmae\": \"x\""),
         "top level: unknown key \"nmae\""},
        {two_keyframes(R"({"time": 1, "position": [0, 1, 0], "target": [0, 0, 0], "fvo": 50})"),
         "keyframe 1: unknown key \"fvo\""},
        {R"({"format": "fgr-camera-path", "version": 1, "scene": 3, "keyframes": []})",
         "\"scene\" must be a string"},
        {R"({"$schema": 3, "format": "fgr-camera-path", "version": 1, "keyframes": []})",
         "\"$schema\" 3 must be a string"},
    };
    for (const auto& [text, reason] : cases) {
        try {
            parse_camera_path_json(text);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find(reason), std::string::npos)
                << "for " << text << " got: " << error.what();
            EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
        }
    }
}

// The check plugins' keyframes get (view_validation.hpp): a keyframe whose camera basis would be
// NaN or infinite in float is refused, naming it.
TEST(CameraPathFile, KeyframesWhoseBasisWouldNotBeFiniteAreRefused) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"time": 1, "position": [1e30, 1e30, 1e30], "target": [-1e30, -1e30, -1e30]})",
         "keyframe 1: position and target 3.46e+30 apart: too far apart for a camera basis"},
        {R"({"time": 1, "position": [0, -1e30, 0], "target": [0, 1e30, 0], "up": [1, 0, 0]})",
         "keyframe 1: position and target 2e+30 apart: too far apart"},
        {R"({"time": 1, "position": [0, 0, 0], "target": [1e-30, 0, 0]})",
         "keyframe 1: position and target 1e-30 apart: too close together for a camera basis"},
        {R"({"time": 1, "position": [0, 1, 0], "target": [0, 0, 0], "up": [0, 2, 0]})",
         "keyframe 1: up is zero or parallel to the view direction"},
        {R"({"time": 1, "position": [0, 0, 3], "target": [0, 0, 0]})",
         "keyframe 1: up is zero or parallel to the view direction"},
        {R"({"time": 1, "position": [0, 1, 0], "target": [0, 0, 0], "up": [1e30, 0, 1e30]})",
         "keyframe 1: up too long for float"},
    };
    for (const auto& [keyframe, reason] : cases) {
        try {
            parse_camera_path_json(two_keyframes(keyframe));
            ADD_FAILURE() << "accepted: " << keyframe;
        } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find(reason), std::string::npos)
                << "for " << keyframe << " got: " << error.what();
            EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
        }
    }
    // Close to those limits but fine: the basis is finite and uses the given up.
    const CameraPathFile file = parse_camera_path_json(two_keyframes(
        R"({"time": 1, "position": [0, 1e-15, 0], "target": [0, 0, 0], "up": [0, 1, 1e-3]})"));
    const CameraBasis basis = camera_basis(file.path.keyframes[1].view);
    EXPECT_NEAR(basis.up.z, 1.0f, 1e-6f);
    EXPECT_NEAR(basis.forward.y, -1.0f, 1e-6f);
}

// "version" is compared as the integer it is: no wrap-around to 1, no rounding.
TEST(CameraPathFile, VersionMustBeTheInteger1) {
    const auto with_version = [](const std::string& version) {
        return R"({"format": "fgr-camera-path", "version": )" + version +
               R"(, "keyframes": [{"time": 0, "position": [1, 0, 0], "target": [0, 0, 0]},
                                  {"time": 1, "position": [0, 1, 0], "target": [0, 0, 0]}]})";
    };
    EXPECT_EQ(parse_camera_path_json(with_version("1")).path.keyframes.size(), 2u);
    for (const std::string version : {"4294967297", "18446744073709551617", "1.5", "1.0", "\"1\"",
                                      "-1", "0", "2", "true", "null", "[1]"}) {
        try {
            parse_camera_path_json(with_version(version));
            ADD_FAILURE() << "version " << version << " accepted";
        } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find("unsupported \"version\""), std::string::npos)
                << "version " << version << ": " << error.what();
        }
    }
    try {
        parse_camera_path_json(with_version("4294967297"));
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "unsupported \"version\" 4294967297 (this fgr reads version 1)");
    }
}

TEST(CameraPathFile, FilesAreWrittenAtomicallyAndReadBack) {
    const auto directory = std::filesystem::temp_directory_path() / "fgr_camera_path_file_test";
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
    const auto file = directory / "path.json";
    write_camera_path_file(file, sample_path());
    EXPECT_EQ(read_camera_path_file(file).path.keyframes.size(), 3u);
    // Only the file itself: no temporaries left beside it.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory),
                            std::filesystem::directory_iterator()),
              1);
    EXPECT_THROW(write_camera_path_file(directory / "missing" / "p.json", sample_path()),
                 std::runtime_error);
    try {
        read_camera_path_file(directory / "absent.json");
        ADD_FAILURE() << "read a missing file";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("absent.json"), std::string::npos);
    }
    std::ofstream(directory / "bad.json") << "{";
    try {
        read_camera_path_file(directory / "bad.json");
        ADD_FAILURE() << "read a broken file";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("bad.json': not valid JSON"), std::string::npos)
            << error.what();
    }
    std::filesystem::remove_all(directory);
}

// What the viewer saves names its JSON Schema (schemas/camera-path.schema.json) beside the running
// executable, for editors; reading takes "$schema" and does not read it.
TEST(CameraPathFile, WrittenFilesNameTheirSchemaAndReadBack) {
    const nlohmann::json written = nlohmann::json::parse(camera_path_json(sample_path()));
    EXPECT_EQ(written.at("$schema"), schema_reference("camera-path.schema.json"));
    EXPECT_EQ(parse_camera_path_json(written.dump()).path.keyframes.size(), 3u);
    nlohmann::json elsewhere = written;
    elsewhere["$schema"] = "https://example.org/camera-path.schema.json";
    EXPECT_EQ(parse_camera_path_json(elsewhere.dump()).path.name, "recorded");
}

// A value nested 100000 deep where "version" or "format" stands (which once crashed the reader
// printing it), a key given twice, bytes after a NUL or after the document: refused, one line.
TEST(CameraPathFile, HostileDocumentsAreRefusedWithOneLine) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    const std::string valid = camera_path_json(sample_path());
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"format": "fgr-camera-path", "version": )" + deep + R"(, "keyframes": []})",
         "nest deeper than 64 levels"},
        {R"({"format": )" + deep + R"(, "version": 1, "keyframes": []})",
         "nest deeper than 64 levels"},
        {R"({"format": "fgr-camera-path", "version": 1, "version": 1, "keyframes": []})",
         "the key \"version\" appears twice"},
        {valid + std::string(1, '\0') + "{}", "a NUL byte at offset"},
        {valid + "{}", "not valid JSON"},
    };
    for (const auto& [text, reason] : cases) {
        try {
            parse_camera_path_json(text);
            ADD_FAILURE() << "accepted: " << text.substr(0, 80);
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find(reason), std::string::npos)
                << "for " << text.substr(0, 80) << " got: " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            EXPECT_LT(message.size(), 400u) << message.substr(0, 400);
        }
    }
}

// 10^4 seeded mutations (FGR_FUZZ_CASES, FGR_FUZZ_SEED) of valid files: of the text, its structure
// and its values. Each is read or refused with one line, never a crash; what is read writes back
// to a file that reads the same.
TEST(FuzzCameraPath, SeededCasesNeverCrash) {
    const std::vector<std::string> seeds = {
        camera_path_json(sample_path()),
        two_keyframes(R"({"time": 1, "position": [0, 1, 0], "target": [0, 0, 0], "fov": 50})")};
    const std::uint64_t base = test::fuzz_base_seed(0x43616d5061746831);  // "CamPath1"
    const std::uint64_t cases = test::fuzz_case_count();
    std::uint64_t accepted = 0;
    for (std::uint64_t i = 0; i < cases; ++i) {
        const std::uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        std::string text = seeds[rng.below(seeds.size())];
        test::mutate_document(text, rng, rng.range(1, 3));
        try {
            const CameraPathFile file = parse_camera_path_json(text);
            ++accepted;
            const CameraPathFile again = parse_camera_path_json(camera_path_json(file));
            ASSERT_EQ(again.path.keyframes.size(), file.path.keyframes.size()) << "seed " << seed;
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            ASSERT_FALSE(message.empty()) << "seed " << seed;
            ASSERT_EQ(message.find('\n'), std::string::npos) << "seed " << seed << ": " << message;
            ASSERT_LT(message.size(), 400u) << "seed " << seed << ": " << message;
        }
    }
    // Both outcomes are exercised, not just refusals.
    if (cases >= 1000) {
        EXPECT_GT(accepted, cases / 20);
        EXPECT_LT(accepted, cases * 19 / 20);
    }
}

TEST(CameraPathFile, OnlyJsonArgumentsAreTakenForFiles) {
    EXPECT_TRUE(looks_like_camera_path_file("flight.json"));
    EXPECT_TRUE(looks_like_camera_path_file("/tmp/a/b.json"));
    EXPECT_FALSE(looks_like_camera_path_file("orbit"));
    EXPECT_FALSE(looks_like_camera_path_file(".json"));
}

}  // namespace
}  // namespace fgr
