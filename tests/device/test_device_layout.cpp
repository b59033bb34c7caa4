// SPDX-License-Identifier: Apache-2.0
// The layouts the host and the kernels share (kernels/shared/fgr_layout_*.h), checked on the
// device: the OpenCL compiler reports each shared struct's size and each field's offset and they
// must equal the host's (whose own are pinned by static_asserts in device/kernel_layout.hpp), and
// the driver names each kernel argument at the index the host sets it by. A header edited on one
// side only fails here: a mutated copy of a shared header, compiled for the device, is caught.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "device/kernel_assembly.hpp"
#include "device/kernel_layout.hpp"
#include "device/math_check.hpp"
#include "device_suite.hpp"
#include "fgr/kernel_library.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

// Every shared struct's fields, as (struct, field): the host takes offsetof, the device the
// distance of the field's address from the struct's.
#define FGR_SHARED_FIELDS(X)             \
    X(camera_frame, eye)                 \
    X(camera_frame, forward)             \
    X(camera_frame, right)               \
    X(camera_frame, up)                  \
    X(camera_frame, tan_half_fov)        \
    X(camera_frame, pixel_angle)         \
    X(camera_frame, width)               \
    X(camera_frame, height)              \
    X(camera_frame, projection)          \
    X(camera_frame, fisheye_half_fov)    \
    X(camera_frame, eye_separation)      \
    X(camera_frame, convergence)         \
    X(camera_frame, region_x)            \
    X(camera_frame, region_y)            \
    X(camera_frame, region_width)        \
    X(camera_frame, region_height)       \
    X(environment_info, transform)       \
    X(environment_info, width)           \
    X(environment_info, height)          \
    X(environment_info, rows_offset)     \
    X(environment_info, columns_offset)  \
    X(path_settings, max_bounces)        \
    X(path_settings, roulette_depth)     \
    X(path_settings, radiance_clamp)     \
    X(path_settings, flags)              \
    X(path_settings, seed)               \
    X(path_settings, light_count)        \
    X(path_settings, environment_weight) \
    X(path_settings, launch_samples)

#define FGR_SHARED_STRUCTS(X) X(camera_frame) X(environment_info) X(path_settings)

struct Measure {
    std::string name;   // "camera_frame" (its size) or "camera_frame.eye" (the field's offset)
    std::string value;  // the OpenCL C expression that gives it on the device
    int host = 0;       // what the host's compiler says
};

std::vector<Measure> measures() {
    std::vector<Measure> list;
#define FGR_STRUCT_SIZE(type) \
    list.push_back({#type, "sizeof(" #type ")", int(sizeof(layout::type))});
#define FGR_FIELD_OFFSET(type, field)                                 \
    list.push_back({#type "." #field,                                 \
                    "(int)((__private char*)&" #type "_value." #field \
                    " - (__private char*)&" #type "_value)",          \
                    int(offsetof(layout::type, field))});
    FGR_SHARED_STRUCTS(FGR_STRUCT_SIZE)
    FGR_SHARED_FIELDS(FGR_FIELD_OFFSET)
#undef FGR_STRUCT_SIZE
#undef FGR_FIELD_OFFSET
    return list;
}

// The shared headers as a program pastes them, then a kernel writing every measure in order.
std::string layout_report_source(const std::vector<KernelFile>& headers) {
    std::string source;
    for (const KernelFile& file : headers) {
        source += fmt::format("#line 1 \"{}\"\n{}\n", file.name, file.source);
    }
    source += "__kernel void layout_report(__global int* out) {\n";
#define FGR_DECLARE(type) source += "    " #type " " #type "_value;\n";
    FGR_SHARED_STRUCTS(FGR_DECLARE)
#undef FGR_DECLARE
    const std::vector<Measure> list = measures();
    for (size_t i = 0; i < list.size(); ++i) {
        source += fmt::format("    out[{}] = (int)({});\n", i, list[i].value);
    }
    source += "}\n";
    return source;
}

std::vector<KernelFile> shared_headers() {
    const auto headers = kernel_layout();
    return {headers.begin(), headers.end()};
}

class DeviceLayout : public test::DeviceSuite<> {
protected:
    // The measures that differ between the device (compiling `headers`) and the host, as
    // "name: device D, host H" lines.
    static std::vector<std::string> mismatches(const std::vector<KernelFile>& headers) {
        const std::vector<Measure> list = measures();
        AssembledProgram assembled{layout_report_source(headers), ""};
        cl::Program program = cache_->build(*device_, assembled);
        cl::Kernel kernel(program, "layout_report");
        cl::Buffer out(device_->context, CL_MEM_WRITE_ONLY, sizeof(cl_int) * list.size());
        kernel.setArg(0, out);
        device_->queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1), cl::NDRange(1));
        std::vector<cl_int> device(list.size());
        device_->queue.enqueueReadBuffer(out, CL_TRUE, 0, sizeof(cl_int) * list.size(),
                                         device.data());
        std::vector<std::string> differ;
        for (size_t i = 0; i < list.size(); ++i) {
            if (device[i] != list[i].host) {
                differ.push_back(
                    fmt::format("{}: device {}, host {}", list[i].name, device[i], list[i].host));
            }
        }
        return differ;
    }

    // The name the driver gives argument `index` of `kernel_name` in `program`.
    static std::string argument_name(const cl::Program& program, const char* kernel_name,
                                     int index) {
        cl::Kernel kernel(program, kernel_name);
        std::string name = kernel.getArgInfo<CL_KERNEL_ARG_NAME>(static_cast<cl_uint>(index));
        // Some drivers count the terminating NUL in the string's length.
        while (!name.empty() && name.back() == '\0') name.pop_back();
        return name;
    }

    // A DE scene's program for `mode`, built so the driver keeps each argument's name.
    static cl::Program mode_program(RenderMode mode) {
        static const Scene scene = test::inline_scene(
            "real scene_de(vec3 p, PARAMS) { return v3_length(p) - fgr_real(1.0f); }\n");
        KernelSwitches switches;
        switches.mode = mode;
        AssembledProgram assembled = assemble_program(scene, switches);
        assembled.options += " -cl-kernel-arg-info";
        return cache_->build(*device_, assembled);
    }
};

TEST_F(DeviceLayout, SharedStructsLayOutAsOnTheHost) {
    const std::vector<std::string> differ = mismatches(shared_headers());
    EXPECT_TRUE(differ.empty()) << fmt::format("{}", fmt::join(differ, "\n"));
}

// A header changed for the device alone (two of camera_frame's fields trade places, as an edit
// to a private copy would) is caught: the device's offsets no longer match the host's.
TEST_F(DeviceLayout, AMutatedHeaderIsCaught) {
    std::vector<KernelFile> headers = shared_headers();
    std::string mutated;
    for (KernelFile& file : headers) {
        if (std::string(file.name) != "shared/fgr_layout_camera.h") continue;
        mutated = file.source;
        const std::string width = "fgr_layout_int width;";
        const std::string height = "fgr_layout_int height;";
        const size_t at_width = mutated.find(width), at_height = mutated.find(height);
        ASSERT_NE(at_width, std::string::npos);
        ASSERT_NE(at_height, std::string::npos);
        mutated.replace(at_height, height.size(), width);
        mutated.replace(at_width, width.size(), height);
        file.source = mutated.c_str();
    }
    ASSERT_FALSE(mutated.empty()) << "no shared/fgr_layout_camera.h among the shared headers";
    const std::vector<std::string> differ = mismatches(headers);
    EXPECT_EQ(differ, (std::vector<std::string>{"camera_frame.width: device 76, host 72",
                                                "camera_frame.height: device 72, host 76"}));
}

struct NamedArgument {
    const char* kernel;
    int index;
    const char* name;
};

void expect_names(const cl::Program& program, const std::vector<NamedArgument>& arguments,
                  std::string (*name_of)(const cl::Program&, const char*, int)) {
    for (const NamedArgument& argument : arguments) {
        EXPECT_EQ(name_of(program, argument.kernel, argument.index), argument.name)
            << argument.kernel << " argument " << argument.index;
    }
}

// What every mode's fgr_render starts with, the prepass and the probes (in every program).
const std::vector<NamedArgument> kCommonArguments = {
    {"fgr_render", FGR_RENDER_ARG_PLANES, "planes"},
    {"fgr_render", FGR_RENDER_ARG_PLANE_SIZE, "plane_size"},
    {"fgr_render", FGR_RENDER_ARG_TILE_COUNT, "tile_count"},
    {"fgr_render", FGR_RENDER_ARG_CAMERA, "camera"},
    {"fgr_render", FGR_RENDER_ARG_SAMPLE, "sample"},
    {"fgr_render", FGR_RENDER_ARG_PARAMS, "fgr_params"},
    {"fgr_render", FGR_RENDER_ARG_MARCH_STARTS, "march_starts"},
    {"fgr_render", FGR_RENDER_ARG_MARCH_HINTS, "march_hints"},
    {"fgr_render", FGR_RENDER_ARG_HAS_HINTS, "has_hints"},
    {"fgr_prepass", FGR_PREPASS_ARG_STARTS, "starts"},
    {"fgr_prepass", FGR_PREPASS_ARG_BLOCK_PLANE, "block_plane"},
    {"fgr_prepass", FGR_PREPASS_ARG_PACKET_COUNT, "packet_count"},
    {"fgr_prepass", FGR_PREPASS_ARG_CAMERA, "camera"},
    {"fgr_prepass", FGR_PREPASS_ARG_PARAMS, "fgr_params"},
    {"fgr_prepass", FGR_PREPASS_ARG_CONE_SCALE, "cone_scale"},
    {"fgr_probe_de", FGR_PROBE_ARG_POINTS, "points"},
    {"fgr_probe_de", FGR_PROBE_ARG_PLANE_SIZE, "plane_size"},
    {"fgr_probe_de", FGR_PROBE_ARG_PACKET_COUNT, "packet_count"},
    {"fgr_probe_de", FGR_PROBE_ARG_OUT, "out"},
    {"fgr_probe_de", FGR_PROBE_ARG_PARAMS, "fgr_params"},
    {"fgr_probe_normal", FGR_PROBE_ARG_POINTS, "points"},
    {"fgr_probe_normal", FGR_PROBE_ARG_OUT, "out"},
    {"fgr_probe_normal", FGR_PROBE_ARG_PARAMS, "fgr_params"},
    {"fgr_probe_normal", FGR_PROBE_ARG_EPS, "eps"},
};

TEST_F(DeviceLayout, ShadedKernelArgumentsSitAtTheirIndices) {
    const cl::Program program = mode_program(RenderMode::Shaded);
    expect_names(program, kCommonArguments, argument_name);
    expect_names(program,
                 {{"fgr_render", FGR_SHADED_ARG_LIGHTS, "lights"},
                  {"fgr_render", FGR_SHADED_ARG_LIGHT_COUNT, "light_count"}},
                 argument_name);
}

TEST_F(DeviceLayout, PathKernelArgumentsSitAtTheirIndices) {
    const cl::Program program = mode_program(RenderMode::Path);
    expect_names(program,
                 {{"fgr_render", FGR_RENDER_ARG_CAMERA, "camera"},
                  {"fgr_render", FGR_PATH_ARG_LIGHTS, "lights"},
                  {"fgr_render", FGR_PATH_ARG_SETTINGS, "settings"},
                  {"fgr_render", FGR_PATH_ARG_ENV_DATA, "env_data"},
                  {"fgr_render", FGR_PATH_ARG_ENVIRONMENT, "env"}},
                 argument_name);
}

TEST_F(DeviceLayout, BruteKernelArgumentsSitAtTheirIndices) {
    const cl::Program program = mode_program(RenderMode::Brute);
    expect_names(program,
                 {{"fgr_render", FGR_RENDER_ARG_HAS_HINTS, "has_hints"},
                  {"fgr_render", FGR_BRUTE_ARG_STATE, "state"},
                  {"fgr_brute_shade", FGR_RENDER_ARG_PLANES, "planes"},
                  {"fgr_brute_shade", FGR_RENDER_ARG_HAS_HINTS, "has_hints"},
                  {"fgr_brute_shade", FGR_BRUTE_SHADE_ARG_STATE, "state"},
                  {"fgr_brute_shade", FGR_BRUTE_SHADE_ARG_LIGHTS, "lights"},
                  {"fgr_brute_shade", FGR_BRUTE_SHADE_ARG_LIGHT_COUNT, "light_count"}},
                 argument_name);
}

TEST_F(DeviceLayout, MathCheckKernelArgumentsSitAtTheirIndices) {
    AssembledProgram assembled = math_check_program(false, 1);
    assembled.options += " -cl-kernel-arg-info";
    const cl::Program program = cache_->build(*device_, assembled);
    expect_names(program,
                 {{"fgr_check_exp", FGR_MATH_CHECK_ARG_A, "a"},
                  {"fgr_check_exp", FGR_MATH_CHECK_ARG_B, "b"},
                  {"fgr_check_exp", FGR_MATH_CHECK_ARG_OUT, "out"},
                  {"fgr_check_exp", FGR_MATH_CHECK_ARG_FIRST_CASE, "first_case"}},
                 argument_name);
}

}  // namespace
}  // namespace fgr
