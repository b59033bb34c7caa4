// SPDX-License-Identifier: Apache-2.0
/* fgr render mode "brute": rendering without a distance estimator, after Syntopia's "Rendering 3D
 * fractals without a distance estimator". Only the scene's inside test is used (a DE scene's is
 * its DE's sign against the hit threshold, see fgr_geometry.cl), so this mode renders sets no DE
 * is known for.
 *
 * Two kernels (planes, FGR_BRUTE_*_PLANE in shared/fgr_layout_planes.h: colour, depth, then the
 * albedo and normal the shading used, then with FGR_STATS each pixel's inside tests):
 *   fgr_render       one pass of sampling along each pixel's ray. The pass draws
 *                    brute_samples stratified samples between brute_near and the pixel's best
 *                    depth so far (max_distance before the first hit), stops at the first sample
 *                    in the solid, and refines the crossing by brute_bisection bisection steps
 *                    between it and the last sample before it. The best depth lives in `state`
 *                    from pass to pass and can only come closer.
 *   fgr_brute_shade  screen-space shading of the depth buffer once the passes are done: normals
 *                    from neighbouring pixels' world positions, Blinn-Phong with the scene's
 *                    lights, screen-space ambient occlusion, shadows sampled towards the lights
 *                    with the same inside test, outer glow for misses, fog.
 *
 * What counts as solid (brute_solid): "auto" is whatever state the ray does not start in, so a
 * camera inside the set sees the walls of its cavities; "set" and "complement" fix it (a camera
 * inside the solid then sees the cut at brute_near: cross-sections; "complement" renders the
 * set's interior as the seed's reversed inside() does). Pixels are sampled at their centres:
 * depth is a minimum over passes, and jittering rays would dilate silhouettes.
 *
 * Arguments of both (FGR_BRUTE_ARG_*, FGR_BRUTE_SHADE_ARG_*, shared/fgr_layout_arguments.h):
 * those every mode takes (planes .. has_hints, see fgr_camera.cl), then `state` (each pixel's
 * best depth, tile-major like the planes; -1: none yet); fgr_brute_shade then takes the scene's
 * lights (FGR_LIGHT_FLOATS floats each, shared/fgr_layout_lights.h) and their count. */

#define FGR_BRUTE_SOLID_AUTO 0
#define FGR_BRUTE_SOLID_SET 1
#define FGR_BRUTE_SOLID_COMPLEMENT 2

/* An int per lane, for pixel coordinates and plane indices, whatever the lanes' precision. */
typedef FGR_LANE_TYPE(int) index_lanes;
#define convert_index_lanes FGR_LANE_TYPE(convert_int)
/* Truth of int lanes as the lanes' mask (long lanes with FGR_DOUBLE). */
#define index_truth FGR_LANE_TYPE(FGR_LANES(convert_int, convert_long))

/* plane[index] for each lane's own index. */
#if FGR_WIDTH == 1
#define fgr_gather(plane, i) convert_real((plane)[i])
#elif FGR_WIDTH == 4
#define fgr_gather(plane, i) \
    convert_real((float4)((plane)[(i).s0], (plane)[(i).s1], (plane)[(i).s2], (plane)[(i).s3]))
#elif FGR_WIDTH == 8
#define fgr_gather(plane, i)                                                                  \
    convert_real((float8)((plane)[(i).s0], (plane)[(i).s1], (plane)[(i).s2], (plane)[(i).s3], \
                          (plane)[(i).s4], (plane)[(i).s5], (plane)[(i).s6], (plane)[(i).s7]))
#elif FGR_WIDTH == 16
#define fgr_gather(plane, i)                                                                   \
    convert_real((float16)((plane)[(i).s0], (plane)[(i).s1], (plane)[(i).s2], (plane)[(i).s3], \
                           (plane)[(i).s4], (plane)[(i).s5], (plane)[(i).s6], (plane)[(i).s7], \
                           (plane)[(i).s8], (plane)[(i).s9], (plane)[(i).sa], (plane)[(i).sb], \
                           (plane)[(i).sc], (plane)[(i).sd], (plane)[(i).se], (plane)[(i).sf]))
#endif

/* The unit direction through the centre of pixel (px, py). */
inline vec3 brute_pixel_direction(camera_frame camera, real px, real py) {
    camera_sample centre;
    centre.pixel_x = centre.pixel_y = fgr_real(0.5f);
    centre.lens_x = centre.lens_y = fgr_real(0.0f);
    return v3_normalize(primary_direction(camera, px, py, centre));
}

/* The inside test at distance t from the eye along dir (fgr_geometry.cl's surface_inside; a DE
 * scene's surface is where its DE falls below the hit threshold's footprint there, the surface
 * the shaded mode's sphere tracer stops at). */
inline mask brute_inside(vec3 eye, vec3 dir, real t, float footprint, PARAMS) {
    return surface_inside(v3_mad(eye, dir, t), footprint * t, PARAMS_PASS);
}

/* The footprint per unit distance that a DE scene's surface is taken at. */
inline float brute_footprint(camera_frame camera, PARAMS) {
    return param_hit_threshold * camera.pixel_angle;
}

/* Which state is solid for rays from eye along dir: see brute_solid above. */
inline mask brute_target(vec3 eye, vec3 dir, float footprint, PARAMS) {
    if (param_brute_solid == FGR_BRUTE_SOLID_SET) return (mask)(FGR_TRUE);
    if (param_brute_solid == FGR_BRUTE_SOLID_COMPLEMENT) return (mask)(0);
    return !brute_inside(eye, dir, fgr_real(param_brute_near), footprint, PARAMS_PASS);
}

/* A uniform number in [0, 1) for stratum `index` of pass `pass` of pixel (px, py): the same in
 * every packet width. A pass draws many numbers a pixel, one a stratum, so the stratum goes into
 * the seed beside the pass (fgr_sampler.cl's hashed numbers). */
inline real brute_random(real px, real py, int pass, int index) {
    const uint_lanes seed =
        sampler_pixel_seed(px, py, pass) ^ (uint_lanes)((uint)(index + 1) * 2654435761u);
    return sampler_hashed_unit(sampler_mix(sampler_mix(seed)));
}

/* One pass of sampling for the lanes of `active`: the new best depth (unchanged where nothing
 * closer was found). `tests` counts each lane's inside tests. */
inline real brute_pass(vec3 eye, vec3 dir, float footprint, real best, mask active, real px,
                       real py, int pass, mask* tests, PARAMS) {
    const float near = param_brute_near;
    const mask target = brute_target(eye, dir, footprint, PARAMS_PASS);
    fgr_count_if(*tests, active);
    /* A ray starting in the solid sees the cut at near. */
    const mask cut =
        active & (brute_inside(eye, dir, fgr_real(near), footprint, PARAMS_PASS) == target);
    const real end = select(fgr_real(param_max_distance), best, best >= 0.0f);
    active &= !cut & (end > near);

    const int count = max(param_brute_samples, 1);
    const real stratum = (end - near) / (float)count;
    real clear = fgr_real(near); /* the last sample outside the solid */
    real solid_at = end;         /* the first sample in it */
    mask found = (mask)(0);
    for (int i = 0; i < count; ++i) {
        if (!fgr_any(active)) break;
        const real t = near + ((float)i + brute_random(px, py, pass, i)) * stratum;
        const mask solid = active & (brute_inside(eye, dir, t, footprint, PARAMS_PASS) == target);
        fgr_count_if(*tests, active);
        solid_at = select(solid_at, t, solid);
        clear = select(clear, t, active & !solid);
        found |= solid;
        active &= !solid;
    }
    /* Each bisection step halves the bracket [clear, solid_at] around a crossing; the depth kept
     * is its solid end, so it stays on the surface's solid side and below the old best. */
    for (int k = 0; k < param_brute_bisection; ++k) {
        if (!fgr_any(found)) break;
        const real middle = 0.5f * (clear + solid_at);
        const mask solid = brute_inside(eye, dir, middle, footprint, PARAMS_PASS) == target;
        fgr_count_if(*tests, found);
        solid_at = select(solid_at, middle, found & solid);
        clear = select(clear, middle, found & !solid);
    }
    best = select(best, solid_at, found);
    return select(best, fgr_real(near), cut);
}

/* Renders pass `sample` of every pixel of the tile: refines `state` and writes the depth so far
 * to FGR_DEPTH_PLANE (and with FGR_STATS, the pass's inside tests, summed over passes, to
 * FGR_BRUTE_STATS_PLANE). The colour planes are left to fgr_brute_shade. */
__kernel void fgr_render(FGR_RENDER_ARGS, __global float* state) {
    const int tile = get_global_id(0);
    if (tile >= tile_count) return;
    const tile_pixels pixels = pixels_of_tile(tile, camera);
    const vec3 eye = camera_origin(camera, pixels.px, pixels.py);
    const vec3 dir = brute_pixel_direction(camera, pixels.px, pixels.py);
    const real previous = sample == 0 ? fgr_real(-1.0f) : fgr_load(tile, state);
    mask tests = (mask)(0);
    const real best = brute_pass(eye, dir, brute_footprint(camera, PARAMS_PASS), previous,
                                 pixels.inside, pixels.px, pixels.py, sample, &tests, PARAMS_PASS);
    fgr_store(best, tile, state);
    fgr_store(best, tile, planes + FGR_DEPTH_PLANE * plane_size);
#ifdef FGR_STATS
    accumulate_plane(convert_real(tests), sample, tile,
                     planes + FGR_BRUTE_STATS_PLANE * plane_size);
#endif
}

/* --- Screen-space shading -------------------------------------------------------------------- */

/* Where the solid side of the crossing is taken for a discontinuity: neighbours whose depth
 * differs by more than this fraction of the pixel's own are another surface (a silhouette or a
 * step), not a continuation of this one. At 640 pixels across a 45 degree view this only rejects
 * surfaces seen within about 1.5 degrees of grazing. */
#define FGR_BRUTE_DISCONTINUITY 0.05f
/* Samples of the screen-space occlusion's disc, and the glow's. */
#define FGR_SSAO_SAMPLES 16
/* Ambient light: higher than the shaded mode's, since occlusion here darkens everything. */
#define FGR_BRUTE_AMBIENT 0.12f

/* The depth of pixel (x, y) in `state`, -1 off the region, in another view than pixel
 * (from_x, from_y) (a stereo pair's other eye), or where the ray has no hit. Off the image that
 * is the truth; off a tiled render's region but on the image it is not, which is why tiles are
 * rendered with FGR_BRUTE_MAX_REACH pixels of padding and cropped. */
inline real brute_depth_at(__global const float* state, index_lanes x, index_lanes y,
                           index_lanes from_x, index_lanes from_y, camera_frame camera) {
    const index_lanes lx = x - camera.region_x, ly = y - camera.region_y;
    const index_lanes on_region =
        (lx >= 0) & (lx < camera.region_width) & (ly >= 0) & (ly < camera.region_height);
    const index_lanes cx = clamp(lx, 0, camera.region_width - 1);
    const index_lanes cy = clamp(ly, 0, camera.region_height - 1);
    const index_lanes index =
        ((cy / FGR_TILE_H) * region_tiles_x(camera) + cx / FGR_TILE_W) * FGR_WIDTH +
        (cy % FGR_TILE_H) * FGR_TILE_W + cx % FGR_TILE_W;
    const mask same_view = camera_same_view(camera, convert_real(x), convert_real(y),
                                            convert_real(from_x), convert_real(from_y));
    return select(fgr_real(-1.0f), fgr_gather(state, index), index_truth(on_region) & same_view);
}

inline vec3 brute_world_point(camera_frame camera, vec3 eye, index_lanes x, index_lanes y,
                              real depth) {
    return v3_mad(eye, brute_pixel_direction(camera, convert_real(x), convert_real(y)), depth);
}

/* The surface's tangent along pixel step (dx, dy) at `centre`: the central difference where both
 * neighbours continue the surface (second-order accurate), otherwise towards whichever neighbour
 * continues it best (the smaller depth jump), so a pixel at a silhouette takes its tangent from
 * the side it belongs to. *valid is false where neither neighbour does. */
inline vec3 brute_tangent(__global const float* state, camera_frame camera, vec3 eye, index_lanes x,
                          index_lanes y, real depth, vec3 centre, int dx, int dy, mask* valid) {
    const real before = brute_depth_at(state, x - dx, y - dy, x, y, camera);
    const real after = brute_depth_at(state, x + dx, y + dy, x, y, camera);
    const mask has_before = before >= 0.0f, has_after = after >= 0.0f;
    const real jump_before = fabs(depth - before), jump_after = fabs(after - depth);
    const mask use_after = has_after & (!has_before | (jump_after <= jump_before));
    const real jump = select(jump_before, jump_after, use_after);
    const real limit = FGR_BRUTE_DISCONTINUITY * depth;
    *valid = (has_before | has_after) & (jump <= limit);
    const mask central = has_before & has_after & (jump_before <= limit) & (jump_after <= limit);
    const vec3 after_point = brute_world_point(camera, eye, x + dx, y + dy, after);
    const vec3 before_point = brute_world_point(camera, eye, x - dx, y - dy, before);
    const vec3 one_sided =
        v3_select(v3_sub(centre, before_point), v3_sub(after_point, centre), use_after);
    return v3_select(one_sided, v3_sub(after_point, before_point), central);
}

/* The surface normal at pixel (x, y), facing the camera, from its neighbours' world positions;
 * where a tangent has no continuing neighbour (isolated pixels, needles) the normal faces the
 * camera. */
inline vec3 brute_normal(__global const float* state, camera_frame camera, vec3 eye, vec3 dir,
                         index_lanes x, index_lanes y, real depth, vec3 centre) {
    mask valid_x, valid_y;
    const vec3 along_x = brute_tangent(state, camera, eye, x, y, depth, centre, 1, 0, &valid_x);
    const vec3 along_y = brute_tangent(state, camera, eye, x, y, depth, centre, 0, 1, &valid_y);
    vec3 n = v3_normalize(v3_cross(along_x, along_y));
    n = v3_select(n, v3_neg(n), v3_dot(n, dir) > 0.0f);
    const mask usable = valid_x & valid_y & (v3_length2(n) > 0.5f);
    return v3_select(v3_neg(dir), n, usable);
}

/* A disc of FGR_SSAO_SAMPLES points of radius `radius` pixels (Vogel's spiral, turned by a
 * per-pixel angle so the pattern's structure becomes fine noise): the pixel offset of point k. */
inline void brute_disc_point(int k, real radius, real spin, real* ox, real* oy) {
    const float fraction = sqrt(((float)k + 0.5f) / (float)FGR_SSAO_SAMPLES);
    const real angle = spin + (float)k * 2.39996323f; /* the golden angle */
    *ox = radius * fraction * fgr_cos(angle);
    *oy = radius * fraction * fgr_sin(angle);
}

inline real brute_spin(real px, real py) { return 6.28318531f * brute_random(px, py, -1, 0); }

/* Screen-space ambient occlusion with its radius in world units (ao_radius): each disc sample's
 * world point occludes by how far it rises above the tangent plane (the cosine of its direction
 * with the normal, less a small bias against a curved surface occluding itself), weighted by
 * radius / d (at most 4) and fading as 1 - (d / radius)^2 to nothing at the radius. An open face
 * gives 1, a crease or a pit less. */
inline real brute_occlusion(__global const float* state, camera_frame camera, vec3 eye,
                            index_lanes x, index_lanes y, real px, real py, real depth, vec3 centre,
                            vec3 n, mask hit, PARAMS) {
    const float radius = param_ao_radius;
    const real pixels = clamp(radius / (depth * camera.pixel_angle), 1.0f,
                              fmin(0.25f * (float)camera.width, (float)FGR_BRUTE_MAX_REACH));
    const real spin = brute_spin(px, py);
    real occluded = fgr_real(0.0f);
    for (int k = 0; k < FGR_SSAO_SAMPLES; ++k) {
        real ox, oy;
        brute_disc_point(k, pixels, spin, &ox, &oy);
        const index_lanes sx = x + convert_index_lanes(rint(ox));
        const index_lanes sy = y + convert_index_lanes(rint(oy));
        const real sample_depth = brute_depth_at(state, sx, sy, x, y, camera);
        const vec3 v = v3_sub(brute_world_point(camera, eye, sx, sy, sample_depth), centre);
        const real distance = v3_length(v);
        const real rise = v3_dot(n, v) / fmax(distance, FGR_MIN_LENGTH) - 0.1f;
        /* As in McGuire et al.'s Alchemy AO, nearer occluders weigh more (up to 4 times). */
        const real reach = clamp(distance / radius, 0.0f, 1.0f);
        const real nearness = fmin(radius / fmax(distance, FGR_MIN_LENGTH), 4.0f);
        occluded += select(fgr_real(0.0f), fmax(rise, 0.0f) * nearness * (1.0f - reach * reach),
                           hit & (sample_depth >= 0.0f));
    }
    return clamp(1.0f - occluded / (float)FGR_SSAO_SAMPLES, 0.0f, 1.0f);
}

#if defined(FGR_EFFECT_SHADOWS) || defined(FGR_EFFECT_SOFT_SHADOWS)
/* 1 where the light is visible from the surface seen at `depth` along dir, 0 where a sample
 * towards it lies in the solid: brute_samples * 2 stratified samples between a few footprints off
 * the surface and `reach`, spaced quadratically (densest near the surface, where occluders cast
 * the sharpest shadows). */
inline real brute_visibility(vec3 eye, vec3 dir, real depth, vec3 to_light, real reach, mask lit,
                             mask target, real px, real py, int light, camera_frame camera,
                             PARAMS) {
    const real pixel = depth * camera.pixel_angle;
    const vec3 start = v3_mad(eye, dir, depth - 2.0f * pixel); /* back out of the solid */
    const real first = 4.0f * pixel;
    const float footprint = brute_footprint(camera, PARAMS_PASS);
    const int count = 2 * max(param_brute_samples, 1);
    mask open = lit;
    mask blocked = (mask)(0);
    for (int i = 0; i < count; ++i) {
        if (!fgr_any(open)) break;
        const real f = ((float)i + brute_random(px, py, -2 - light, i)) / (float)count;
        const real t = first + (reach - first) * f * f;
        /* A DE scene's surface as seen from the camera: its footprint grows with the whole
         * way the light travels from the eye. */
        const mask solid = open & (surface_inside(v3_mad(start, to_light, t),
                                                  footprint * (depth + t), PARAMS_PASS) == target);
        blocked |= solid;
        open &= !solid;
    }
    return select(fgr_real(1.0f), fgr_real(0.0f), blocked);
}
#endif

/* Blinn-Phong with the scene's lights (as the shaded mode lights), times occlusion. */
inline vec3 brute_lighting(vec3 eye, vec3 dir, real depth, vec3 p, vec3 n, vec3 albedo, real ao,
                           mask hit, real px, real py, camera_frame camera,
                           __constant const float* lights, int light_count, PARAMS) {
    vec3 colour = v3_scale(albedo, fgr_real(FGR_BRUTE_AMBIENT));
    const vec3 to_eye = v3_neg(dir);
#if defined(FGR_EFFECT_SHADOWS) || defined(FGR_EFFECT_SOFT_SHADOWS)
    const mask target = brute_target(eye, dir, brute_footprint(camera, PARAMS_PASS), PARAMS_PASS);
#else
    (void)eye;
    (void)depth;
    (void)px;
    (void)py;
    (void)camera;
    (void)hit;
#endif
    for (int i = 0; i < light_count; ++i) {
        __constant const float* light = lights + i * FGR_LIGHT_FLOATS;
        real falloff, reach;
        const vec3 l = light_direction(light, p, param_max_distance, &falloff, &reach);
        const real diffuse = fmax(v3_dot(n, l), 0.0f);
        const vec3 half_vector = v3_normalize(v3_add(l, to_eye));
        const real specular =
            FGR_SPECULAR * fgr_pown(fmax(v3_dot(n, half_vector), 0.0f), FGR_SHININESS);
        real strength = light[FGR_LIGHT_INTENSITY] * falloff *
                        select(fgr_real(0.0f), fgr_real(1.0f), diffuse > 0.0f);
#if defined(FGR_EFFECT_SHADOWS) || defined(FGR_EFFECT_SOFT_SHADOWS)
        strength *= brute_visibility(eye, dir, depth, l, reach, hit & (diffuse > 0.0f), target, px,
                                     py, i, camera, PARAMS_PASS);
#endif
        const vec3 light_colour = light_vec3(light, FGR_LIGHT_COLOUR);
        const vec3 lit = v3(albedo.x * diffuse + specular, albedo.y * diffuse + specular,
                            albedo.z * diffuse + specular);
        colour = v3_add(colour, v3_scale(v3_mul(lit, light_colour), strength));
    }
    return v3_scale(colour, ao);
}

#ifdef FGR_EFFECT_GLOW
/* The seed's outer glow: a pixel that missed lightens by the share of its neighbours (within
 * 1/48 of the image's width) that hit, times glow_strength, in glow_colour. */
inline vec3 brute_glow(vec3 colour, __global const float* state, camera_frame camera, index_lanes x,
                       index_lanes y, real px, real py, mask missed, PARAMS) {
    if (!fgr_any(missed)) return colour;
    const real pixels =
        fgr_real(fmin(fmax(3.0f, (float)camera.width / 48.0f), (float)FGR_BRUTE_MAX_REACH));
    const real spin = brute_spin(px, py);
    real near_hits = fgr_real(0.0f);
    for (int k = 0; k < FGR_SSAO_SAMPLES; ++k) {
        real ox, oy;
        brute_disc_point(k, pixels, spin, &ox, &oy);
        const real d = brute_depth_at(state, x + convert_index_lanes(rint(ox)),
                                      y + convert_index_lanes(rint(oy)), x, y, camera);
        near_hits += select(fgr_real(0.0f), fgr_real(1.0f), d >= 0.0f);
    }
    const real amount =
        select(fgr_real(0.0f), param_glow_strength * near_hits / (float)FGR_SSAO_SAMPLES, missed);
    return v3_add(colour, v3_scale(fgr_param_lanes(param_glow_colour), amount));
}
#endif

/* Shades every pixel of the tile from the depth buffer `state` once the passes are done: writes
 * the colour and depth planes (depth -1 where nothing was hit), and the shading's albedo and
 * normal. */
__kernel void fgr_brute_shade(FGR_RENDER_ARGS, __global const float* state,
                              __constant const float* lights, int light_count) {
    (void)sample;
    const int tile = get_global_id(0);
    if (tile >= tile_count) return;
    const tile_pixels pixels = pixels_of_tile(tile, camera);
    const real px = pixels.px, py = pixels.py;
    const index_lanes x = convert_index_lanes(px), y = convert_index_lanes(py);
    const vec3 eye = camera_origin(camera, px, py); /* neighbours in its view share it */
    const vec3 dir = brute_pixel_direction(camera, px, py);
    const real depth = fgr_load(tile, state);
    const mask hit = pixels.inside & (depth >= 0.0f);

    vec3 colour = background(dir);
    vec3 albedo = v3_splat(0.0f, 0.0f, 0.0f), normal = albedo;
    if (fgr_any(hit)) {
        const real safe_depth = select(fgr_real(1.0f), depth, hit);
        const vec3 p = v3_mad(eye, dir, safe_depth);
        const vec3 n = brute_normal(state, camera, eye, dir, x, y, safe_depth, p);
        real ao = fgr_real(1.0f);
#if defined(FGR_EFFECT_AMBIENT_OCCLUSION) || defined(FGR_EFFECT_SAMPLED_OCCLUSION)
        ao = brute_occlusion(state, camera, eye, x, y, px, py, safe_depth, p, n, hit, PARAMS_PASS);
#endif
        const vec3 surface_albedo = scene_colour(p, PARAMS_PASS);
        const vec3 lit = brute_lighting(eye, dir, safe_depth, p, n, surface_albedo, ao, hit, px, py,
                                        camera, lights, light_count, PARAMS_PASS);
        colour = v3_select(colour, lit, hit);
        albedo = v3_select(albedo, surface_albedo, hit);
        normal = v3_select(normal, n, hit);
    }
#ifdef FGR_EFFECT_GLOW
    colour = brute_glow(colour, state, camera, x, y, px, py, pixels.inside & !hit, PARAMS_PASS);
#endif
#ifdef FGR_EFFECT_FOG
    colour = apply_fog(colour, depth, hit, param_max_distance, PARAMS_PASS);
#endif
    /* Pixels the projection does not cover (outside a fisheye's circle) are black. */
    colour = v3_select(v3_splat(0.0f, 0.0f, 0.0f), colour, pixels.inside);
    fgr_store(colour.x, tile, planes + FGR_COLOUR_PLANE * plane_size);
    fgr_store(colour.y, tile, planes + (FGR_COLOUR_PLANE + 1) * plane_size);
    fgr_store(colour.z, tile, planes + (FGR_COLOUR_PLANE + 2) * plane_size);
    fgr_store(select(fgr_real(-1.0f), depth, hit), tile, planes + FGR_DEPTH_PLANE * plane_size);
    fgr_store(albedo.x, tile, planes + FGR_BRUTE_ALBEDO_PLANE * plane_size);
    fgr_store(albedo.y, tile, planes + (FGR_BRUTE_ALBEDO_PLANE + 1) * plane_size);
    fgr_store(albedo.z, tile, planes + (FGR_BRUTE_ALBEDO_PLANE + 2) * plane_size);
    fgr_store(normal.x, tile, planes + FGR_BRUTE_NORMAL_PLANE * plane_size);
    fgr_store(normal.y, tile, planes + (FGR_BRUTE_NORMAL_PLANE + 1) * plane_size);
    fgr_store(normal.z, tile, planes + (FGR_BRUTE_NORMAL_PLANE + 2) * plane_size);
}
