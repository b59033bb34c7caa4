// SPDX-License-Identifier: Apache-2.0
/* fgr: the camera as the host sends it to every render mode and the prepass (see
 * fgr_layout_types.h for how this header is shared). fgr_camera.cl maps pixels to rays with it;
 * host/camera/projection.hpp describes each projection's layout, host/render/camera_frame.cpp
 * fills it. */
#ifndef FGR_LAYOUT_CAMERA_H
#define FGR_LAYOUT_CAMERA_H

#ifndef __OPENCL_C_VERSION__
#include "fgr_layout_types.h"
#endif

/* camera_frame.projection: pinhole, equirectangular (the whole sphere), equidistant fisheye, or
 * a stereo pair of off-axis pinholes side by side or top/bottom. */
#define FGR_PROJECTION_PINHOLE 0
#define FGR_PROJECTION_EQUIRECTANGULAR 1
#define FGR_PROJECTION_FISHEYE 2
#define FGR_PROJECTION_STEREO_SBS 3
#define FGR_PROJECTION_STEREO_TB 4

#ifdef __cplusplus
namespace fgr::layout {
#endif

/* The eye, then the orthonormal basis, each padded to a float4. The host keeps the eye in double
 * and sends it split, eye = hi + lo: hi (eye.xyz) is the nearest float, lo the float nearest the
 * rest, carried in the otherwise unused w components (eye.w, forward.w, right.w). Double lanes
 * see the eye to about 2^-48 of its size, so a deep zoom's eye can move by less than float's
 * step. */
typedef struct camera_frame {
    fgr_layout_float4 eye;     /* xyz: float(eye), w: x of float(eye - xyz) */
    fgr_layout_float4 forward; /* w: y of float(eye - eye.xyz) */
    fgr_layout_float4 right;   /* w: z of float(eye - eye.xyz) */
    fgr_layout_float4 up;
    fgr_layout_float tan_half_fov;
    fgr_layout_float pixel_angle; /* one pixel's angular footprint, as the projection gives it
                                   * (pixel_angle in host/camera/projection.cpp): pinhole
                                   * 2 tan_half_fov / width */
    fgr_layout_int width;         /* of the whole image: directions and footprints follow it */
    fgr_layout_int height;
    fgr_layout_int projection;         /* FGR_PROJECTION_* */
    fgr_layout_float fisheye_half_fov; /* radians from the axis at the image circle's rim */
    fgr_layout_float eye_separation;   /* stereo: world distance between the eyes */
    fgr_layout_float convergence;      /* stereo: distance of the zero-parallax plane */
    /* The rectangle of the image this launch renders (tiled stills render the image a region at
     * a time): tiles and planes cover the region, pixel coordinates stay the whole image's, so
     * every pixel gets exactly the ray, samples and random numbers of an untiled render. */
    fgr_layout_int region_x;
    fgr_layout_int region_y;
    fgr_layout_int region_width;
    fgr_layout_int region_height;
} camera_frame;

#ifdef __cplusplus
}  // namespace fgr::layout
#endif

#endif /* FGR_LAYOUT_CAMERA_H */
