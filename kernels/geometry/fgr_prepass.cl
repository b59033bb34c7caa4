// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: the cone-marched depth prepass.
 *
 * Every primary ray used to start its march at the eye and pay for the empty space its
 * neighbours had already crossed. The prepass marches one cone per block of
 * FGR_PREPASS_BLOCK x FGR_PREPASS_BLOCK pixels, a cone wide enough to hold every ray any sample
 * of those pixels can take, and stops where the cone comes near the surface; the render kernel
 * then starts all of the block's rays there (march_start_of).
 *
 * Why a start is safe. The cone's axis is the ray through the block's centre, direction d; a
 * pixel ray of the block leaves the same eye along d' with |d' - d| <= k (the chord to the
 * block's farthest corner, from corners and edge midpoints). At distance t' along it the ray is
 * within |t' - t| + t' k of the axis point at distance t. The axis march evaluates the DE at
 * t and advances by
 *
 *     step = (s DE - t (k + s f)) / (1 + k + s f),
 *
 * with s the scene's step factor (1 / the DE's Lipschitz bound: s DE is a distance the surface
 * is surely beyond) and f the hit footprint per unit distance. Then every pixel ray's points at
 * distances up to t + step are at least t' f from the surface: the plain march, which hits where
 * DE < t' f, would not have stopped there, and starting further on changes only where in the
 * last footprint its steps land. The cone gives up (the block starts where it got to) once its
 * step is no longer large against its own width, and starts at the eye at once where the DE at
 * the eye is 0 or less (a camera on or in the surface: the march's own escape rule decides) or
 * the block spans both eyes of a stereo pair. A block whose cone passes max_distance sends its
 * rays nowhere: they start past their reach and cost no step at all.
 *
 * The host skips the prepass where its rays do not share the cone's apex or its rule: depth of
 * field (rays leave the lens), glow (it needs the closest approach along the whole ray), IFS
 * scenes (traced exactly) and the brute-force mode (no DE). `cone_scale` scales k: 1 is the
 * safe cone; the tests narrow it on purpose to see that a cone too narrow for its block is
 * caught.
 *
 * The block's size, FGR_PREPASS_BLOCK pixels a side, the layout of the kernel's buffer (its
 * planes FGR_PREPASS_*_PLANE) and its arguments (FGR_PREPASS_ARG_*) are shared with the host
 * (shared/fgr_layout_planes.h, shared/fgr_layout_arguments.h). */

/* A cone stops once its step falls below this fraction of its own width at that distance (the
 * margin t (k + s f)): from there it would creep on in ever smaller steps. */
#define FGR_PREPASS_STOP 0.5f

/* Blocks lie on the whole image's grid, not the region's, so a pixel's block, and with it where
 * its rays start, is the same whether the image renders whole or in tiles (bit for bit). The
 * region's blocks start at block (prepass_first_block_x, prepass_first_block_y). */
inline int prepass_first_block_x(camera_frame camera) {
    return camera.region_x / FGR_PREPASS_BLOCK;
}

inline int prepass_first_block_y(camera_frame camera) {
    return camera.region_y / FGR_PREPASS_BLOCK;
}

inline int prepass_blocks_x(camera_frame camera) {
    return (camera.region_x + camera.region_width - 1) / FGR_PREPASS_BLOCK + 1 -
           prepass_first_block_x(camera);
}

inline int prepass_blocks_y(camera_frame camera) {
    return (camera.region_y + camera.region_height - 1) / FGR_PREPASS_BLOCK + 1 -
           prepass_first_block_y(camera);
}

/* Where the rays of pixels (px, py) start their march: the prepass's distance for each lane's
 * block (0 where there was no prepass: the host fills the buffer with zeros). Lanes past the
 * region's edge read its last block. */
inline real march_start_of(__global const float* starts, tile_pixels pixels, camera_frame camera) {
    const int blocks_x = prepass_blocks_x(camera), blocks_y = prepass_blocks_y(camera);
#if FGR_WIDTH == 1
    const int bx =
        min((int)pixels.px / FGR_PREPASS_BLOCK - prepass_first_block_x(camera), blocks_x - 1);
    const int by =
        min((int)pixels.py / FGR_PREPASS_BLOCK - prepass_first_block_y(camera), blocks_y - 1);
    return fgr_real(starts[by * blocks_x + bx]);
#else
    real start;
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        const int bx = min((int)pixels.px[lane] / FGR_PREPASS_BLOCK - prepass_first_block_x(camera),
                           blocks_x - 1);
        const int by = min((int)pixels.py[lane] / FGR_PREPASS_BLOCK - prepass_first_block_y(camera),
                           blocks_y - 1);
        start[lane] = starts[by * blocks_x + bx];
    }
    return start;
#endif
}

/* Where camera rays start given a reprojected hint (render/prepass/reprojection.hpp: the viewer's
 * previous frame's depths seen from the new view, less a margin; 0 for none): at the hint, for the
 * lanes whose hint lies past `start` and where the DE there is more than twice the hit footprint
 * (outside the surface, and not where the march would stop at once), at `start` elsewhere. A hint
 * is not proof that the way to it is clear, as the cone is: render/prepass/reprojection.hpp keeps
 * hints away from holes and depth edges, where a surface the previous frame did not see may come
 * into view, and the viewer uses them only for previews while the camera moves. Costs one DE
 * evaluation per packet with a hint, counted in *evaluations. */
inline real march_start_with_hint(real start, real hint, vec3 origin, vec3 dir, mask active,
                                  march_limits limits, mask* evaluations, PARAMS) {
    const mask hinted = active & (hint > start) & (hint < limits.max_distance);
    if (!fgr_any(hinted)) return start;
    const real dist = scene_de(v3_mad(origin, dir, hint), PARAMS_PASS);
    fgr_count_if(*evaluations, hinted);
    return select(start, hint, hinted & (dist > 2.0f * limits.footprint * hint));
}

/* Where the camera rays of tile `tile` start: their block's prepass distance, moved on by the
 * reprojected hints where the render has them (has_hints). The hint's DE evaluation is added to
 * *evaluations. Every DE mode's entry point starts its camera rays here. */
inline real camera_ray_start(__global const float* march_starts, __global const float* march_hints,
                             int has_hints, int tile, tile_pixels pixels, camera_frame camera,
                             vec3 origin, vec3 dir, mask active, march_limits limits,
                             mask* evaluations, PARAMS) {
    const real start = march_start_of(march_starts, pixels, camera);
    if (!has_hints) return start;
    return march_start_with_hint(start, fgr_load(tile, march_hints), origin, dir, active, limits,
                                 evaluations, PARAMS_PASS);
}

/* The unit direction through the point (pixel_x, pixel_y) in [0, 1]^2 of pixel (px, py): a
 * stereo pair's eye follows the pixel, as in primary_direction. */
inline vec3 prepass_direction(camera_frame camera, real px, real py, real pixel_x, real pixel_y) {
    camera_sample s;
    s.pixel_x = pixel_x;
    s.pixel_y = pixel_y;
    s.lens_x = s.lens_y = fgr_real(0.0f);
    return v3_normalize(primary_direction(camera, px, py, s));
}

#ifndef FGR_GEOMETRY_IFS
/* One cone per lane; the lanes of a packet are neighbouring blocks laid out like a tile's pixels.
 * Writes the start distance of each block to plane FGR_PREPASS_STARTS_PLANE of `starts`, and the
 * DE evaluations its cone took to plane FGR_PREPASS_EVALUATIONS_PLANE (block_plane floats each). */
__kernel void fgr_prepass(__global float* starts, int block_plane, int packet_count,
                          camera_frame camera, PARAMS, float cone_scale) {
    const int packet = get_global_id(0);
    if (packet >= packet_count) return;
    const int blocks_x = prepass_blocks_x(camera), blocks_y = prepass_blocks_y(camera);
    const int packets_x = (blocks_x + FGR_TILE_W - 1) / FGR_TILE_W;
    const real bx = (float)((packet % packets_x) * FGR_TILE_W) + FGR_LANE_X;
    const real by = (float)((packet / packets_x) * FGR_TILE_H) + FGR_LANE_Y;
    const mask valid = (bx < (float)blocks_x) & (by < (float)blocks_y);

    /* The block's corners, edge midpoints and centre, in image pixels. */
    const real x0 = (bx + (float)prepass_first_block_x(camera)) * FGR_PREPASS_BLOCK;
    const real y0 = (by + (float)prepass_first_block_y(camera)) * FGR_PREPASS_BLOCK;
    /* Point i of 0, 1, 2 across the block is x0 + i * mid: in pixel x0 + min(i * mid, B - 1),
     * at 0, 0 or 1 across it. */
    const float mid = 0.5f * FGR_PREPASS_BLOCK;
    const vec3 axis = prepass_direction(camera, x0 + mid, y0 + mid, fgr_real(0.0f), fgr_real(0.0f));
    real chord = fgr_real(0.0f);
    for (int j = 0; j <= 2; ++j) {
        const float into_y = fmin(mid * (float)j, FGR_PREPASS_BLOCK - 1.0f);
        for (int i = 0; i <= 2; ++i) {
            const float into_x = fmin(mid * (float)i, FGR_PREPASS_BLOCK - 1.0f);
            const vec3 d = prepass_direction(camera, x0 + into_x, y0 + into_y,
                                             fgr_real(mid * (float)i - into_x),
                                             fgr_real(mid * (float)j - into_y));
            chord = fmax(chord, v3_length(v3_sub(d, axis)));
        }
    }
    /* Panoramas bend their rays across a block: the nine directions bound it only up to terms
     * of second order, which this margin covers. */
    if (camera.projection == FGR_PROJECTION_EQUIRECTANGULAR ||
        camera.projection == FGR_PROJECTION_FISHEYE) {
        chord *= 1.25f;
    }
    const real k = chord * cone_scale;
    /* A stereo pair's block across the seam holds rays from both eyes: no shared apex. */
    const real last = fgr_real(FGR_PREPASS_BLOCK - 1.0f);
    const mask one_eye = camera_same_view(camera, x0, y0, x0 + last, y0 + last);
    const vec3 origin = camera_origin(camera, x0 + mid, y0 + mid);

    const march_limits limits = scene_march_limits(camera.pixel_angle, PARAMS_PASS);
    const real margin = k + limits.step_factor * limits.footprint; /* per unit distance */
    mask active = valid & one_eye;
    real t = fgr_real(0.0f);
    mask steps = (mask)(0);
    for (int step = 0; step < limits.max_steps; ++step) {
        if (!fgr_any(active)) break;
        const real dist = scene_de(v3_mad(origin, axis, t), PARAMS_PASS);
        fgr_count_if(steps, active);
        const real advance = (limits.step_factor * dist - t * margin) / (1.0f + margin);
        /* At the eye: a DE of 0 or less leaves the block to the march's escape rule. */
        active &= (step > 0) | (dist > 0.0f);
        const mask moves = active & (advance > FGR_PREPASS_STOP * t * margin) & (advance > 0.0f);
        t = select(t, t + advance, moves);
        active = moves & (t <= limits.max_distance);
    }
    /* Float storage must not round a start past what the cone cleared. */
    const real start = select(fgr_real(0.0f), t * (1.0f - 1e-6f), valid & one_eye);
    /* Lanes of blocks outside the image write nowhere. */
    const int first =
        (packet / packets_x) * FGR_TILE_H * blocks_x + (packet % packets_x) * FGR_TILE_W;
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        const int lx = lane % FGR_TILE_W, ly = lane / FGR_TILE_W;
        if ((packet % packets_x) * FGR_TILE_W + lx >= blocks_x) continue;
        if ((packet / packets_x) * FGR_TILE_H + ly >= blocks_y) continue;
        const int block = first + ly * blocks_x + lx;
#if FGR_WIDTH == 1
        starts[FGR_PREPASS_STARTS_PLANE * block_plane + block] = (float)start;
        starts[FGR_PREPASS_EVALUATIONS_PLANE * block_plane + block] = (float)steps;
#else
        starts[FGR_PREPASS_STARTS_PLANE * block_plane + block] = (float)start[lane];
        starts[FGR_PREPASS_EVALUATIONS_PLANE * block_plane + block] = (float)steps[lane];
#endif
    }
}
#endif
