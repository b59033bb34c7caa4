// SPDX-License-Identifier: Apache-2.0
/* Stereographic quaternion Julia set: every point p of R^3 is lifted onto the unit 3-sphere of
 * the quaternions by the inverse stereographic projection, and belongs to the set when the
 * quaternion Julia iteration q -> q^2 + c started there stays bounded.
 *
 * Source: Mikael Hvidtfeldt Christensen (Syntopia), "Stereographic Quaternion Julias" (2011, his
 * blog hvidtfeldts.net, after an idea of Daniel Piker), rendered as in his "Rendering 3D fractals
 * without a distance estimator": by brute force, from an inside test alone. The quaternion Julia
 * DE bounds the 4D distance to the whole Julia set, not to its slice by the curved 3-sphere:
 * where the sphere runs close along the set without entering it, that bound is near 0 far from
 * any point of the 3D set, and a march would crawl. So the scene is inside-only.
 *
 * The lift, with P = scale * p and the pole on the real axis:
 *
 *     q0 = ((1 - |P|^2) + 2 P.x i + 2 P.y j + 2 P.z k) / (1 + |P|^2)
 *
 * so p = 0 lifts to q = 1, p -> infinity to q = -1 and the unit sphere |P| = 1 to the purely
 * imaginary unit quaternions. Then q0 is turned by `tilt` in the (real, k) plane, which moves the
 * pole off the real axis. Untilted, the 3D set is a solid of revolution about the axis Im(c)
 * (a quaternion Julia set is symmetric under the rotations of i, j, k that fix Im(c), and these
 * are rotations of p); tilted, those circles become the circles of a Moebius flow, and the solids
 * of revolution become shell- and conch-like spirals.
 *
 * The set is invariant under p -> -p / |P|^2 (the antipodal map q -> -q of the 3-sphere: both
 * square to the same quaternion), so each part inside the sphere |P| = 1 has an inverted twin
 * outside it. p = 0 and p -> infinity share one orbit; with the default c it escapes, so the set
 * is bounded and hollow at the origin.
 *
 * Inside: |q|^2 <= bailout^2 for all `iterations` steps. Every orbit leaving the ball of radius
 * R = (1 + sqrt(1 + 4|c|)) / 2 escapes (|q^2 + c| >= |q|^2 - |c| > |q| beyond it), so with
 * bailout >= R (|c| <= 2 gives R <= 2; the bailout's minimum is 2) no orbit called escaped would
 * have stayed bounded. A larger bailout still fattens the set at a finite iteration count (orbits
 * on their way out count as inside for a few steps longer). Orbits stop at the bailout, so |q|^2
 * never exceeds (bailout^2 + |c|)^2 ~ 1.7e7: no overflow in float. */

#define FGR_SCENE_INSIDE_ONLY

typedef struct stereo_quaternion {
    real x, y, z, w; /* x + y i + z j + w k */
} stereo_quaternion;

inline real stereo_norm2(stereo_quaternion q) {
    return q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
}

/* The inverse stereographic projection of scale * p onto the unit 3-sphere, tilted. Coordinates
 * are clamped to +-1e18 first so |P|^2 stays finite in float (at that size q is -1 to the last
 * bit anyway); without it p = 1e20 would give Inf / Inf. */
inline stereo_quaternion stereo_lift(vec3 p, PARAMS) {
    const real limit = fgr_real(1e18f);
    const float scale = param_scale;
    const real px = fmin(fmax(p.x * scale, -limit), limit);
    const real py = fmin(fmax(p.y * scale, -limit), limit);
    const real pz = fmin(fmax(p.z * scale, -limit), limit);
    const real inverse = 1.0f / (1.0f + px * px + py * py + pz * pz);
    /* (1 - r^2) / (1 + r^2) = 2 / (1 + r^2) - 1: no cancellation for large r */
    const real real_part = 2.0f * inverse - 1.0f;
    const real k_part = 2.0f * pz * inverse;
    const float tilt = radians(param_tilt);
    const float cos_tilt = cos(tilt), sin_tilt = sin(tilt);
    stereo_quaternion q;
    q.x = cos_tilt * real_part + sin_tilt * k_part;
    q.y = 2.0f * px * inverse;
    q.z = 2.0f * py * inverse;
    q.w = cos_tilt * k_part - sin_tilt * real_part;
    return q;
}

/* Runs q -> q^2 + c from the lifted p for `iterations` steps; returns the lanes whose orbit
 * stayed within the bailout, and records the orbit in *trap when `record` is set. */
inline mask stereo_julia_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float c_x = param_c_x, c_y = param_c_y, c_z = param_c_z, c_w = param_c_w;
    const float bailout2 = param_bailout * param_bailout;
    stereo_quaternion q = stereo_lift(p, PARAMS_PASS);
    mask inside = stereo_norm2(q) <= bailout2;
    for (int i = 0; i < param_iterations; ++i) {
        if (!fgr_any(inside)) break;
        /* q^2 = (x^2 - y^2 - z^2 - w^2, 2xy, 2xz, 2xw) */
        const real x = q.x * q.x - q.y * q.y - q.z * q.z - q.w * q.w + c_x;
        const real y = 2.0f * q.x * q.y + c_y;
        const real z = 2.0f * q.x * q.z + c_z;
        const real w = 2.0f * q.x * q.w + c_w;
        q.x = select(q.x, x, inside);
        q.y = select(q.y, y, inside);
        q.z = select(q.z, z, inside);
        q.w = select(q.w, w, inside);
        if (record) *trap = trap_update(*trap, v3(q.x, q.y, q.z), inside);
        inside = inside & (stereo_norm2(q) <= bailout2);
    }
    return inside;
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_INSIDE_SCENE(stereo_julia_iterate)
