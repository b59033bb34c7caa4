// SPDX-License-Identifier: Apache-2.0
// Scene authoring: the kernel API versions (a scene says which one its source is
// written for; a frozen version-1 scene keeps compiling; version-2 names stay out of version 1),
// the version-2 helpers that take what a vec3 parameter gives and the folds (checked by their
// geometry, through the kernel, at packet widths 1 and 16), and the orbit-scene contract
// (kernels/fractals/fgr_iterate.cl) against the same maths written out by hand in packet form.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "child_process.hpp"
#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "fgr/kernel_library.hpp"
#include "random_points.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"
#include "render_probes.hpp"
#include "scene/kernel_api.hpp"
#include "scene/parameters.hpp"
#include "scene/plugin_loader.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

constexpr std::array kWidths{1, 16};

using test::shared_device;

using test::read_file;

// An SDK example as this build made it (tests/fixtures/sdk_examples).
Scene sdk_example(const std::string& id) {
    const auto file = std::filesystem::path(FGR_TEST_FIXTURE_DIR) / "sdk_examples" / (id + ".so");
    LoadResult loaded = load_scene_plugin(file);
    if (!loaded.scene) throw std::runtime_error(file.string() + ": " + loaded.error);
    return std::move(*loaded.scene);
}

Frame render_small(const Scene& scene, int packet_width) {
    ProgramCache no_disk_cache{std::filesystem::path()};
    Renderer renderer(shared_device(), no_disk_cache, scene, {packet_width, scene.effects});
    return renderer.render(test::default_view_request(scene));
}

// --- Kernel API versions ----------------------------------------------------------------------

TEST(KernelApi, TheVersionIsReadFromTheSourcesOwnDefine) {
    EXPECT_EQ(declared_kernel_api("real scene_de(vec3 p, PARAMS) { return p.x; }"), 1);
    EXPECT_EQ(declared_kernel_api("#define FGR_KERNEL_API 2\nreal scene_de..."), 2);
    EXPECT_EQ(declared_kernel_api("  #  define   FGR_KERNEL_API 1  \n"), 1);
    EXPECT_EQ(declared_kernel_api("/* #define FGR_KERNEL_API 2 */\n// #define FGR_KERNEL_API 2\n"),
              1);
    for (const char* unknown : {"#define FGR_KERNEL_API 5\n", "#define FGR_KERNEL_API 0\n",
                                "#define FGR_KERNEL_API two\n"}) {
        try {
            declared_kernel_api(unknown);
            ADD_FAILURE() << "accepted: " << unknown;
        } catch (const std::invalid_argument& error) {
            EXPECT_NE(std::string(error.what()).find("kernel APIs 1 to 4"), std::string::npos)
                << error.what();
        }
    }
}

TEST(KernelApi, TheHostAndTheLibraryAgreeOnTheLatestVersion) {
    const auto prelude = kernel_prelude();
    const auto types = std::find_if(prelude.begin(), prelude.end(), [](const KernelFile& file) {
        return std::string_view(file.name) == "fgr_types.cl";
    });
    ASSERT_NE(types, prelude.end());
    std::smatch match;
    const std::string text(types->source);
    ASSERT_TRUE(
        std::regex_search(text, match, std::regex(R"(#define FGR_KERNEL_API_LATEST (\d+))")));
    EXPECT_EQ(std::stoi(match[1].str()), kKernelApiLatest);
}

TEST(KernelApi, APluginWrittenForANewerVersionIsRefusedAtLoadWithTheReason) {
    Scene scene = sdk_example("icosahedral-kifs");
    scene.source = "#define FGR_KERNEL_API 9\n" + scene.source;
    ProgramCache no_disk_cache{std::filesystem::path()};
    try {
        Renderer renderer(shared_device(), no_disk_cache, scene, {1, 0});
        ADD_FAILURE() << "built a scene written for kernel API 9";
    } catch (const std::exception& error) {
        EXPECT_NE(std::string(error.what()).find("update fgr"), std::string::npos) << error.what();
    }
}

// A copy of the SDK's octahedral KIFS as it was written for version 1 (a float3 rotation axis),
// frozen: it must keep building and render the example's image at both packet widths.
TEST(KernelApi, AFrozenVersionOneSceneKeepsCompilingAndRendersAsBefore) {
    const Scene example = sdk_example("octahedral-kifs");
    Scene frozen = example;
    frozen.source = read_file(std::filesystem::path(FGR_TEST_SOURCE_DIR) /
                              "fixtures/kernel_api_v1/octahedral_kifs_v1.cl");
    ASSERT_FALSE(frozen.source.empty());
    ASSERT_EQ(declared_kernel_api(frozen.source), 1);
    for (const int width : kWidths) {
        const Frame original = render_small(example, width);
        const Frame kept = render_small(frozen, width);
        ASSERT_GT(original.hits, 0);
        EXPECT_EQ(kept.hits, original.hits) << "width " << width;
        EXPECT_EQ(kept.image.rgb, original.image.rgb) << "width " << width;
    }
}

// Every public helper of version 1 called with its version-1 signature: renaming or retyping one
// breaks this build (and with it every plugin written for version 1).
TEST(KernelApi, EveryVersionOneHelperKeepsItsSignature) {
    Scene surface = test::sphere_scene();
    surface.source = read_file(std::filesystem::path(FGR_TEST_SOURCE_DIR) /
                               "fixtures/kernel_api_v1/library_surface_v1.cl");
    for (const int width : kWidths) {
        const std::vector<glm::vec3> points{{0.5f, 0.1f, -0.2f}};
        ProgramCache no_disk_cache{std::filesystem::path()};
        Renderer renderer(shared_device(), no_disk_cache, surface, {width, 0});
        const auto de = renderer.probe_de(points, default_param_values(surface));
        EXPECT_TRUE(std::isfinite(de.front())) << "width " << width;
    }
}

// The versions differ where they should: version 2's names are not in version 1, and version 2
// takes the rotation axis as a vec3 (what a parameter gives), not a float3.
TEST(KernelApi, EachVersionSeesOnlyItsOwnNamesAndSignatures) {
    const std::string uses_v2_fold =
        "real scene_de(vec3 p, PARAMS) { (void)fgr_params; return v3_length(fold_icosahedral(p)) - "
        "1.0f; }\n";
    const std::string uses_v1_rotation =
        "real scene_de(vec3 p, PARAMS) { (void)fgr_params;\n"
        "  return v3_length(op_rotate(p, rotation_about_axis((float3)(0.0f, 0.0f, 1.0f), 30.0f))) "
        "- 1.0f; }\n";
    const auto builds = [](const std::string& source) {
        ProgramCache no_disk_cache{std::filesystem::path()};
        try {
            Renderer renderer(shared_device(), no_disk_cache, test::inline_scene(source), {1, 0});
            return true;
        } catch (const KernelBuildError&) {
            return false;
        }
    };
    EXPECT_FALSE(builds(uses_v2_fold)) << "version 1 sees fold_icosahedral";
    EXPECT_TRUE(builds("#define FGR_KERNEL_API 2\n" + uses_v2_fold));
    EXPECT_TRUE(builds(uses_v1_rotation));
    EXPECT_FALSE(builds("#define FGR_KERNEL_API 2\n" + uses_v1_rotation))
        << "version 2 takes a float3 axis";
}

// From kernel API 4 parameters read as the uniform values they are: a vec3 parameter's component
// is a float in ordinary C (`const float h = param_offset.z;`), scalar parameters go into plain
// float expressions, and v3_uniform hands a float3 to the vec3 helpers, at one ray per work-item
// (the narrowest double packet, 4, in double) and at the device's packets, in float and double. The
// probe says the values arrive (a ball of radius size / 2 about offset); fog and glow read the
// built-in colours as the library does, and the orbit colours by base_colour.
TEST(KernelApi, VersionFourReadsParametersAsUniformValuesAtEveryWidthAndPrecision) {
    Scene scene = test::inline_scene(R"(
#define FGR_KERNEL_API 4
#define FGR_SCENE_HAS_COLOUR
FGR_ORBIT(1, FGR_NO_BAILOUT)
    const float h = param_offset.z;
    const float radius = 0.5f * param_size;
    const float3 centre = (float3)(param_offset.x, param_offset.y, h);
FGR_ITERATE
    z = v3_sub(z, v3_uniform(centre));
FGR_DISTANCE(v3_length(z) - radius)
)");
    const auto add = [&scene](const char* id, ParamType type, std::array<float, 3> value) {
        scene.params.insert(scene.params.begin(), ParamInfo{.id = id,
                                                            .type = type,
                                                            .min_value = -4.0f,
                                                            .max_value = 4.0f,
                                                            .default_value = value});
    };
    add("offset", ParamType::Vec3, {0.1f, -0.2f, 0.3f});
    add("size", ParamType::Float, {1.0f, 0, 0});
    add("colour_mode", ParamType::Int, {0, 0, 0});
    add("palette", ParamType::Int, {0, 0, 0});
    add("base_colour", ParamType::Colour, {0.8f, 0.6f, 0.4f});
    const std::vector<glm::vec3> points{{0.1f, -0.2f, 0.3f}, {1.1f, -0.2f, 0.3f}};
    const ComputeDevice& device = shared_device();
    for (const bool double_precision : {false, true}) {
        if (double_precision && !device.info.has_fp64) continue;
        for (const int width : {1, preferred_packet_width(device.info)}) {
            SCOPED_TRACE(fmt::format("width {}, {}", width, double_precision ? "double" : "float"));
            ProgramCache no_disk_cache{std::filesystem::path()};
            std::optional<Renderer> built;
            try {
                built.emplace(
                    device, no_disk_cache, scene,
                    with_precision({width, FGR_EFFECT_FOG | FGR_EFFECT_GLOW}, double_precision));
            } catch (const KernelBuildError& error) {
                ADD_FAILURE() << error.what() << "\n" << error.build_log();
                continue;
            }
            Renderer& renderer = *built;
            const auto de = renderer.probe_de(points, default_param_values(scene));
            EXPECT_NEAR(de[0], -0.5f, 1e-5f);
            EXPECT_NEAR(de[1], 0.5f, 1e-5f);
            FrameRequest request = test::default_view_request(scene);
            request.width = 32;
            request.height = 24;
            EXPECT_GT(renderer.render(request).hits, 0);
        }
    }
}

// Mixing a lane value and a uniform one up is told how to fix it: before version 4 a vec3
// parameter's component is a `real` (float16 in a 16-ray packet), which a float cannot hold; from
// version 4 the parameter is a float3, which a vec3 helper does not take.
TEST(KernelApi, AParameterReadAsTheWrongKindOfValueIsToldTheFix) {
    const auto build_error = [](const std::string& source) {
        Scene scene = test::inline_scene(source);
        scene.params.insert(scene.params.begin(),
                            ParamInfo{.id = "offset", .type = ParamType::Vec3});
        ProgramCache no_disk_cache{std::filesystem::path()};
        try {
            Renderer renderer(shared_device(), no_disk_cache, scene, {16, 0});
        } catch (const KernelBuildError& error) {
            return std::string(error.what());
        }
        return std::string("built");
    };
    const std::string component_as_float = build_error(
        "#define FGR_KERNEL_API 3\n"
        "real scene_de(vec3 p, PARAMS) { const float h = param_offset.z; return p.z - h; }\n");
    EXPECT_NE(component_as_float.find("from kernel API 4 (`#define FGR_KERNEL_API 4`"),
              std::string::npos)
        << component_as_float;
    const std::string float3_as_vec3 = build_error(
        "#define FGR_KERNEL_API 4\n"
        "real scene_de(vec3 p, PARAMS) { return v3_length(v3_sub(p, param_offset)) - 1.0f; }\n");
    EXPECT_NE(float3_as_vec3.find("pass v3_uniform(param_<id>)"), std::string::npos)
        << float3_as_vec3;
}

// --- Version-2 helpers, through the kernel --------------------------------------------------

// A scene whose "DE" is one component of a helper's result: which helper by `which`, which
// component (x, y, z, or the dr it reports) by `component`, so one build serves every case.
Scene helper_probe_scene() {
    Scene scene = test::inline_scene(R"(
#define FGR_KERNEL_API 2
real scene_de(vec3 p, PARAMS) {
    real dr = fgr_real(1.0f);
    vec3 q = p;
    switch (param_which) {
        case 0: q = fold_icosahedral(p); break;
        case 1: q = fold_box_axes(p, param_size); break;
        case 2: q = invert_sphere(p, &dr, param_centre, param_radius, param_min_radius); break;
        case 3: q = rotate_about(p, param_axis, param_angle); break;
        case 4: q = op_rotate(p, rotation_about_axis(param_axis, param_angle)); break;
        default: q = scale_about(p, param_radius, param_centre); break;
    }
    switch (param_component) {
        case 0: return q.x;
        case 1: return q.y;
        case 2: return q.z;
        default: return dr;
    }
}
)");
    const auto add = [&scene](const char* id, ParamType type, std::array<float, 3> value) {
        ParamInfo param;
        param.id = id;
        param.type = type;
        param.min_value = -360.0f;
        param.max_value = 360.0f;
        param.default_value = value;
        scene.params.insert(scene.params.begin(), param);
    };
    add("which", ParamType::Int, {0, 0, 0});
    add("component", ParamType::Int, {0, 0, 0});
    add("size", ParamType::Vec3, {1.0f, 0.5f, 2.0f});
    add("centre", ParamType::Vec3, {0.5f, 0.0f, 0.0f});
    add("radius", ParamType::Float, {1.5f, 0, 0});
    add("min_radius", ParamType::Float, {0.25f, 0, 0});
    add("axis", ParamType::Vec3, {0.0f, 0.0f, 2.0f});
    add("angle", ParamType::Float, {90.0f, 0, 0});
    return scene;
}

// What a helper gives at each point: xyz and the dr it reports.
struct HelperResult {
    std::vector<glm::vec3> points;
    std::vector<float> dr;
};

class HelperProbe {
public:
    explicit HelperProbe(int width)
        : scene_(helper_probe_scene()), renderer_(shared_device(), cache_, scene_, {width, 0}) {}

    HelperResult run(int which, const std::vector<glm::vec3>& points,
                     const std::vector<std::string>& settings = {}) {
        std::vector<float> params = default_param_values(scene_);
        set_param_from_text(scene_, params, "which=" + std::to_string(which));
        for (const auto& setting : settings) set_param_from_text(scene_, params, setting);
        std::array<std::vector<float>, 4> components;
        for (int c = 0; c < 4; ++c) {
            set_param_from_text(scene_, params, "component=" + std::to_string(c));
            components[size_t(c)] = renderer_.probe_de(points, params);
        }
        HelperResult result;
        for (size_t i = 0; i < points.size(); ++i) {
            result.points.emplace_back(components[0][i], components[1][i], components[2][i]);
            result.dr.push_back(components[3][i]);
        }
        return result;
    }

private:
    Scene scene_;
    ProgramCache cache_{std::filesystem::path()};
    Renderer renderer_;
};

using test::random_points;

// All sign combinations of the cyclic permutations of (a, b, c), duplicates removed.
std::vector<glm::vec3> cyclic_sign_permutations(float a, float b, float c) {
    std::vector<glm::vec3> out;
    for (const glm::vec3 base : {glm::vec3(a, b, c), glm::vec3(c, a, b), glm::vec3(b, c, a)}) {
        for (int signs = 0; signs < 8; ++signs) {
            const glm::vec3 p(signs & 1 ? -base.x : base.x, signs & 2 ? -base.y : base.y,
                              signs & 4 ? -base.z : base.z);
            if (std::none_of(out.begin(), out.end(), [&](glm::vec3 q) { return q == p; }))
                out.push_back(p);
        }
    }
    return out;
}

class Helpers : public ::testing::TestWithParam<int> {};

// The icosahedral fold maps every vertex of the icosahedron to one point, icosahedron_vertex(),
// and every vertex of the dodecahedron to dodecahedron_vertex(): it is the symmetry of both, with
// those corners. Any point lands in the region (x, y >= 0, on the mirror's positive side) at its
// own distance from the origin (an isometry).
TEST_P(Helpers, TheIcosahedralFoldFoldsBothPolyhedraOntoTheirCornerAndKeepsLengths) {
    HelperProbe probe(GetParam());
    const float phi = (1.0f + std::sqrt(5.0f)) / 2.0f;
    auto icosahedron = cyclic_sign_permutations(1.0f, 0.0f, phi);
    ASSERT_EQ(icosahedron.size(), 12u);
    auto dodecahedron = cyclic_sign_permutations(0.0f, 1.0f / phi, phi);
    for (const glm::vec3 cube : cyclic_sign_permutations(1.0f, 1.0f, 1.0f))
        dodecahedron.push_back(cube);
    ASSERT_EQ(dodecahedron.size(), 20u);
    for (auto& p : icosahedron) p = glm::normalize(p);
    for (auto& p : dodecahedron) p = glm::normalize(p);
    const glm::vec3 icosahedron_corner(0.52573111f, 0.0f, 0.85065081f);
    const glm::vec3 dodecahedron_corner(0.0f, 0.35682209f, 0.93417236f);
    // Five reflections of unit vectors in float: a few ulps each.
    constexpr float kTolerance = 2e-6f;
    for (const glm::vec3 q : probe.run(0, icosahedron).points) {
        EXPECT_LT(glm::length(q - icosahedron_corner), kTolerance)
            << q.x << " " << q.y << " " << q.z;
    }
    for (const glm::vec3 q : probe.run(0, dodecahedron).points) {
        EXPECT_LT(glm::length(q - dodecahedron_corner), kTolerance)
            << q.x << " " << q.y << " " << q.z;
    }
    const glm::vec3 mirror(-0.5f, -0.80901699f, 0.30901699f);
    const auto points = random_points(200, 3.0f, 7);
    const auto folded = probe.run(0, points).points;
    for (size_t i = 0; i < points.size(); ++i) {
        const glm::vec3 q = folded[i];
        EXPECT_NEAR(glm::length(q), glm::length(points[i]), 1e-5f * glm::length(points[i]));
        EXPECT_GE(q.x, 0.0f);
        EXPECT_GE(q.y, 0.0f);
        EXPECT_GE(glm::dot(q, mirror), -1e-5f * glm::length(q));
    }
}

TEST_P(Helpers, TheBoxFoldTakesALimitPerAxis) {
    HelperProbe probe(GetParam());
    // Limits (1, 0.5, 2): x = 1.5 reflects about 1 to 0.5, y = -0.7 about -0.5 to -0.3, z = 2.5
    // about 2 to 1.5; inside its limits a point stays.
    const auto q = probe.run(1, {{1.5f, -0.7f, 2.5f}, {0.9f, 0.4f, -1.9f}}).points;
    EXPECT_NEAR(q[0].x, 0.5f, 1e-6f);
    EXPECT_NEAR(q[0].y, -0.3f, 1e-6f);
    EXPECT_NEAR(q[0].z, 1.5f, 1e-6f);
    EXPECT_EQ(q[1], glm::vec3(0.9f, 0.4f, -1.9f));
}

TEST_P(Helpers, SphereInversionMapsOutsideInWithItsScaleAndStopsAtTheMinimumRadius) {
    HelperProbe probe(GetParam());
    // Centre (0.5, 0, 0), radius 1.5: a point 3 from the centre goes to 2.25 / 3 = 0.75 from it,
    // lengths there scaled by 2.25 / 9; 0.1 from the centre counts as 0.25 (the minimum radius):
    // 2.25 * 0.1 / 0.0625 = 3.6 from it, scale 36.
    const auto far = probe.run(2, {{3.5f, 0.0f, 0.0f}, {0.6f, 0.0f, 0.0f}});
    EXPECT_NEAR(far.points[0].x, 1.25f, 1e-6f);
    EXPECT_NEAR(far.dr[0], 0.25f, 1e-6f);
    EXPECT_NEAR(far.points[1].x, 4.1f, 1e-5f);
    EXPECT_NEAR(far.dr[1], 36.0f, 1e-4f);
    // An involution beyond the minimum radius: inverting twice gives the point back.
    std::vector<glm::vec3> points;
    for (const glm::vec3 p : random_points(100, 2.0f, 11)) {
        if (glm::length(p - glm::vec3(0.5f, 0.0f, 0.0f)) > 0.3f) points.push_back(p);
    }
    const auto once = probe.run(2, points);
    const auto twice = probe.run(2, once.points);
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_LT(glm::length(twice.points[i] - points[i]),
                  1e-4f * (1.0f + glm::length(points[i])));
        EXPECT_NEAR(once.dr[i] * twice.dr[i], 1.0f, 1e-4f);
    }
}

TEST_P(Helpers, RotationsTakeTheirAxisFromAVec3ParameterOfAnyLength) {
    HelperProbe probe(GetParam());
    // 90 degrees about +z (given as (0, 0, 2)): x goes to y, right-handed; both forms.
    for (const int which : {3, 4}) {
        const auto q = probe.run(which, {{1.0f, 0.0f, 0.5f}}).points.front();
        EXPECT_NEAR(q.x, 0.0f, 1e-6f);
        EXPECT_NEAR(q.y, 1.0f, 1e-6f);
        EXPECT_NEAR(q.z, 0.5f, 1e-6f);
    }
    // 120 degrees about (1, 1, 1) cycles the axes: x -> y -> z.
    const auto cycled =
        probe.run(3, {{1.0f, 0.0f, 0.0f}}, {"axis=3,3,3", "angle=120"}).points.front();
    EXPECT_NEAR(cycled.x, 0.0f, 1e-6f);
    EXPECT_NEAR(cycled.y, 1.0f, 1e-6f);
    EXPECT_NEAR(cycled.z, 0.0f, 1e-6f);
    // A zero axis turns nothing.
    const auto kept =
        probe.run(3, {{0.3f, -0.2f, 0.9f}}, {"axis=0,0,0", "angle=37"}).points.front();
    EXPECT_EQ(kept, glm::vec3(0.3f, -0.2f, 0.9f));
}

TEST_P(Helpers, ScaleAboutKeepsItsCentreAndScalesDistancesFromIt) {
    HelperProbe probe(GetParam());
    // Scale 1.5 (the radius parameter) about (0.5, 0, 0).
    const auto q = probe.run(5, {{0.5f, 0.0f, 0.0f}, {1.5f, 1.0f, -2.0f}}).points;
    EXPECT_NEAR(glm::length(q[0] - glm::vec3(0.5f, 0.0f, 0.0f)), 0.0f, 1e-6f);
    EXPECT_NEAR(q[1].x, 2.0f, 1e-6f);
    EXPECT_NEAR(q[1].y, 1.5f, 1e-6f);
    EXPECT_NEAR(q[1].z, -3.0f, 1e-6f);
}

std::string width_name(const ::testing::TestParamInfo<int>& width) {
    return "width" + std::to_string(width.param);
}

INSTANTIATE_TEST_SUITE_P(PacketWidths, Helpers, ::testing::ValuesIn(kWidths), width_name);

// --- The orbit-scene contract ---------------------------------------------------------------

// Each SDK example written with FGR_ORBIT against the same maths written out by hand in packet
// form (bench/authoring/*_packet.cl, what bench/authoring_cost.sh times): the same surface, so the
// same hits and the same image at both packet widths.
TEST(OrbitScenes, TheSdkExamplesRenderAsTheirHandWrittenPacketForms) {
    for (const auto& [id, packet] : {std::pair{"icosahedral-kifs", "icosahedral_kifs_packet.cl"},
                                     std::pair{"pseudo-kleinian", "pseudo_kleinian_packet.cl"}}) {
        const Scene example = sdk_example(id);
        Scene by_hand = example;
        by_hand.source =
            read_file(std::filesystem::path(FGR_TEST_SOURCE_DIR) / "../bench/authoring" / packet);
        for (const int width : kWidths) {
            const Frame orbit = render_small(example, width);
            const Frame written = render_small(by_hand, width);
            ASSERT_GT(orbit.hits, 1000) << id;
            // Sums may round differently (a fused multiply-add here, two operations there): a
            // handful of silhouette pixels may flip, and no pixel may differ by more than 2 LSB
            // elsewhere.
            const double hit_difference = std::abs(double(orbit.hits) - double(written.hits));
            EXPECT_LE(hit_difference, 0.001 * double(orbit.hits)) << id << " width " << width;
            size_t far_apart = 0;
            for (size_t i = 0; i < orbit.image.rgb.size(); ++i) {
                if (std::abs(int(orbit.image.rgb[i]) - int(written.image.rgb[i])) > 2) ++far_apart;
            }
            EXPECT_LE(far_apart, orbit.image.rgb.size() / 1000) << id << " width " << width;
        }
    }
}

// The lines of an OpenCL source that hold code: comments removed, blank lines skipped, each line
// stripped of surrounding blanks.
std::vector<std::string> code_lines(const std::string& source) {
    const std::string code =
        std::regex_replace(source, std::regex(R"(/\*[\s\S]*?\*/|//[^\n]*)"), "");
    std::vector<std::string> lines;
    std::istringstream in(code);
    for (std::string line; std::getline(in, line);) {
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos) continue;
        lines.push_back(line.substr(first, line.find_last_not_of(" \t\r") - first + 1));
    }
    return lines;
}

// The SDK guide's orbit-scene examples are short (at most 15 lines of kernel code),
// and the guide shows each file's code as it is.
TEST(OrbitScenes, TheGuidesExamplesAreAtMostFifteenLinesAndShownAsTheyAre) {
    const std::filesystem::path sdk = std::filesystem::path(FGR_TEST_SOURCE_DIR) / "../sdk";
    const std::string guide =
        read_file(std::filesystem::path(FGR_TEST_SOURCE_DIR) / "../docs/sdk/orbit-scenes.md");
    for (const char* file : {"examples/icosahedral-kifs/icosahedral_kifs.cl",
                             "examples/pseudo-kleinian/pseudo_kleinian.cl"}) {
        const auto lines = code_lines(read_file(sdk / file));
        EXPECT_LE(lines.size(), 15u) << file;
        // The guide's code block holding the file's last line of code (its FGR_DISTANCE).
        const size_t last = guide.find(lines.back());
        ASSERT_NE(last, std::string::npos) << file << " is not in the guide";
        const size_t block = guide.rfind("```c\n", last);
        const size_t end = guide.find("```", last);
        ASSERT_NE(block, std::string::npos);
        EXPECT_EQ(code_lines(guide.substr(block + 5, end - block - 5)), lines) << file;
    }
}

// An escape-time fractal in the contract: the power-8 Mandelbulb with its bailout, against the
// library's hand-written mandelbulb_de, DE for DE at points inside, near and far from the set
// (lanes escaping at different iterations in one packet).
TEST(OrbitScenes, TheBailoutStopsEachLaneWhereTheHandWrittenLoopDoes) {
    const std::string orbit_bulb = R"(
#define FGR_KERNEL_API 2
FGR_ORBIT(param_iterations, 2.0f)
FGR_ITERATE
    const real r = v3_length(z);
    const real r7 = fgr_pown(r, 7);
    dr = 8.0f * r7 * dr + 1.0f;
    z = v3_add(bulb_power_integer(z, r, r7 * r, 8, 0), c);
FGR_DISTANCE(select(0.5f * log(v3_length(z)) * v3_length(z) / dr, fgr_real(0.0f),
                    v3_length(z) <= 0.0f))
)";
    const std::string library_bulb = R"(
real scene_de(vec3 p, PARAMS) {
    orbit_trap unused;
    return mandelbulb_de(p, 8.0f, 2.0f, param_iterations, 0, 0, &unused);
}
)";
    auto points = random_points(160, 1.6f, 5);
    points.push_back({0.0f, 0.0f, 0.0f});
    for (const int width : kWidths) {
        ProgramCache no_disk_cache{std::filesystem::path()};
        const Scene a = test::inline_scene(orbit_bulb), b = test::inline_scene(library_bulb);
        Renderer ra(shared_device(), no_disk_cache, a, {width, 0}),
            rb(shared_device(), no_disk_cache, b, {width, 0});
        const auto da = ra.probe_de(points, default_param_values(a));
        const auto db = rb.probe_de(points, default_param_values(b));
        for (size_t i = 0; i < points.size(); ++i) {
            EXPECT_NEAR(da[i], db[i], 1e-5f * (1.0f + std::abs(db[i])))
                << "width " << width << " at " << points[i].x << " " << points[i].y << " "
                << points[i].z;
        }
    }
}

// Colour is opt-in: without `#define FGR_SCENE_HAS_COLOUR` an orbit scene takes the library's
// default colour (and needs no colour parameters); with it, the orbit trap's.
TEST(OrbitScenes, OrbitTrapColourIsChosenByTheUsualDefine) {
    Scene coloured = sdk_example("icosahedral-kifs");
    Scene plain = coloured;
    const std::string define = "#define FGR_SCENE_HAS_COLOUR\n";
    const size_t at = plain.source.find(define);
    ASSERT_NE(at, std::string::npos);
    plain.source.erase(at, define.size());
    const Frame with_trap = render_small(coloured, 16);
    const Frame without = render_small(plain, 16);
    EXPECT_EQ(with_trap.hits, without.hits);
    EXPECT_NE(with_trap.image.rgb, without.image.rgb);
}

}  // namespace
}  // namespace fgr
