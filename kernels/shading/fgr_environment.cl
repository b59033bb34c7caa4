// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: environment lighting, lookup and importance sampling.
 *
 * An environment is an equirectangular map (host/render/environment.hpp builds its tables)
 * seen at infinity. Directions are z-up, as fgr's worlds are. Texel (column i, row j) of a
 * width x height map covers polar angles theta (from +z) in [j, j + 1] pi / height (row 0 looks
 * straight up) and azimuths phi in [i, i + 1] 2 pi / width, the direction of (theta, phi) being
 *     (-sin theta cos phi, sin theta sin phi, cos theta):
 * phi = 0 looks along -x (the seam), 90 degrees along +y, 180 along +x (the map's centre). The
 * rotation turns the map about +z: what the map shows at phi is seen at phi + rotation.
 *
 * Radiance is nearest-texel, and sampling is piecewise constant over the same texels: a row by
 * the rows' alias table, a column by that row's alias table (constant time, one lane at a time),
 * then a point uniform in solid angle inside the texel (cos theta uniform across the row's band).
 * The pdf per solid angle is therefore constant in each texel: P(texel) / solid_angle(texel),
 * P being stored beside the texel's colour.
 *
 * Kernel arguments: ENVIRONMENT in a parameter list, ENVIRONMENT_PASS in a call:
 *     env_data  the tables' flat buffer (shared/fgr_layout_environment.h)
 *     env       environment_info by value (shared/fgr_layout_environment.h) */

#define ENVIRONMENT __global const float *env_data, environment_info env
#define ENVIRONMENT_PASS env_data, env

/* One lane's scalar, and the lanes through private arrays (the gathers go lane by lane). */
#define ENV_SCALAR FGR_LANES(float, double)
#if FGR_WIDTH == 1
#define env_to_lanes(array) ((array)[0])
#define env_from_lanes(value, array) ((array)[0] = (value))
#else
#define env_to_lanes(array) FGR_PASTE(vload, FGR_WIDTH)(0, (array))
#define env_from_lanes(value, array) FGR_PASTE(vstore, FGR_WIDTH)((value), 0, (array))
#endif

#define ENV_PI FGR_LANES(3.14159265358979323846f, 3.14159265358979323846)
/* The largest value below 1, where a sample u must stay. */
#define ENV_ONE_BELOW FGR_LANES(0x1.fffffep-1f, 0x1.fffffffffffffp-1)

/* One draw from the alias table of `n` entries at `table` with u in [0, 1): the entry u * n picks,
 * kept when the fraction of u * n falls below its threshold, else its alias; *fraction gets that
 * fraction stretched back over [0, 1) (uniform inside the chosen cell, so it places the point
 * inside the texel). */
inline int env_alias_pick(__global const float* table, int n, ENV_SCALAR u, ENV_SCALAR* fraction) {
    const ENV_SCALAR x = u * (ENV_SCALAR)n;
    const int k = min((int)x, n - 1);
    const ENV_SCALAR f = fmin(x - (ENV_SCALAR)k, (ENV_SCALAR)ENV_ONE_BELOW);
    __global const float* entry = table + FGR_ENV_ALIAS_FLOATS * k;
    const ENV_SCALAR threshold = entry[FGR_ENV_ALIAS_THRESHOLD];
    if (f < threshold) {
        *fraction = fmin(f / threshold, (ENV_SCALAR)ENV_ONE_BELOW);
        return k;
    }
    *fraction = fmin((f - threshold) / ((ENV_SCALAR)1 - threshold), (ENV_SCALAR)ENV_ONE_BELOW);
    return ((__global const int*)entry)[FGR_ENV_ALIAS_INDEX];
}

/* A continuous coordinate as a cell index in [0, count - 1]; NaN (inactive lanes) gives 0. */
inline int env_cell(ENV_SCALAR x, int count) {
    if (!(x >= 0)) return 0;
    if (x >= (ENV_SCALAR)(count - 1)) return count - 1;
    return (int)x;
}

/* Solid angle of a texel of rows `row` (lanes, as reals): (2 pi / width) * 2 sin(theta_mid)
 * sin(half_height), the difference of the band's cosines without cancellation. */
inline real env_texel_solid_angle(real row, environment_info env) {
    const real band = ENV_PI / (float)env.height;
    return (4.0f * ENV_PI / (float)env.width) * fgr_sin((row + 0.5f) * band) * fgr_sin(0.5f * band);
}

/* For each lane's direction: the texel it falls in (row and column as reals) and that texel's
 * probability. Rotation applied; intensity not. */
inline void env_locate(vec3 dir, environment_info env, real* row, real* column) {
    const real horizontal = sqrt(dir.x * dir.x + dir.y * dir.y);
    const real theta = atan2(horizontal, dir.z);
    const real phi_turns = atan2(dir.y, -dir.x) * (0.5f / ENV_PI) - env.transform.x;
    const real u = phi_turns - floor(phi_turns);
    *row = theta * ((float)env.height / ENV_PI);
    *column = u * (float)env.width;
}

/* Gathers each lane's texel colour and probability at the continuous (row, column) given; lanes
 * outside `wanted` skip the loads and get black of probability 1. */
inline void env_gather(__global const float* env_data, environment_info env, real row_f,
                       real column_f, mask wanted, vec3* colour, real* probability, real* row_out) {
    ENV_SCALAR rows[FGR_WIDTH], columns[FGR_WIDTH], gathered[FGR_WIDTH];
    ENV_SCALAR r[FGR_WIDTH], g[FGR_WIDTH], b[FGR_WIDTH], p[FGR_WIDTH], row_index[FGR_WIDTH];
    env_from_lanes(row_f, rows);
    env_from_lanes(column_f, columns);
    env_from_lanes(select(fgr_real(0.0f), fgr_real(1.0f), wanted), gathered);
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        if (gathered[lane] == 0) {
            r[lane] = g[lane] = b[lane] = row_index[lane] = 0;
            p[lane] = 1;
            continue;
        }
        const int row = env_cell(rows[lane], env.height);
        const int column = env_cell(columns[lane], env.width);
        __global const float* texel = env_data + FGR_ENV_TEXEL_FLOATS * (row * env.width + column);
        r[lane] = texel[0];
        g[lane] = texel[1];
        b[lane] = texel[2];
        p[lane] = texel[FGR_ENV_TEXEL_PROBABILITY];
        row_index[lane] = (ENV_SCALAR)row;
    }
    *colour = v3(env_to_lanes(r), env_to_lanes(g), env_to_lanes(b));
    *probability = env_to_lanes(p);
    *row_out = env_to_lanes(row_index);
}

/* Radiance arriving from unit direction `dir` (from the environment towards the scene, i.e. seen
 * looking along dir): the texel dir falls in, times the intensity (black outside `wanted`). */
inline vec3 environment_radiance(vec3 dir, mask wanted, ENVIRONMENT) {
    real row_f, column_f, probability, row;
    vec3 colour;
    env_locate(dir, env, &row_f, &column_f);
    env_gather(env_data, env, row_f, column_f, wanted, &colour, &probability, &row);
    return v3_scale(colour, fgr_real(env.transform.y));
}

/* environment_radiance and environment_pdf from one lookup. */
inline vec3 environment_radiance_pdf(vec3 dir, mask wanted, ENVIRONMENT, real* pdf) {
    real row_f, column_f, probability, row;
    vec3 colour;
    env_locate(dir, env, &row_f, &column_f);
    env_gather(env_data, env, row_f, column_f, wanted, &colour, &probability, &row);
    *pdf = probability / env_texel_solid_angle(row, env);
    return v3_scale(colour, fgr_real(env.transform.y));
}

/* Solid-angle density with which environment_sample picks direction `dir`. */
inline real environment_pdf(vec3 dir, mask wanted, ENVIRONMENT) {
    real row_f, column_f, probability, row;
    vec3 colour;
    env_locate(dir, env, &row_f, &column_f);
    env_gather(env_data, env, row_f, column_f, wanted, &colour, &probability, &row);
    return probability / env_texel_solid_angle(row, env);
}

/* A unit direction drawn by importance from (u1, u2) in [0, 1)^2 (u2 picks the row, u1 the
 * column; what is left of each places the point inside the texel), its solid-angle pdf in *pdf
 * (> 0 for every direction it returns) and the environment's radiance along it in *radiance (as
 * environment_radiance gives it, from the same texel). Lanes outside `wanted` skip the tables and
 * get the first texel's top edge, probability 1 and black. */
inline vec3 environment_sample_radiance(real u1, real u2, mask wanted, ENVIRONMENT, real* pdf,
                                        vec3* radiance) {
    ENV_SCALAR su1[FGR_WIDTH], su2[FGR_WIDTH];
    ENV_SCALAR rows[FGR_WIDTH], columns[FGR_WIDTH], fraction_v[FGR_WIDTH], fraction_u[FGR_WIDTH],
        p[FGR_WIDTH], r[FGR_WIDTH], g[FGR_WIDTH], b[FGR_WIDTH];
    /* NaN lanes become 0 through fmax; u = 1 would leave the table's last entry. */
    env_from_lanes(fmin(fmax(u1, fgr_real(0.0f)), fgr_real(ENV_ONE_BELOW)), su1);
    env_from_lanes(fmin(fmax(u2, fgr_real(0.0f)), fgr_real(ENV_ONE_BELOW)), su2);
    ENV_SCALAR searched[FGR_WIDTH];
    env_from_lanes(select(fgr_real(0.0f), fgr_real(1.0f), wanted), searched);
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        if (searched[lane] == 0) {
            rows[lane] = columns[lane] = fraction_v[lane] = fraction_u[lane] = 0;
            r[lane] = g[lane] = b[lane] = 0;
            p[lane] = 1;
            continue;
        }
        const ENV_SCALAR v = su2[lane] >= 0 ? su2[lane] : (ENV_SCALAR)0; /* NaN-safe */
        const ENV_SCALAR u = su1[lane] >= 0 ? su1[lane] : (ENV_SCALAR)0;
        ENV_SCALAR fv, fu;
        const int row = env_alias_pick(env_data + env.rows_offset, env.height, v, &fv);
        const int column =
            env_alias_pick(env_data + env.columns_offset + FGR_ENV_ALIAS_FLOATS * row * env.width,
                           env.width, u, &fu);
        __global const float* texel = env_data + FGR_ENV_TEXEL_FLOATS * (row * env.width + column);
        rows[lane] = (ENV_SCALAR)row;
        columns[lane] = (ENV_SCALAR)column;
        fraction_v[lane] = fv;
        fraction_u[lane] = fu;
        r[lane] = texel[0];
        g[lane] = texel[1];
        b[lane] = texel[2];
        p[lane] = texel[FGR_ENV_TEXEL_PROBABILITY];
    }
    const real row = env_to_lanes(rows);
    const real band = ENV_PI / (float)env.height;
    /* cos theta uniform across the band: from the top edge down by fraction_v of its width. */
    const real half_band = 0.5f * band;
    const real mid = (row + 0.5f) * band;
    const real cos_top = fgr_cos(row * band);
    const real band_width = 2.0f * fgr_sin(mid) * fgr_sin(half_band);
    const real z = clamp(cos_top - env_to_lanes(fraction_v) * band_width, -1.0f, 1.0f);
    const real sin_theta = sqrt(fmax(1.0f - z * z, fgr_real(0.0f)));
    const real phi =
        2.0f * ENV_PI *
        ((env_to_lanes(columns) + env_to_lanes(fraction_u)) / (float)env.width + env.transform.x);
    *pdf = env_to_lanes(p) / env_texel_solid_angle(row, env);
    *radiance =
        v3_scale(v3(env_to_lanes(r), env_to_lanes(g), env_to_lanes(b)), fgr_real(env.transform.y));
    return v3(-sin_theta * fgr_cos(phi), sin_theta * fgr_sin(phi), z);
}

/* environment_sample_radiance without the radiance. */
inline vec3 environment_sample(real u1, real u2, mask wanted, ENVIRONMENT, real* pdf) {
    vec3 radiance;
    return environment_sample_radiance(u1, u2, wanted, ENVIRONMENT_PASS, pdf, &radiance);
}
