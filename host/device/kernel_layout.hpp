// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the host and the kernels exchange, as the kernels declare it (kernels/shared/): structs
// passed by value, the light lists' layouts, which plane holds what and each kernel argument's
// index. Both sides compile the same headers; here the host checks that its compiler lays the
// structs out as OpenCL C does (each field aligned to its size, a float4 to 16 bytes, a struct
// to its largest field and padded to a multiple of it). tests/device/test_device_layout.cpp has the
// device report the same figures.

#include <cstddef>

#include "fgr_layout_arguments.h"
#include "fgr_layout_camera.h"
#include "fgr_layout_environment.h"
#include "fgr_layout_lights.h"
#include "fgr_layout_path.h"
#include "fgr_layout_planes.h"
#include "fgr_layout_types.h"

namespace fgr::layout {

static_assert(sizeof(fgr_layout_int) == 4 && sizeof(fgr_layout_uint) == 4 &&
              sizeof(fgr_layout_float) == 4);
static_assert(sizeof(fgr_layout_float4) == 16 && alignof(fgr_layout_float4) == 16);

static_assert(sizeof(camera_frame) == 112 && alignof(camera_frame) == 16);
static_assert(offsetof(camera_frame, eye) == 0);
static_assert(offsetof(camera_frame, forward) == 16);
static_assert(offsetof(camera_frame, right) == 32);
static_assert(offsetof(camera_frame, up) == 48);
static_assert(offsetof(camera_frame, tan_half_fov) == 64);
static_assert(offsetof(camera_frame, pixel_angle) == 68);
static_assert(offsetof(camera_frame, width) == 72);
static_assert(offsetof(camera_frame, height) == 76);
static_assert(offsetof(camera_frame, projection) == 80);
static_assert(offsetof(camera_frame, fisheye_half_fov) == 84);
static_assert(offsetof(camera_frame, eye_separation) == 88);
static_assert(offsetof(camera_frame, convergence) == 92);
static_assert(offsetof(camera_frame, region_x) == 96);
static_assert(offsetof(camera_frame, region_y) == 100);
static_assert(offsetof(camera_frame, region_width) == 104);
static_assert(offsetof(camera_frame, region_height) == 108);

static_assert(sizeof(environment_info) == 32 && alignof(environment_info) == 16);
static_assert(offsetof(environment_info, transform) == 0);
static_assert(offsetof(environment_info, width) == 16);
static_assert(offsetof(environment_info, height) == 20);
static_assert(offsetof(environment_info, rows_offset) == 24);
static_assert(offsetof(environment_info, columns_offset) == 28);

static_assert(sizeof(path_settings) == 32 && alignof(path_settings) == 4);
static_assert(offsetof(path_settings, max_bounces) == 0);
static_assert(offsetof(path_settings, roulette_depth) == 4);
static_assert(offsetof(path_settings, radiance_clamp) == 8);
static_assert(offsetof(path_settings, flags) == 12);
static_assert(offsetof(path_settings, seed) == 16);
static_assert(offsetof(path_settings, light_count) == 20);
static_assert(offsetof(path_settings, environment_weight) == 24);
static_assert(offsetof(path_settings, launch_samples) == 28);

// Each count covers the planes it counts, one block after the other.
static_assert(FGR_COLOUR_PLANE + FGR_COLOUR_PLANES == FGR_DEPTH_PLANE &&
              FGR_DEPTH_PLANE + 1 == FGR_COMMON_PLANES);
static_assert(FGR_SHADED_STEPS_PLANE == FGR_COMMON_PLANES &&
              FGR_SHADED_SECONDARY_PACKET_STEPS_PLANE == FGR_SHADED_SECONDARY_STEPS_PLANE + 1 &&
              FGR_SHADED_HEAP_PEAK_PLANE == FGR_SHADED_SECONDARY_PACKET_STEPS_PLANE + 1 &&
              FGR_SHADED_HEAP_PEAK_PLANE + 1 == FGR_COMMON_PLANES + FGR_SHADED_STATS_PLANES);
static_assert(FGR_SHADED_AOV_FOREGROUND + 3 == FGR_SHADED_AOV_PLANES);
static_assert(FGR_PATH_ALBEDO_PLANE == FGR_COMMON_PLANES &&
              FGR_PATH_ODD_RADIANCE_PLANE == FGR_PATH_ALPHA_PLANE + 1 &&
              FGR_PATH_SAMPLE_LIMIT_PLANE == FGR_PATH_ODD_RADIANCE_PLANE + 3 &&
              FGR_PATH_SAMPLE_LIMIT_PLANE + 1 == FGR_COMMON_PLANES + FGR_PATH_AUXILIARY_PLANES &&
              FGR_PATH_LANE_STEPS_PLANE == FGR_PATH_SAMPLE_LIMIT_PLANE + 1 &&
              FGR_PATH_PACKET_STEPS_PLANE + 1 == FGR_PATH_LANE_STEPS_PLANE + FGR_PATH_STATS_PLANES);
static_assert(FGR_BRUTE_ALBEDO_PLANE == FGR_COMMON_PLANES &&
              FGR_BRUTE_STATS_PLANE == FGR_COMMON_PLANES + FGR_BRUTE_SURFACE_PLANES);
static_assert(FGR_LIGHT_INTENSITY < FGR_LIGHT_FLOATS &&
              FGR_PATH_LIGHT_COS_MAX < FGR_PATH_LIGHT_FLOATS);
static_assert(FGR_PREPASS_EVALUATIONS_PLANE < FGR_PREPASS_PLANES &&
              FGR_PROBE_POINT_REST_PLANE + 3 == FGR_PROBE_POINT_PLANES);

}  // namespace fgr::layout
