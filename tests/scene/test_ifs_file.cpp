// SPDX-License-Identifier: Apache-2.0
// IFS scene files (scene/ifs/ifs.hpp): the shipped files (plugins/ifs/) parse and their geometry is
// what it claims (bounding spheres that hold, attractors that match the DE scenes they copy), bad
// files are refused with one line naming the file and the map, a seeded fuzz test of the reader,
// and discovery of IFS files beside plugins.
//
// Reproduce a fuzz failure with FGR_FUZZ_SEED=<case seed> FGR_FUZZ_CASES=1 (the seed is printed
// with it); FGR_FUZZ_CASES=<n> runs more or fewer cases.

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "fuzz_rng.hpp"
#include "json_mutation.hpp"
#include "scene/discovery.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/scene_file.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kIfsDir = FGR_TEST_IFS_DIR;
using test::kPluginDir;
using test::write_text;

std::vector<fs::path> shipped_ifs_files() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kIfsDir)) {
        if (is_ifs_file_name(entry.path())) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string read_text(const fs::path& file) { return test::read_file(file); }

glm::dvec3 apply(const IfsMap& map, const glm::dvec3& x) { return map.linear * x + map.offset; }

// Points of the attractor by the chaos game (maps chosen uniformly; the first 100 dropped).
std::vector<glm::dvec3> chaos_game(const IfsScene& ifs, int count, uint64_t seed) {
    std::mt19937_64 engine(seed);
    glm::dvec3 x = ifs.bounds.centre;
    std::vector<glm::dvec3> points;
    for (int i = 0; i < count + 100; ++i) {
        x = apply(ifs.maps[engine() % ifs.maps.size()], x);
        if (i >= 100) points.push_back(x);
    }
    return points;
}

// A rotation by Rodrigues' formula, written out here rather than taken from glm::rotate (which the
// reader uses), so the two are checked against each other.
glm::dmat3 rodrigues(glm::dvec3 axis, double degrees) {
    axis = glm::normalize(axis);
    const double a = degrees * 3.14159265358979323846 / 180.0;
    const glm::dmat3 k(glm::dvec3(0, axis.z, -axis.y), glm::dvec3(-axis.z, 0, axis.x),
                       glm::dvec3(axis.y, -axis.x, 0));  // columns: K x = axis x x
    return glm::dmat3(1.0) + std::sin(a) * k + (1.0 - std::cos(a)) * (k * k);
}

// A minimal valid file, with `maps` as given.
json minimal(json maps) {
    return {{"format", "fgr-ifs"},
            {"version", 1},
            {"id", "test-ifs"},
            {"name", "Test"},
            {"maps", std::move(maps)}};
}

json sierpinski_maps() {
    json maps = json::array();
    for (const auto& v : {glm::dvec3(1, 1, 1), glm::dvec3(-1, -1, 1), glm::dvec3(1, -1, -1),
                          glm::dvec3(-1, 1, -1)}) {
        maps.push_back({{"scale", 0.5}, {"translate", {v.x / 2, v.y / 2, v.z / 2}}});
    }
    return maps;
}

// --- Shipped files -------------------------------------------------------------------------------

TEST(IfsFile, EveryShippedFileParsesWithUniqueIds) {
    const std::vector<fs::path> files = shipped_ifs_files();
    ASSERT_GE(files.size(), 6u) << kIfsDir;
    std::set<std::string> ids;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        IfsScene ifs;
        ASSERT_NO_THROW(ifs = read_ifs_file(file));
        EXPECT_TRUE(ids.insert(ifs.id).second) << "duplicate id " << ifs.id;
        EXPECT_FALSE(ifs.cameras.empty());
        EXPECT_FALSE(ifs.lights.empty());
        EXPECT_LE(ifs.default_depth, ifs.max_depth);
        for (const IfsMap& map : ifs.maps) {
            EXPECT_LT(map.contraction, 1.0);
            EXPECT_GT(singular_values(map.linear)[2], 1e-3) << "every shipped map is full rank";
        }
    }
    for (const char* id : {"sierpinski-ifs", "menger-ifs", "jerusalem-cube", "tree",
                           "koch-snowflake", "spiral-shell"}) {
        EXPECT_TRUE(ids.count(id)) << id;
    }
}

TEST(IfsFile, ShippedBoundingSpheresHoldTheirImagesAndTheAttractor) {
    for (const fs::path& file : shipped_ifs_files()) {
        SCOPED_TRACE(file.string());
        const IfsScene ifs = read_ifs_file(file);
        const IfsBounds& b = ifs.bounds;
        ASSERT_TRUE(std::isfinite(b.radius) && b.radius > 0.0);
        for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
            const IfsMap& map = ifs.maps[i];
            EXPECT_LE(glm::length(apply(map, b.centre) - b.centre) + map.contraction * b.radius,
                      b.radius * (1.0 + 1e-9))
                << "map " << i;
        }
        for (const glm::dvec3& p : chaos_game(ifs, 10000, 7)) {
            ASSERT_LE(glm::length(p - b.centre), b.radius * (1.0 + 1e-9));
        }
    }
}

// The sphere is small, not just valid: for these two the best ball about any centre is the
// circumscribed one, radius sqrt(3) about the origin.
TEST(IfsFile, BoundingSphereOfSymmetricFilesIsTheCircumsphere) {
    for (const char* name : {"sierpinski.ifs.json", "menger.ifs.json"}) {
        const IfsScene ifs = read_ifs_file(kIfsDir / name);
        EXPECT_NEAR(ifs.bounds.radius, std::sqrt(3.0), 1e-6) << name;
        EXPECT_LT(glm::length(ifs.bounds.centre), 1e-6) << name;
    }
    // From a poor start: maps x/2 (twice) and x/2 + (10, 0, 0) have the segment [0, 20] as
    // attractor, but the centroid of their fixed points is (20/3, 0, 0), where R is 40/3. The
    // search finds radius 10 about (10, 0, 0).
    std::vector<IfsMap> maps(3);
    for (IfsMap& map : maps) map.linear = glm::dmat3(0.5);
    maps[2].offset = {10, 0, 0};
    const IfsBounds bounds = ifs_bounding_sphere(maps);
    EXPECT_NEAR(bounds.radius, 10.0, 1e-6);
    EXPECT_NEAR(bounds.centre.x, 10.0, 1e-6);
}

// sierpinski.cl's DE in double: tetrahedron_frame, fold_sierpinski and sd_tetrahedron.
double sierpinski_de(glm::dvec3 p, int iterations) {
    const double s2 = std::sqrt(0.5), s6 = 1.0 / std::sqrt(6.0), s3 = 1.0 / std::sqrt(3.0);
    glm::dvec3 w(s2 * p.x + s6 * p.y + s3 * p.z, -s2 * p.x + s6 * p.y + s3 * p.z,
                 -2.0 * s6 * p.y + s3 * p.z);
    double size = 1.0;
    for (int i = 0; i < iterations; ++i) {
        if (w.x + w.y < 0) w = {-w.y, -w.x, w.z};
        if (w.x + w.z < 0) w = {-w.z, w.y, -w.x};
        if (w.y + w.z < 0) w = {w.x, -w.z, -w.y};
        size /= 2.0;
        w -= glm::dvec3(size);  // offset (1, 1, 1) * (scale - 1) * size
    }
    const double planes = std::max(std::abs(w.x + w.y) - w.z, std::abs(w.x - w.y) + w.z);
    return std::max((planes - size) * s3, glm::length(w) - std::sqrt(3.0) * size);
}

// menger.cl's DE in double: fold_menger, the middle-layer min and sd_box.
double menger_de(glm::dvec3 p, int iterations) {
    glm::dvec3 w = p;
    double size = 1.0;
    for (int i = 0; i < iterations; ++i) {
        w = glm::abs(w);
        if (w.x < w.y) std::swap(w.x, w.y);
        if (w.x < w.z) std::swap(w.x, w.z);
        if (w.y < w.z) std::swap(w.y, w.z);
        size /= 3.0;
        const double shift = 2.0 * size;
        w -= glm::dvec3(shift);
        w.z = std::min(std::abs(w.z), std::abs(w.z + shift));
    }
    const glm::dvec3 q = glm::abs(w) - glm::dvec3(size);
    return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

// The IFS and the DE scene draw the same set: every attractor point is inside (or on) the DE's
// level-n solid, and the maps' fixed points are the solid's outer corners.
TEST(IfsFile, SierpinskiAndMengerMatchTheirDistanceEstimatedScenes) {
    const IfsScene sierpinski = read_ifs_file(kIfsDir / "sierpinski.ifs.json");
    for (const glm::dvec3& p : chaos_game(sierpinski, 10000, 11)) {
        ASSERT_LE(sierpinski_de(p, 8), 1e-6) << p.x << " " << p.y << " " << p.z;
    }
    // The apex (0, 0, sqrt(3)) and the base at z = -1/sqrt(3) (sierpinski.c's comment).
    double top = -1e9, bottom = 1e9;
    for (const IfsMap& map : sierpinski.maps) {
        const glm::dvec3 fixed = glm::inverse(glm::dmat3(1.0) - map.linear) * map.offset;
        top = std::max(top, fixed.z);
        bottom = std::min(bottom, fixed.z);
        EXPECT_NEAR(glm::length(fixed), std::sqrt(3.0), 1e-9);
    }
    EXPECT_NEAR(top, std::sqrt(3.0), 1e-9);
    EXPECT_NEAR(bottom, -1.0 / std::sqrt(3.0), 1e-9);

    const IfsScene menger = read_ifs_file(kIfsDir / "menger.ifs.json");
    ASSERT_EQ(menger.maps.size(), 20u);
    for (const glm::dvec3& p : chaos_game(menger, 10000, 13)) {
        ASSERT_LE(menger_de(p, 5), 1e-9) << p.x << " " << p.y << " " << p.z;
    }
    glm::dvec3 low(1e9), high(-1e9);
    for (const IfsMap& map : menger.maps) {
        const glm::dvec3 fixed = glm::inverse(glm::dmat3(1.0) - map.linear) * map.offset;
        low = glm::min(low, fixed);
        high = glm::max(high, fixed);
    }
    EXPECT_LT(glm::length(low + glm::dvec3(1.0)), 1e-9);  // the cube [-1, 1]^3
    EXPECT_LT(glm::length(high - glm::dvec3(1.0)), 1e-9);
    // A point of a removed tunnel is not in the attractor's sponge.
    EXPECT_GT(menger_de({0.0, 0.0, 0.9}, 5), 0.1);
}

TEST(IfsFile, SierpinskiAndMengerShareTheirDeScenesCameras) {
    const IfsScene sierpinski = read_ifs_file(kIfsDir / "sierpinski.ifs.json");
    EXPECT_EQ(sierpinski.cameras.front().name, "front");
    EXPECT_EQ(sierpinski.cameras.front().view.position, glm::dvec3(3.636, 4.038, 1.805));
    EXPECT_EQ(sierpinski.cameras.front().view.fov_degrees, 50.0f);
    const IfsScene menger = read_ifs_file(kIfsDir / "menger.ifs.json");
    EXPECT_EQ(menger.cameras.front().name, "corner");
    EXPECT_EQ(menger.cameras.front().view.position, glm::dvec3(4.191, 2.934, 2.278));
}

// --- Maps and matrices ---------------------------------------------------------------------------

TEST(IfsFile, ComposedScaleRotateTranslateEqualsTheMatrix) {
    const glm::dvec3 scale(0.3, 0.4, 0.5);
    const glm::dvec3 axis(1.0, 2.0, 3.0);
    const double degrees = 40.0;
    const glm::dvec3 translate(0.1, -0.2, 0.3);
    const glm::dmat3 expected =
        rodrigues(axis, degrees) *
        glm::dmat3(glm::dvec3(scale.x, 0, 0), glm::dvec3(0, scale.y, 0), glm::dvec3(0, 0, scale.z));
    json matrix = json::array();
    for (int r = 0; r < 3; ++r) {
        matrix.push_back({expected[0][r], expected[1][r], expected[2][r], translate[r]});
    }
    const json composed = minimal(
        json::array({{{"scale", {scale.x, scale.y, scale.z}},
                      {"rotate", {{"axis", {axis.x, axis.y, axis.z}}, {"degrees", degrees}}},
                      {"translate", {translate.x, translate.y, translate.z}}},
                     {{"matrix", matrix}},
                     // Another fixed point: two equal maps alone would make a single point.
                     {{"scale", 0.5}, {"translate", {1, 0, 0}}}}));
    const IfsScene ifs = parse_ifs_json(composed.dump(), "composed.ifs.json");
    ASSERT_EQ(ifs.maps.size(), 3u);
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            EXPECT_NEAR(ifs.maps[0].linear[c][r], expected[c][r], 1e-12) << c << "," << r;
            EXPECT_NEAR(ifs.maps[1].linear[c][r], expected[c][r], 1e-12) << c << "," << r;
        }
        EXPECT_NEAR(ifs.maps[0].offset[c], translate[c], 1e-15);
        EXPECT_NEAR(ifs.maps[1].offset[c], translate[c], 1e-15);
    }
    // Each key alone, and a scalar scale.
    const IfsScene parts = parse_ifs_json(
        minimal(json::array({{{"scale", 0.5}}, {{"scale", 0.5}, {"translate", {1, 0, 0}}}})).dump(),
        "parts.ifs.json");
    EXPECT_EQ(parts.maps[0].linear, glm::dmat3(0.5));
    EXPECT_EQ(parts.maps[1].offset, glm::dvec3(1, 0, 0));
    EXPECT_EQ(parts.maps[0].colour, IfsMap{}.colour);
}

TEST(IfsFile, SingularValuesOfKnownMatrices) {
    const glm::dmat3 rotation = rodrigues({0.3, -1.0, 0.7}, 73.0);
    const glm::dmat3 diagonal(glm::dvec3(0.3, 0, 0), glm::dvec3(0, 0.5, 0), glm::dvec3(0, 0, 0.2));
    EXPECT_NEAR(largest_singular_value(rotation * diagonal), 0.5, 1e-14);
    EXPECT_NEAR(largest_singular_value(diagonal * rotation), 0.5, 1e-14);
    const glm::dvec3 all = singular_values(rodrigues({1, 1, 0}, 20.0) * diagonal * rotation);
    EXPECT_NEAR(all[0], 0.5, 1e-14);
    EXPECT_NEAR(all[1], 0.3, 1e-14);
    EXPECT_NEAR(all[2], 0.2, 1e-14);
    // A shear: [[1, 1], [0, 1]] has the golden ratio and its inverse.
    const glm::dmat3 shear(glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 0, 0.5));
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    const glm::dvec3 sheared = singular_values(shear);
    EXPECT_NEAR(sheared[0], phi, 1e-14);
    EXPECT_NEAR(sheared[1], 1.0 / phi, 1e-14);
    EXPECT_NEAR(sheared[2], 0.5, 1e-14);
    EXPECT_EQ(largest_singular_value(glm::dmat3(0.0)), 0.0);
    EXPECT_NEAR(largest_singular_value(glm::dmat3(-0.7)), 0.7, 1e-15);
    // Rank 2, and nearly so: the small value keeps its relative accuracy.
    EXPECT_EQ(singular_values(
                  glm::dmat3(glm::dvec3(1, 2, 3), glm::dvec3(2, 4, 6), glm::dvec3(0, 1, 0)))[2],
              0.0);
    const glm::dmat3 thin = rotation * glm::dmat3(glm::dvec3(0.5, 0, 0), glm::dvec3(0, 0.4, 0),
                                                  glm::dvec3(0, 0, 1e-12));
    EXPECT_NEAR(singular_values(thin)[2], 1e-12, 1e-16);
}

// --- Refusals ------------------------------------------------------------------------------------

// The reason parse_ifs_json gives for `document` (as JSON text), "" if it parses.
std::string refusal(const std::string& text, const std::string& origin = "bad.ifs.json") {
    try {
        (void)parse_ifs_json(text, origin);
        return "";
    } catch (const IfsError& error) {
        return error.what();
    }
}

struct BadCase {
    std::string what;
    std::string text;
    std::string expected;  // part of the message after "bad.ifs.json: "
};

std::vector<BadCase> bad_cases() {
    std::vector<BadCase> cases;
    const auto add = [&](std::string what, const json& document, std::string expected) {
        cases.push_back({std::move(what), document.dump(), std::move(expected)});
    };
    json maps = sierpinski_maps();
    json doc = minimal(maps);

    json grow = maps;
    grow[3] = {{"scale", 1.02}};
    add("non-contractive", minimal(grow),
        "map 3 is not contractive (largest singular value 1.02 >= 1)");
    json flat = maps;
    flat[2] = {{"scale", {0.5, 0.5, 0.0}}};
    add("singular", minimal(flat), "map 2 is singular");
    json nearly_flat = maps;
    nearly_flat[1] = {{"scale", {0.5, 0.5, 1e-12}}};
    add("nearly singular", minimal(nearly_flat), "map 1 is singular");
    json rank_two = maps;
    rank_two[0] = {{"matrix", {{0.2, 0.4, 0.0, 0.0}, {0.1, 0.2, 0.0, 0.0}, {0.0, 0.0, 0.3, 0.0}}}};
    add("rank two matrix", minimal(rank_two), "map 0 is singular");
    json huge = maps;
    huge[1]["translate"] = {0.0, 1e300, 0.0};
    add("huge translation", minimal(huge), "map 1 \"translate\" must be finite");
    add("zero maps", minimal(json::array()), "\"maps\" has 0 entries; 1 to 64 allowed");
    json lit = minimal(maps);
    lit["environment"] = "uniform:1,1";
    add("environment of two radiances", lit, "\"environment\": environment uniform:RADIANCE");
    json too_many = json::array();
    for (int i = 0; i < 65; ++i) too_many.push_back({{"scale", 0.5}});
    add("65 maps", minimal(too_many), "\"maps\" has 65 entries");
    json no_maps = doc;
    no_maps.erase("maps");
    add("no maps", no_maps, "\"maps\" is missing");
    json mixed = maps;
    mixed[0]["matrix"] = {{0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 0.5, 0}};
    add("matrix and translate", minimal(mixed), "map 0: \"matrix\" cannot be combined");
    json short_row = maps;
    short_row[0] = {{"matrix", {{0.5, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 0.5, 0}}}};
    add("matrix row of 3", minimal(short_row), "map 0 \"matrix\" must be 3 rows of 4 numbers");
    json zero_axis = maps;
    zero_axis[2]["rotate"] = {{"axis", {0, 0, 0}}, {"degrees", 30}};
    add("zero rotation axis", minimal(zero_axis), "map 2 \"rotate\" \"axis\" must not be zero");
    json bright = maps;
    bright[1]["colour"] = {0.5, 1.5, 0.5};
    add("colour above 1", minimal(bright), "map 1 \"colour\" components must be in [0, 1]");
    json map_typo = maps;
    map_typo[3]["translat"] = {0, 0, 0};
    add("unknown map key", minimal(map_typo), "map 3: unknown key \"translat\"");
    json schema_number = doc;
    schema_number["$schema"] = 3;
    add("\"$schema\" a number", schema_number, "\"$schema\" 3 must be a string");
    json map_schema = maps;
    map_schema[0]["$schema"] = "ifs.schema.json";
    add("\"$schema\" in a map", minimal(map_schema), "map 0: unknown key \"$schema\"");

    json deep = doc;
    deep["depth"] = {{"default", 1000}, {"max", 1000}};
    add("depth 1000", deep, "\"depth\" \"default\" 1000 must be an integer in [0, 24]");
    json fractional = doc;
    fractional["depth"] = {{"default", 2.5}};
    add("fractional depth", fractional, "must be an integer");
    json inverted = doc;
    inverted["depth"] = {{"default", 9}, {"max", 4}};
    add("default above max", inverted, "\"depth\" \"default\" 9 is above \"max\" 4");
    json negative = doc;
    negative["depth"] = {{"max", -1}};
    add("negative depth", negative, "\"depth\" \"max\" -1 must be an integer");

    json version = doc;
    version["version"] = 2;
    add("version 2", version, "unsupported \"version\" 2 (this fgr reads version 1)");
    version["version"] = 4294967297ull;
    add("version 2^32 + 1", version, "unsupported \"version\" 4294967297");
    version["version"] = "1";
    add("version as text", version, "unsupported \"version\" \"1\"");
    version["version"] = 1.0;
    add("version 1.0", version, "unsupported \"version\" 1.0");
    version.erase("version");
    add("no version", version, "\"version\" is missing");
    json format = doc;
    format["format"] = "fgr-camera-path";
    add("wrong format", format, "\"format\" \"fgr-camera-path\" must be \"fgr-ifs\"");
    format.erase("format");
    add("no format", format, "\"format\" is missing");
    json id = doc;
    id["id"] = "Bad Id";
    add("id with space", id, "\"id\" 'Bad Id' must match [a-z][a-z0-9_-]* (at most 63 characters)");
    id["id"] = "x\ny";
    add("id with newline", id, "\"id\" contains a control character");
    id.erase("id");
    add("no id", id, "\"id\" is missing");
    json name = doc;
    name.erase("name");
    add("no name", name, "\"name\" is missing");
    json typo = doc;
    typo["camera"] = json::array();
    add("unknown top-level key", typo, "top level: unknown key \"camera\"");

    json camera = doc;
    camera["cameras"] = {{{"name", "front"}, {"position", {0, 0, 0}}, {"target", {0, 0, 0}}}};
    add("camera at its target", camera, "camera 'front':");
    camera["cameras"] = {{{"name", "Front"}, {"position", {0, 0, 5}}, {"target", {0, 0, 0}}}};
    add("camera name", camera,
        "camera 0: name 'Front' must match [a-z0-9_-]+ (at most 63 characters)");
    camera["cameras"] = {
        {{"name", "a"}, {"position", {0, 5, 0}}, {"target", {0, 0, 0}}, {"fov", 200}}};
    add("camera fov", camera, "camera 'a':");
    json path = doc;
    path["camera_paths"] = {{{"name", "p"},
                             {"keyframes",
                              {{{"time", 1}, {"position", {0, 5, 0}}, {"target", {0, 0, 0}}},
                               {{"time", 1}, {"position", {0, 6, 0}}, {"target", {0, 0, 0}}}}}}};
    add("keyframe times not increasing", path, "camera path 'p' keyframe 1: time 1 not after 1");
    path["camera_paths"] = {
        {{"name", "p"},
         {"keyframes", {{{"time", 1}, {"position", {0, 5, 0}}, {"target", {0, 0, 0}}}}}}};
    add("one keyframe", path, "camera path 'p' \"keyframes\" has 1 entries; 2 to 10000 allowed");
    json light = doc;
    light["lights"] = {{{"type", "directional"}, {"direction", {0, 0, 0}}}};
    add("zero light direction", light, "light 0: zero direction");
    light["lights"] = {{{"type", "spot"}, {"position", {0, 0, 0}}}};
    add("unknown light type", light,
        "light 0 \"type\" \"spot\" must be \"directional\" or \"point\"");
    light["lights"] = {{{"type", "point"}, {"position", {0, 0, 2}}, {"intensity", -1}}};
    add("negative intensity", light, "light 0: negative intensity -1");

    add("a single map", minimal(json::array({{{"scale", 0.5}, {"translate", {1, 0, 0}}}})),
        "the attractor is a single point (2 0 0)");
    add("maps with one fixed point", minimal(json::array({{{"scale", 0.5}}, {{"scale", 0.3}}})),
        "the attractor is a single point");

    // Leaf shapes: inside the bounding sphere (radius sqrt(3) about the origin here), solid.
    json leaf = doc;
    leaf["leaf"] = {{"shape", "box"}, {"min", {-1, -1, -1}}, {"max", {1, 1, 1.5}}};
    add("leaf box outside the sphere", leaf, "\"leaf\" box corner (-1 -1 1.5) lies outside");
    leaf["leaf"] = {{"shape", "box"}, {"min", {-1, 1, -1}}, {"max", {1, 1, 1}}};
    add("leaf box with no depth", leaf, "\"leaf\" box: \"min\" must be below \"max\"");
    leaf["leaf"] = {{"shape", "tetrahedron"},
                    {"vertices", {{1, 1, 1}, {-1, -1, 1}, {1, -1, -1}, {0, 0, 1}}}};
    add("flat leaf tetrahedron", leaf, "\"leaf\" tetrahedron is flat");
    leaf["leaf"] = {{"shape", "tetrahedron"}, {"vertices", {{1, 1, 1}, {-1, -1, 1}, {1, -1, -1}}}};
    add("three leaf vertices", leaf, "\"vertices\" has 3 entries; 4 to 4 allowed");
    leaf["leaf"] = {{"shape", "cone"}};
    add("unknown leaf shape", leaf, "\"leaf\" \"shape\" 'cone' must be");
    leaf["leaf"] = {{"shape", "ball"}, {"radius", 2}};
    add("unknown leaf key", leaf, "radius");

    cases.push_back({"broken JSON", R"({"format": "fgr-ifs", "version": 1,,})",
                     "not valid JSON: parse error at line 1, column"});
    cases.push_back({"truncated JSON", doc.dump().substr(0, 40), "not valid JSON"});
    cases.push_back({"not an object", "[1, 2, 3]", "must be a JSON object"});
    // 10^5 maps of 15 bytes each: under the size limit, over the map limit.
    std::string many =
        R"({"format": "fgr-ifs", "version": 1, "id": "many", "name": "Many", "maps": [)";
    for (int i = 0; i < 100000; ++i) many += i == 0 ? R"({"scale": 0.5})" : R"(,{"scale": 0.5})";
    cases.push_back({"10^5 maps", many + "]}", "\"maps\" has 100000 entries; 1 to 64 allowed"});
    cases.push_back({"over 4 MiB", doc.dump() + std::string(kIfsMaxFileBytes, ' '),
                     "more than the 4194304 an IFS file may have"});
    return cases;
}

TEST(IfsFile, BadFilesAreRefusedInOneLineNamingTheFileAndTheMap) {
    for (const BadCase& bad : bad_cases()) {
        SCOPED_TRACE(bad.what);
        const std::string message = refusal(bad.text);
        ASSERT_FALSE(message.empty()) << "accepted";
        EXPECT_EQ(message.rfind("bad.ifs.json: ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_NE(message.find(bad.expected), std::string::npos)
            << "message: " << message << "\nexpected it to contain: " << bad.expected;
    }
}

// A light's "type" nested 100000 deep (which once crashed the reader printing it), a key given
// twice, bytes after a NUL or after the document: refused in one short line naming the file.
TEST(IfsFile, HostileDocumentsAreRefusedInOneShortLine) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    json doc = minimal(sierpinski_maps());
    doc["lights"] = {{{"type", "DEEP"}, {"position", {0, 0, 2}}}};
    std::string light = doc.dump();
    light.replace(light.find("\"DEEP\""), 6, deep);
    std::string twice = minimal(sierpinski_maps()).dump();
    twice.insert(1, R"("name": "Other", )");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {light, "nest deeper than 64 levels"},
        {twice, "the key \"name\" appears twice"},
        {minimal(sierpinski_maps()).dump() + std::string(1, '\0') + "junk", "a NUL byte at offset"},
        {minimal(sierpinski_maps()).dump() + " {}", "not valid JSON"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string message = refusal(text);
        ASSERT_FALSE(message.empty()) << "accepted: " << text.substr(0, 80);
        EXPECT_EQ(message.rfind("bad.ifs.json: ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_LT(message.size(), 400u) << message.substr(0, 400);
        EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
}

// "$schema" names the file's JSON Schema for editors (schemas/ifs.schema.json): taken at the top
// level, and not read.
TEST(IfsFile, ASchemaReferenceIsAcceptedAtTheTopLevel) {
    json doc = minimal(sierpinski_maps());
    doc["$schema"] = "file:///usr/share/fgr/schemas/ifs.schema.json";
    EXPECT_EQ(refusal(doc.dump()), "");
}

TEST(IfsFile, ReadingNamesTheFile) {
    const test::TempDir dir("fgr_ifs_test");
    const fs::path missing = dir.path() / "missing.ifs.json";
    try {
        (void)read_ifs_file(missing);
        FAIL() << "read a missing file";
    } catch (const IfsError& error) {
        EXPECT_EQ(std::string(error.what()).rfind(missing.string() + ": ", 0), 0u) << error.what();
    }
    // One byte over the limit is refused for its size; a file of exactly the limit is read (and
    // refused only for not being JSON).
    const fs::path big = dir.path() / "big.ifs.json";
    write_text(big, std::string(kIfsMaxFileBytes + 1, ' '));
    try {
        (void)read_ifs_file(big);
        FAIL() << "read an oversized file";
    } catch (const IfsError& error) {
        EXPECT_NE(std::string(error.what()).find("file too large"), std::string::npos)
            << error.what();
    }
    const fs::path limit = dir.path() / "limit.ifs.json";
    write_text(limit, std::string(kIfsMaxFileBytes, ' '));
    try {
        (void)read_ifs_file(limit);
        FAIL() << "parsed a file of spaces";
    } catch (const IfsError& error) {
        EXPECT_EQ(std::string(error.what()).find("file too large"), std::string::npos)
            << error.what();
    }
}

TEST(IfsFile, DefaultsFrameTheBoundingSphere) {
    const IfsScene ifs = parse_ifs_json(minimal(sierpinski_maps()).dump(), "defaults.ifs.json");
    ASSERT_EQ(ifs.cameras.size(), 1u);
    const CameraView& view = ifs.cameras[0].view;
    EXPECT_EQ(view.target, ifs.bounds.centre);
    const double distance = glm::length(view.position - view.target);
    // The sphere's angular radius is a bit under the 30 degree half fov.
    const double half_angle = std::asin(ifs.bounds.radius / distance) * 180.0 / 3.14159265358979;
    EXPECT_GT(half_angle, 20.0);
    EXPECT_LT(half_angle, 30.0);
    EXPECT_EQ(view.fov_degrees, 60.0f);
    ASSERT_EQ(ifs.lights.size(), 1u);
    EXPECT_EQ(ifs.lights[0].type, LightType::Directional);
    EXPECT_EQ(ifs.description, "");
    // No depth given: the footprint rule decides, up to the cap (the tetrahedron's estimate at
    // its default view is far within the default's budget).
    EXPECT_EQ(ifs.default_depth, kIfsMaxDepth);
    EXPECT_EQ(ifs.max_depth, kIfsMaxDepth);
}

// A file may name the path mode's environment, which its scene keeps; without one it has none.
TEST(IfsFile, NamesItsOwnEnvironment) {
    json document = minimal(sierpinski_maps());
    EXPECT_EQ(
        ifs_scene_to_scene(parse_ifs_json(document.dump(), "a.ifs.json"), "a.ifs.json").environment,
        "");
    document["environment"] = "studio";
    EXPECT_EQ(
        ifs_scene_to_scene(parse_ifs_json(document.dump(), "a.ifs.json"), "a.ifs.json").environment,
        "studio");
}

TEST(IfsFile, SceneHasTheDepthSliderAndTheMaps) {
    const fs::path file = kIfsDir / "menger.ifs.json";
    const IfsScene ifs = read_ifs_file(file);
    const Scene scene = ifs_scene_to_scene(ifs, file);
    EXPECT_EQ(scene.id, "menger-ifs");
    EXPECT_EQ(scene.plugin_file, file);
    ASSERT_NE(scene.ifs, nullptr);
    EXPECT_EQ(scene.ifs->maps.size(), 20u);
    ASSERT_FALSE(scene.params.empty());
    const ParamInfo& depth = scene.params.front();
    EXPECT_EQ(depth.id, "ifs_depth");
    EXPECT_EQ(depth.type, ParamType::Int);
    EXPECT_EQ(depth.group, "IFS");
    EXPECT_EQ(depth.min_value, 0.0f);
    EXPECT_EQ(depth.max_value, static_cast<float>(ifs.max_depth));
    EXPECT_EQ(depth.default_value[0], static_cast<float>(ifs.default_depth));
    EXPECT_EQ(scene.params.size(), 1 + builtin_param_count());
    EXPECT_FALSE(scene.source.empty());
    // Rays reach past the sphere from the farthest view (the orbit, 5.6 from the centre).
    EXPECT_GE(scene.march.max_distance, 5.6f + 2.0f * static_cast<float>(ifs.bounds.radius));
    EXPECT_EQ(scene.cameras.size(), ifs.cameras.size());
    EXPECT_EQ(scene.camera_paths.size(), 2u);
}

// --- Discovery -----------------------------------------------------------------------------------

TEST(IfsDiscovery, FindsGoodFilesAndSkipsBadOnesWithTheirReason) {
    const test::TempDir dir("fgr_ifs_discovery");
    write_text(dir.path() / "good.ifs.json", read_text(kIfsDir / "sierpinski.ifs.json"));
    json bad = minimal(sierpinski_maps());
    bad["maps"][2] = {{"scale", 1.5}};
    write_text(dir.path() / "bad.ifs.json", bad.dump());
    write_text(dir.path() / "notes.json", "not a scene");
    const test::TempDir second("fgr_ifs_discovery");
    write_text(second.path() / "again.ifs.json", read_text(kIfsDir / "sierpinski.ifs.json"));

    spdlog::set_level(spdlog::level::err);
    const Discovery found = discover_scenes({dir.path(), second.path()});
    spdlog::set_level(spdlog::level::info);
    ASSERT_EQ(found.scenes.size(), 1u);
    const Scene& scene = found.scenes[0];
    EXPECT_EQ(scene.id, "sierpinski-ifs");
    EXPECT_EQ(scene.plugin_file, dir.path() / "good.ifs.json");
    ASSERT_NE(scene.ifs, nullptr);
    EXPECT_EQ(scene.ifs->maps.size(), 4u);
    ASSERT_NE(scene.find_param("ifs_depth"), nullptr);

    ASSERT_EQ(found.skipped.size(), 2u);
    std::map<std::string, std::string> reasons;
    for (const SkippedPlugin& skipped : found.skipped) {
        reasons[skipped.file.filename().string()] = skipped.reason;
    }
    EXPECT_EQ(reasons["bad.ifs.json"],
              "map 2 is not contractive (largest singular value 1.5 >= 1)");
    EXPECT_NE(reasons["again.ifs.json"].find("duplicate scene id 'sierpinski-ifs'"),
              std::string::npos)
        << reasons["again.ifs.json"];
}

// One file nested 100000 deep in a plugin folder is one refused file: every other scene is still
// listed and found by id, through the scene index or not.
TEST(IfsDiscovery, ADeeplyNestedFileIsRefusedAndTheOthersStillLoad) {
    const test::TempDir dir("fgr_ifs_deep");
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    write_text(dir.path() / "a.ifs.json",
               R"({"format": "fgr-ifs", "version": )" + deep + R"(, "id": "a", "maps": []})");
    write_text(dir.path() / "good.ifs.json", read_text(kIfsDir / "sierpinski.ifs.json"));
    spdlog::set_level(spdlog::level::err);
    const Discovery all = discover_scenes({dir.path()});
    const Discovery one =
        discover_scene({dir.path()}, "sierpinski-ifs", dir.path() / "index" / "scenes.json");
    spdlog::set_level(spdlog::level::info);
    for (const Discovery* found : {&all, &one}) {
        ASSERT_EQ(found->scenes.size(), 1u);
        EXPECT_EQ(found->scenes[0].id, "sierpinski-ifs");
        ASSERT_EQ(found->skipped.size(), 1u);
        EXPECT_EQ(found->skipped[0].file.filename(), "a.ifs.json");
        EXPECT_NE(found->skipped[0].reason.find("nest deeper than 64 levels"), std::string::npos)
            << found->skipped[0].reason;
        EXPECT_LT(found->skipped[0].reason.size(), 200u);
    }
}

TEST(IfsDiscovery, ReloadReadsTheFileAgain) {
    const test::TempDir dir("fgr_ifs_reload");
    const fs::path file = dir.path() / "scene.ifs.json";
    json doc = minimal(sierpinski_maps());
    write_text(file, doc.dump());
    LoadResult first = reload_scene_file(file);
    ASSERT_TRUE(first.scene) << first.error;
    EXPECT_EQ(first.scene->name, "Test");
    doc["name"] = "Changed";
    write_text(file, doc.dump());
    LoadResult second = reload_scene_file(file);
    ASSERT_TRUE(second.scene) << second.error;
    EXPECT_EQ(second.scene->name, "Changed");
    write_text(file, "{");
    const LoadResult broken = reload_scene_file(file);
    EXPECT_FALSE(broken.scene);
    EXPECT_EQ(broken.error.rfind("not valid JSON", 0), 0u) << broken.error;
}

TEST(IfsDiscovery, TheBuildsPluginFolderHoldsTheShippedFiles) {
    for (const fs::path& file : shipped_ifs_files()) {
        EXPECT_TRUE(fs::exists(kPluginDir / file.filename())) << file.filename();
    }
}

// --- Fuzzing parse_ifs_json ----------------------------------------------------------------------
//
// Each case starts from a shipped file or a small valid document and applies a few mutations: to
// the text (bytes deleted, inserted, duplicated, the text cut short), to its structure (nesting far
// too deep, a key given twice, huge numbers, NUL bytes, bytes after the document) or to the parsed
// value (a number, string, array or object swapped for a nasty one, a key removed or misspelt, an
// array grown). The checks: nothing but IfsError escapes, a refusal is one short line naming the
// file, and an accepted scene keeps the invariants the renderer relies on.

constexpr uint64_t kIfsFuzzSeed = 0x49465346757a7a31;  // "IFSFuzz1"

using Rng = test::FuzzRng;

void check_case(const std::string& text, uint64_t case_seed, bool& accepted) {
    accepted = false;
    try {
        const IfsScene ifs = parse_ifs_json(text, "fuzz.ifs.json");
        accepted = true;
        ASSERT_FALSE(ifs.maps.empty()) << "case " << case_seed;
        ASSERT_LE(ifs.maps.size(), static_cast<std::size_t>(kIfsMaxMaps)) << "case " << case_seed;
        for (const IfsMap& map : ifs.maps) {
            ASSERT_LT(map.contraction, 1.0) << "case " << case_seed;
            ASSERT_GT(singular_values(map.linear)[2], 0.0) << "case " << case_seed;
        }
        ASSERT_TRUE(std::isfinite(ifs.bounds.radius)) << "case " << case_seed;
        for (const IfsMap& map : ifs.maps) {
            ASSERT_LE(glm::length(apply(map, ifs.bounds.centre) - ifs.bounds.centre) +
                          map.contraction * ifs.bounds.radius,
                      ifs.bounds.radius * (1.0 + 1e-9) + 1e-300)
                << "case " << case_seed;
        }
        ASSERT_FALSE(ifs.cameras.empty()) << "case " << case_seed;
        ASSERT_FALSE(ifs.lights.empty()) << "case " << case_seed;
        ASSERT_LE(0, ifs.default_depth);
        ASSERT_LE(ifs.default_depth, ifs.max_depth) << "case " << case_seed;
        ASSERT_LE(ifs.max_depth, kIfsMaxDepth) << "case " << case_seed;
        const Scene scene = ifs_scene_to_scene(ifs, "fuzz.ifs.json");
        ASSERT_EQ(scene.params.front().id, "ifs_depth") << "case " << case_seed;
    } catch (const IfsError& error) {
        const std::string message = error.what();
        ASSERT_EQ(message.rfind("fuzz.ifs.json: ", 0), 0u)
            << "case " << case_seed << ": " << message;
        ASSERT_EQ(message.find('\n'), std::string::npos) << "case " << case_seed << ": " << message;
        ASSERT_GT(message.size(), std::string("fuzz.ifs.json: ").size()) << "case " << case_seed;
        ASSERT_LT(message.size(), 500u) << "case " << case_seed << ": " << message;
    }
}

TEST(FuzzIfsFile, ParsesOrRefusesEveryMutatedFile) {
    std::vector<std::string> seeds;
    for (const fs::path& file : shipped_ifs_files()) seeds.push_back(read_text(file));
    seeds.push_back(minimal(sierpinski_maps()).dump());
    ASSERT_FALSE(seeds.empty());

    const uint64_t base = test::fuzz_base_seed(kIfsFuzzSeed);
    const uint64_t cases = test::fuzz_case_count();
    int accepted = 0;
    for (uint64_t i = 0; i < cases; ++i) {
        const uint64_t case_seed = base + i;
        Rng rng(case_seed);
        std::string text = seeds[rng.below(seeds.size())];
        test::mutate_document(text, rng, rng.range(1, 3));
        bool ok = false;
        check_case(text, case_seed, ok);
        if (::testing::Test::HasFatalFailure()) return;
        accepted += ok ? 1 : 0;
    }
    // Both outcomes are exercised, not just refusals.
    if (cases >= 1000) {
        EXPECT_GT(accepted, static_cast<int>(cases / 20));
        EXPECT_LT(accepted, static_cast<int>(cases * 19 / 20));
    }
}

}  // namespace
}  // namespace fgr
