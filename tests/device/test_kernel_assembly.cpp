// SPDX-License-Identifier: Apache-2.0
// Kernel assembly: the switches a program is built with, the generated parameter accessors, build
// errors mapped to the scene's own lines, the on-disk program cache, and parameters that change
// without a rebuild.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "device/kernel_assembly.hpp"
#include "device/program_cache.hpp"
#include "fgr/plugin.h"
#include "hermetic_caches.hpp"
#include "render/renderer.hpp"
#include "scene/kernel_api.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

TEST(KernelAssembly, OptionsCarryPacketWidthAndOnlyRequestedEffects) {
    const std::string plain = switch_options({16, 0});
    EXPECT_NE(plain.find("-DFGR_WIDTH=16"), std::string::npos);
    EXPECT_EQ(plain.find("FGR_EFFECT_"), std::string::npos);

    const std::string shadows = switch_options({1, FGR_EFFECT_SHADOWS});
    EXPECT_NE(shadows.find("-DFGR_WIDTH=1"), std::string::npos);
    EXPECT_NE(shadows.find("-DFGR_EFFECT_SHADOWS"), std::string::npos);
    EXPECT_EQ(shadows.find("FGR_EFFECT_AMBIENT_OCCLUSION"), std::string::npos);

    const std::string both = switch_options({8, FGR_EFFECT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION});
    EXPECT_NE(both.find("-DFGR_EFFECT_SHADOWS"), std::string::npos);
    EXPECT_NE(both.find("-DFGR_EFFECT_AMBIENT_OCCLUSION"), std::string::npos);
    EXPECT_EQ(effect_names(FGR_EFFECT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION),
              "shadows,ambient_occlusion");
    EXPECT_EQ(effect_names(0), "none");
}

TEST(KernelAssembly, FloatBuildsMakePlainLiteralsSinglePrecision) {
    EXPECT_NE(switch_options({16, 0}).find("-cl-single-precision-constant"), std::string::npos);
    KernelSwitches in_double{16, 0};
    in_double.double_precision = true;
    EXPECT_EQ(switch_options(in_double).find("-cl-single-precision-constant"), std::string::npos);
}

TEST(KernelAssembly, EffectChangesAddAndRemoveByName) {
    const uint64_t base = FGR_EFFECT_AMBIENT_OCCLUSION;
    EXPECT_EQ(apply_effect_changes(base, ""), base);
    EXPECT_EQ(apply_effect_changes(base, "+shadows"), base | FGR_EFFECT_SHADOWS);
    EXPECT_EQ(apply_effect_changes(base, "reflections,-ambient_occlusion"),
              uint64_t{FGR_EFFECT_REFLECTIONS});
    EXPECT_EQ(apply_effect_changes(base, "+soft_shadows,,-soft_shadows"), base);
    EXPECT_EQ(apply_effect_changes(base, "none"), 0u);
    EXPECT_EQ(apply_effect_changes(base, "none,+fog"), uint64_t{FGR_EFFECT_FOG});
    EXPECT_THROW(apply_effect_changes(base, "+glitter"), std::invalid_argument);
    EXPECT_THROW(apply_effect_changes(base, "-"), std::invalid_argument);
    const std::string options =
        switch_options({16, apply_effect_changes(0, "soft_shadows,reflections")});
    EXPECT_NE(options.find("-DFGR_EFFECT_SOFT_SHADOWS"), std::string::npos);
    EXPECT_NE(options.find("-DFGR_EFFECT_REFLECTIONS"), std::string::npos);
    EXPECT_EQ(options.find("-DFGR_EFFECT_SHADOWS"), std::string::npos);
}

// The assembled program after preprocessing with the program's own -D switches (GNU cpp stands in
// for the OpenCL compiler's preprocessor): the code the device compiler actually sees.
std::string preprocessed(const AssembledProgram& program) {
    const auto source = std::filesystem::temp_directory_path() /
                        ("fgr-assembly-" + std::to_string(::getpid()) + ".cl");
    std::ofstream(source) << program.source;
    // The C preprocessor takes the switches' macros, not the OpenCL compiler's own options, and the
    // version macro the OpenCL compiler defines (without it the shared layouts would include their
    // host-only headers).
    std::string macros = "-D__OPENCL_C_VERSION__=120 ";
    std::istringstream options(program.options);
    for (std::string option; options >> option;) {
        if (option.rfind("-D", 0) == 0) macros += option + " ";
    }
    const std::string command = "cpp -P " + macros + source.string() + " 2>/dev/null";
    std::string output;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[4096];
        for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
            output.append(buffer, n);
        ::pclose(pipe);
    }
    std::filesystem::remove(source);
    return output;
}

TEST(KernelAssembly, DisabledEffectsLeaveNoCodeInTheProgram) {
    const Scene scene = test::sphere_scene();
    const std::string plain = preprocessed(assemble_program(scene, {16, 0}));
    ASSERT_NE(plain.find("fgr_render"), std::string::npos) << "preprocessing failed";
    const struct {
        uint64_t effect;
        const char* code;  // a function only that effect's code defines
    } effects[] = {{FGR_EFFECT_SHADOWS, "light_visibility"},
                   {FGR_EFFECT_SOFT_SHADOWS, "light_visibility"},
                   {FGR_EFFECT_SAMPLED_OCCLUSION, "sampled_occlusion"},
                   {FGR_EFFECT_REFLECTIONS, "add_reflection"},
                   {FGR_EFFECT_REFRACTION, "add_refraction"},
                   {FGR_EFFECT_GLOW, "apply_glow"},
                   {FGR_EFFECT_FOG, "apply_fog"},
                   {FGR_EFFECT_DEPTH_OF_FIELD, "focus"}};
    for (const auto& effect : effects) {
        EXPECT_EQ(plain.find(effect.code), std::string::npos) << effect.code;
        const std::string with = preprocessed(assemble_program(scene, {16, effect.effect}));
        EXPECT_NE(with.find(effect.code), std::string::npos) << effect.code;
    }
}

TEST(KernelAssembly, AccessorsFollowTheBufferLayout) {
    Scene scene =
        test::inline_scene("real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }");
    scene.params.insert(scene.params.begin(),
                        {ParamInfo{.id = "scale", .type = ParamType::Float},
                         ParamInfo{.id = "offset", .type = ParamType::Vec3},
                         ParamInfo{.id = "count", .type = ParamType::Int},
                         ParamInfo{.id = "enabled", .type = ParamType::Bool}});
    const std::string accessors = param_accessors(scene, kKernelApiLatest);
    EXPECT_NE(accessors.find("#define param_scale (fgr_params[0])"), std::string::npos);
    // A vec3 is uniform, a float3; before kernel API 4 it read as a vec3 of lanes.
    EXPECT_NE(accessors.find("#define param_offset ((float3)(fgr_params[1], fgr_params[2], "
                             "fgr_params[3]))"),
              std::string::npos);
    EXPECT_NE(param_accessors(scene, 3).find("#define param_offset v3_splat(fgr_params[1], "
                                             "fgr_params[2], fgr_params[3])"),
              std::string::npos);
    EXPECT_NE(accessors.find("#define param_count ((int)fgr_params[4])"), std::string::npos);
    EXPECT_NE(accessors.find("#define param_enabled (fgr_params[5] != 0.0f)"), std::string::npos);
    // The built-in quality knobs follow the scene's own parameters.
    EXPECT_NE(accessors.find("#define param_max_steps ((int)fgr_params[6])"), std::string::npos);
}

// A scene declares which parameters may be compiled in; only whole values within bounds are, and
// their accessors read the constant instead of the buffer.
TEST(KernelAssembly, SpecialisableParametersCompileInAsConstants) {
    Scene scene = test::inline_scene(
        "/* #define FGR_SPECIALISABLE scale */\n"
        "#define FGR_SPECIALISABLE  count\tscale \n"
        "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_scale; }");
    scene.params.insert(scene.params.begin(), {ParamInfo{.id = "scale", .type = ParamType::Float},
                                               ParamInfo{.id = "count", .type = ParamType::Int}});
    EXPECT_EQ(declared_specialisable(scene.source), (std::vector<std::string>{"count", "scale"}));
    EXPECT_TRUE(declared_specialisable("// #define FGR_SPECIALISABLE count\n").empty());
    std::vector<float> params = default_param_values(scene);
    params[0] = 8.0f;
    params[1] = 12.0f;
    const std::vector<SpecialisedParam> whole = specialisation_for(scene, params);
    ASSERT_EQ(whole.size(), 2u);
    EXPECT_EQ(whole[0], (SpecialisedParam{"count", 12.0f}));
    EXPECT_EQ(whole[1], (SpecialisedParam{"scale", 8.0f}));
    const std::string accessors = param_accessors(scene, kKernelApiLatest, whole);
    EXPECT_NE(accessors.find("#define param_scale (8.0f)"), std::string::npos) << accessors;
    EXPECT_NE(accessors.find("#define param_count ((int)12.0f)"), std::string::npos) << accessors;
    EXPECT_EQ(specialisation_mismatch(scene, whole, params), "");
    EXPECT_NE(specialisation_mismatch(scene, whole, default_param_values(scene)), "");
    // A fraction or a huge value leaves the parameter to the buffer.
    params[0] = 7.5f;
    params[1] = 1e6f;
    EXPECT_TRUE(specialisation_for(scene, params).empty());
    // A declaration naming no int or float parameter is refused, naming the file.
    scene.source = "#define FGR_SPECIALISABLE radius\n" + scene.source;
    try {
        specialisation_for(scene, params);
        FAIL() << "no error for an unknown parameter";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("'radius'"), std::string::npos) << error.what();
    }
}

// The hint reads clang's words for a lane value where a float is wanted, and for a float3 where a
// vec3 is wanted, each only in the kernel API where a parameter gives that type.
TEST(KernelAssembly, BuildErrorsMixingLaneAndUniformValuesGetAHint) {
    const std::string real_as_float =
        "error: s.cl:4:17: initializing 'const __private float' with an expression of "
        "incompatible type 'real' (aka 'float16')\n";
    const std::string float3_as_vec3 =
        "error: s.cl:3:32: passing 'float3' (vector of 3 'float' values) to parameter of "
        "incompatible type 'vec3' (aka 'struct vec3')\n";
    EXPECT_NE(build_error_hint(3, "1 error generated.\n" + real_as_float).find("FGR_KERNEL_API 4"),
              std::string::npos);
    EXPECT_EQ(build_error_hint(4, real_as_float), "");
    EXPECT_NE(build_error_hint(4, float3_as_vec3).find("v3_uniform(param_<id>)"),
              std::string::npos);
    EXPECT_EQ(build_error_hint(3, float3_as_vec3), "");
    EXPECT_EQ(build_error_hint(4, "error: s.cl:1:1: use of undeclared identifier 'x'\n"), "");
    EXPECT_EQ(assemble_program(test::inline_scene("#define FGR_KERNEL_API 4\n"), {1, 0}).kernel_api,
              4);
}

TEST(KernelAssembly, SceneSourceIsTaggedWithItsOwnFileName) {
    const Scene scene = test::inline_scene("real scene_de(vec3 p, PARAMS) { return p.x; }");
    const AssembledProgram program = assemble_program(scene, {1, 0});
    const size_t scene_line = program.source.find("#line 1 \"inline.cl\"\nreal scene_de");
    ASSERT_NE(scene_line, std::string::npos);
    EXPECT_LT(program.source.find("#line 1 \"fgr_types.cl\""), scene_line);
    EXPECT_GT(program.source.find("#line 1 \"fgr_render.cl\""), scene_line);
}

// A scene's program holds the formula families its source calls (formula_NAME( as a word, or
// formula_NAME_distance(), before the scene's source, and no others: a plugin iterates the
// library's steps as a formula scene does, without copying them.
TEST(KernelAssembly, ProgramsHoldTheFormulaFamiliesTheSceneCalls) {
    const auto families_in = [](const std::string& source) {
        const std::string program =
            assemble_program(test::inline_scene("#define FGR_KERNEL_API 2\n" + source), {1, 0})
                .source;
        std::string found;
        for (const char* family : {"bulbs", "hypercomplex", "boxes", "kifs", "kleinian"}) {
            const size_t at = program.find(fmt::format("#line 1 \"formulas/{}.cl\"", family));
            if (at == std::string::npos) continue;
            EXPECT_LT(at, program.find("#line 1 \"inline.cl\"")) << family;
            found += found.empty() ? family : std::string(" ") + family;
        }
        return found;
    };
    const std::string plain = "real scene_de(vec3 p, PARAMS) { return p.x; }\n";
    EXPECT_EQ(families_in(plain), "");
    EXPECT_EQ(
        families_in(plain + "void f(vec3* z, real* w, real* dr, vec3 c) {\n"
                            "    formula_mandelbox (z, w, dr, c, 2.0f, 1.0f, 0.5f, 1.0f);\n}\n"),
        "boxes");
    EXPECT_EQ(families_in(plain + "real g(vec3 z, real w, real dr, vec3 c) {\n"
                                  "    return formula_menger_distance(z, w, dr, c, 3.0f, z);\n}\n"
                                  "void h(vec3* z, real* w, real* dr, vec3 c) {\n"
                                  "    formula_mandelbulb_latitude(z, w, dr, c, 8.0f);\n}\n"),
              "bulbs kifs");
    // Words that only look like calls: a comment's mention, a longer name, another identifier.
    EXPECT_EQ(families_in(plain + "/* like formula_menger, in the library */\n"
                                  "#define my_formula_quaternion(x) (x)\n"
                                  "#define formula_mandelboxes 1\n"),
              "");
    // The library's families are kernel API 2: a scene of API 1 calling one is told so.
    try {
        (void)assemble_program(
            test::inline_scene(plain + "void f(vec3* z, real* w, real* dr, vec3 c) "
                                       "{ formula_quaternion(z, w, dr, c); }\n"),
            {1, 0});
        ADD_FAILURE() << "an API 1 scene calling a formula was assembled";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(
            std::string(error.what()).find("needs kernel API 2: put `#define FGR_KERNEL_API 2`"),
            std::string::npos)
            << error.what();
    }
}

// OpenCL source without its /* */ and // comments.
std::string code_of(const std::string& source) {
    std::string code;
    for (size_t i = 0; i < source.size(); ++i) {
        if (source.compare(i, 2, "/*") == 0) {
            i = std::min(source.find("*/", i + 2), source.size()) + 1;
        } else if (source.compare(i, 2, "//") == 0) {
            i = std::min(source.find('\n', i), source.size());
        } else {
            code += source[i];
        }
    }
    return code;
}

// The built-in scenes whose formulas the library has iterate the library's steps, not copies:
// their programs hold its family, and their code calls none of the folds or squares the steps
// are made of.
TEST(KernelAssembly, BuiltInScenesIterateTheLibrarysSteps) {
    const std::pair<const char*, const char*> users[] = {{"mandelbox.so", "formulas/boxes.cl"},
                                                         {"julia.so", "formulas/hypercomplex.cl"},
                                                         {"menger.so", "formulas/kifs.cl"},
                                                         {"sierpinski.so", "formulas/kifs.cl"}};
    for (const auto& [plugin, family] : users) {
        const Scene scene = test::built_scene(plugin);
        const std::string program = assemble_program(scene, {1, 0}).source;
        EXPECT_NE(program.find(fmt::format("#line 1 \"{}\"", family)), std::string::npos) << plugin;
        for (const char* copy :
             {"fold_box(", "quaternion_square(", "fold_menger(", "fold_sierpinski("}) {
            EXPECT_EQ(code_of(scene.source).find(copy), std::string::npos)
                << plugin << " calls " << copy;
        }
    }
}

TEST(KernelAssembly, BuildErrorsNameTheScenesFileAndLine) {
    const ComputeDevice device = open_device(-1);
    ProgramCache cache{std::filesystem::path()};
    // Line 3 uses an undeclared identifier.
    const Scene scene = test::inline_scene(
        "/* a broken scene */\n"
        "real scene_de(vec3 p, PARAMS) {\n"
        "    return v3_length(p) - undeclared_radius;\n"
        "}\n");
    try {
        Renderer renderer(device, cache, scene, {preferred_packet_width(device.info), 0});
        FAIL() << "a scene that does not compile must throw";
    } catch (const KernelBuildError& error) {
        EXPECT_NE(error.build_log().find("inline.cl:3:"), std::string::npos) << error.build_log();
        EXPECT_NE(error.build_log().find("undeclared_radius"), std::string::npos);
    }
}

class ProgramCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = std::filesystem::temp_directory_path() /
                     ("fgr-cache-test-" + std::to_string(::getpid()));
        std::filesystem::remove_all(directory_);
    }
    void TearDown() override { std::filesystem::remove_all(directory_); }
    std::filesystem::path directory_;
};

TEST_F(ProgramCacheTest, SecondBuildComesFromDiskAndADamagedEntryIsRebuilt) {
    const ComputeDevice device = open_device(-1);
    const Scene scene =
        test::inline_scene("real scene_de(vec3 p, PARAMS) { return v3_length(p) - 0.5f; }");
    const AssembledProgram program = assemble_program(scene, {4, 0});
    BuildReport report;
    ProgramCache(directory_, cache_size_limit(), StoredPrograms::Always)
        .build(device, program, &report);
    EXPECT_EQ(report.origin, BuildReport::Origin::Compiled);
    const auto entry = directory_ / (ProgramCache::cache_key(device, program) + ".bin");
    ASSERT_TRUE(std::filesystem::exists(entry));

    ProgramCache fresh(directory_, cache_size_limit(), StoredPrograms::Always);
    fresh.build(device, program, &report);
    EXPECT_EQ(report.origin, BuildReport::Origin::Disk);
    fresh.build(device, program, &report);
    EXPECT_EQ(report.origin, BuildReport::Origin::Memory);

    std::ofstream(entry, std::ios::binary | std::ios::trunc) << "not a program binary";
    ProgramCache(directory_, cache_size_limit(), StoredPrograms::Always)
        .build(device, program, &report);
    EXPECT_EQ(report.origin, BuildReport::Origin::Compiled);
}

// The tests are hermetic (hermetic_caches.cpp): fgr's default cache is this process's own fresh
// directory and no cache of fgr's or the drivers' lies under the user's ~/.cache.
TEST(ProgramCacheDirectory, TestsUseTheirOwnCachesNotTheUsers) {
    EXPECT_EQ(ProgramCache::default_directory(), test::test_kernel_cache());
    const char* home = std::getenv("HOME");
    const std::filesystem::path user_cache =
        std::filesystem::path(home ? home : "/nonexistent") / ".cache";
    for (const char* variable : {"FGR_CACHE_DIR", "XDG_CACHE_HOME", "POCL_CACHE_DIR"}) {
        const char* value = std::getenv(variable);
        ASSERT_TRUE(value != nullptr && *value != '\0') << variable << " is not set";
        const std::filesystem::path relative =
            std::filesystem::path(value).lexically_relative(user_cache);
        EXPECT_TRUE(relative.empty() || *relative.begin() == "..")
            << variable << "=" << value << " lies under " << user_cache;
    }
}

TEST(ProgramCacheKey, DependsOnSourceSwitchesAndDevice) {
    ComputeDevice device;
    device.info.name = "device A";
    const Scene scene = test::inline_scene("real scene_de(vec3 p, PARAMS) { return p.x; }");
    const AssembledProgram base = assemble_program(scene, {8, 0});
    const std::string key = ProgramCache::cache_key(device, base);
    EXPECT_EQ(key, ProgramCache::cache_key(device, base));
    EXPECT_NE(key,
              ProgramCache::cache_key(device, assemble_program(scene, {8, FGR_EFFECT_SHADOWS})));
    EXPECT_NE(key, ProgramCache::cache_key(device, assemble_program(scene, {16, 0})));
    ComputeDevice other = device;
    other.info.name = "device B";
    EXPECT_NE(key, ProgramCache::cache_key(other, base));
}

TEST(KernelAssembly, ChangingParametersNeedsNoRebuild) {
    const ComputeDevice device = open_device(-1);
    ProgramCache cache{std::filesystem::path()};
    const Scene scene = test::sphere_scene();
    Renderer renderer(device, cache, scene, {preferred_packet_width(device.info), 0});
    FrameRequest request{48, 32, scene.cameras.front().view, default_param_values(scene)};
    const long small_hits = renderer.render(request).hits;
    set_param_from_text(scene, request.params, "radius=0.9");
    const long large_hits = renderer.render(request).hits;
    EXPECT_GT(small_hits, 0);
    EXPECT_GT(large_hits, small_hits * 2);
}

}  // namespace
}  // namespace fgr
