// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: vec3 arithmetic on packets. OpenCL C has no operator overloading, so these
 * short functions stand in for +, -, * on vectors. Masks: combine with & and |, negate with !
 * (both keep true lanes at -1 for vectors and 1 for scalars, which select() and fgr_any expect). */

inline vec3 v3(real x, real y, real z) {
    vec3 r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}

/* The same point or direction in every lane. */
inline vec3 v3_splat(float x, float y, float z) {
    return v3(fgr_real(x), fgr_real(y), fgr_real(z));
}

#if FGR_KERNEL_API >= 4
/* A uniform 3-vector (a vec3 or colour parameter, a float3 constant) in every lane: what the vec3
 * helpers take, e.g. v3_add(z, v3_uniform(param_offset)). */
inline vec3 v3_uniform(float3 u) { return v3_splat(u.x, u.y, u.z); }
#define fgr_param_lanes(param) v3_uniform(param)
#else
#define fgr_param_lanes(param) (param)
#endif
/* fgr_param_lanes(param_X): a vec3 parameter as a vec3, whichever kernel API the scene reads it
 * with; the library's own reads of its built-in colours (fog, glow, base colour) go through it. */

inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
inline vec3 v3_mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
inline vec3 v3_scale(vec3 a, real s) { return v3(a.x * s, a.y * s, a.z * s); }
/* a + b * s, the ray-point form. */
inline vec3 v3_mad(vec3 a, vec3 b, real s) {
    return v3(mad(b.x, s, a.x), mad(b.y, s, a.y), mad(b.z, s, a.z));
}
inline vec3 v3_neg(vec3 a) { return v3(-a.x, -a.y, -a.z); }
inline vec3 v3_abs(vec3 a) { return v3(fabs(a.x), fabs(a.y), fabs(a.z)); }
inline vec3 v3_min(vec3 a, vec3 b) { return v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
inline vec3 v3_max(vec3 a, vec3 b) { return v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }

inline real v3_dot(vec3 a, vec3 b) { return mad(a.x, b.x, mad(a.y, b.y, a.z * b.z)); }
inline real v3_length2(vec3 a) { return v3_dot(a, a); }
inline real v3_length(vec3 a) { return sqrt(v3_dot(a, a)); }

inline vec3 v3_cross(vec3 a, vec3 b) {
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* Unit vector; a zero vector stays zero instead of becoming NaN. */
inline vec3 v3_normalize(vec3 a) {
    real len2 = v3_dot(a, a);
    real inv = select(rsqrt(len2), fgr_real(0.0f), len2 <= 0.0f);
    return v3_scale(a, inv);
}

/* Lane-wise choice: b where m holds, a elsewhere (like select()). */
inline vec3 v3_select(vec3 a, vec3 b, mask m) {
    return v3(select(a.x, b.x, m), select(a.y, b.y, m), select(a.z, b.z, m));
}
