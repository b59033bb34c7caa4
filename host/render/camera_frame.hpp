#pragma once
// The camera as the kernels receive it (`camera_frame` in kernels/fgr_camera.cl): shared by the
// renderer and the cone prepass, which both launch kernels that take it.

#include <CL/opencl.hpp>

#include "camera/camera.hpp"
#include "camera/projection.hpp"
#include "render/renderer.hpp"

namespace fgr {

// Mirrors `camera_frame` in kernels/fgr_camera.cl (float4 members keep both layouts equal).
struct CameraFrame {
    cl_float4 eye;      // xyz: float(eye), w: x of float(eye - xyz)
    cl_float4 forward;  // w: y of float(eye - eye.xyz)
    cl_float4 right;    // w: z of float(eye - eye.xyz)
    cl_float4 up;
    cl_float tan_half_fov;
    cl_float pixel_angle;
    cl_int width;
    cl_int height;
    cl_int projection;  // ProjectionKind
    cl_float fisheye_half_fov;
    cl_float eye_separation;
    cl_float convergence;
    cl_int region_x;
    cl_int region_y;
    cl_int region_width;
    cl_int region_height;
};
static_assert(sizeof(CameraFrame) == 112, "must match camera_frame in fgr_camera.cl");

// The eye goes as a hi/lo split of its double value: hi the nearest float, lo the rest rounded to
// float (in the w components); double lanes add them, float lanes use hi alone.
CameraFrame camera_frame(const CameraView& view, const Projection& projection, int width,
                         int height, PixelRegion region);

}  // namespace fgr
