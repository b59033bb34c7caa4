// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: signed distance functions on packets, after Inigo Quilez's catalogue
 * (https://iquilezles.org/articles/distfunctions/), written for fgr's types and z-up world.
 *
 * Names say the role: sd_* primitives, op_* combinators and transforms. Primitives are centred at
 * the origin and take the point first. Every function says whether its result is
 *   exact  the true signed distance (given exact inputs), or
 *   bound  never more than the true distance in magnitude, and 1-Lipschitz, so sphere tracing
 *          with it never steps through the surface.
 * Scalar shape parameters are uniform `float`s; vector ones are `vec3`: v3_splat(x, y, z) for a
 * constant, v3_uniform(param_<id>) for a vec3 parameter (kernel API 4 reads one as a float3; API 2
 * and 3 as a vec3, which passes straight in).
 *
 * Nothing here divides by zero or takes sqrt of a negative: degenerate shapes (radius 0, a == b
 * capsules, period 0) and the origin give finite results in every lane.
 *
 * Transforms move the point, not the shape: to place a shape, evaluate it at the transformed
 * point, e.g. sd_sphere(op_translate(p, centre), r). Isometries (translate, rotate, repeat)
 * keep exact distances exact; the others say what the caller must do to keep a bound. */

#define FGR_SQRT3 1.73205081f
#define FGR_INV_SQRT3 0.57735027f

/* Length of the 2D vector (x, y) per lane (plain sqrt: the inputs here never overflow). */
inline real sdf_hypot(real x, real y) { return sqrt(mad(x, x, y * y)); }

/* ---------------------------------------------------------------------------------------------
 * Primitives
 */

/* Sphere of `radius`. Exact. */
inline real sd_sphere(vec3 p, float radius) { return v3_length(p) - radius; }

/* Axis-aligned box with half extents `half_size` (components >= 0). Exact. */
inline real sd_box(vec3 p, vec3 half_size) {
    vec3 q = v3_sub(v3_abs(p), half_size);
    real outside = v3_length(v3_max(q, v3_splat(0.0f, 0.0f, 0.0f)));
    real inside = fmin(fmax(q.x, fmax(q.y, q.z)), 0.0f);
    return outside + inside;
}

/* Box with half extents `half_size` whose edges are rounded by `radius`, which must not exceed
 * the smallest half extent (the rounding eats into the box, it does not grow it). Exact. */
inline real sd_round_box(vec3 p, vec3 half_size, float radius) {
    vec3 core = v3_sub(half_size, v3_splat(radius, radius, radius));
    return sd_box(p, core) - radius;
}

/* Torus whose ring of radius `major` lies in the xy-plane around the z axis, tube radius
 * `minor`. Exact. */
inline real sd_torus(vec3 p, float major, float minor) {
    return sdf_hypot(sdf_hypot(p.x, p.y) - major, p.z) - minor;
}

/* Half-space below the plane {x : dot(n, x) = height}, n a unit normal pointing out of the solid
 * (n = (0, 0, 1), height 0 is the ground z <= 0). Exact. */
inline real sd_plane(vec3 p, vec3 n, float height) { return v3_dot(p, n) - height; }

/* Cylinder along z, capped at z = +-half_height. Exact. */
inline real sd_cylinder(vec3 p, float radius, float half_height) {
    real radial = sdf_hypot(p.x, p.y) - radius;
    real axial = fabs(p.z) - half_height;
    real outside = sdf_hypot(fmax(radial, 0.0f), fmax(axial, 0.0f));
    return outside + fmin(fmax(radial, axial), 0.0f);
}

/* Capsule: the points within `radius` of the segment a-b. a == b gives a sphere. Exact. */
inline real sd_capsule(vec3 p, vec3 a, vec3 b, float radius) {
    vec3 pa = v3_sub(p, a);
    vec3 ba = v3_sub(b, a);
    /* The fmax keeps a degenerate segment finite: dot(pa, ba) is 0 there too, so t = 0. */
    real t = clamp(v3_dot(pa, ba) / fmax(v3_length2(ba), 1e-30f), 0.0f, 1.0f);
    return v3_length(v3_mad(pa, ba, -t)) - radius;
}

/* Capped cone (a frustum) along z: radius `bottom_radius` at z = -half_height, `top_radius` at
 * z = +half_height. Either radius may be 0 (a pointed cone); equal radii give a cylinder. Exact.
 * Works in the half-plane (rho, z), rho the distance from the z axis: the nearest boundary point
 * is on a cap or on the slanted side segment from (top_radius, h) to (bottom_radius, -h). */
inline real sd_cone(vec3 p, float half_height, float bottom_radius, float top_radius) {
    real rho = sdf_hypot(p.x, p.y);
    /* Nearest cap: the top one above z = 0. Beyond its rim the offset is horizontal too. */
    real cap_radius = select(fgr_real(top_radius), fgr_real(bottom_radius), p.z < 0.0f);
    real cap_dx = rho - fmin(rho, cap_radius);
    real cap_dz = fabs(p.z) - half_height;
    /* Side segment: top rim + t * (down the side), t in [0, 1]. */
    const float side_x = top_radius - bottom_radius, side_z = 2.0f * half_height;
    const float side_len2 = fmax(side_x * side_x + side_z * side_z, 1e-30f);
    real t =
        clamp(((top_radius - rho) * side_x + (half_height - p.z) * side_z) / side_len2, 0.0f, 1.0f);
    real side_dx = rho - top_radius + side_x * t;
    real side_dz = p.z - half_height + side_z * t;
    /* Inside: left of the side segment and between the caps. */
    mask inside = (side_dx < 0.0f) & (cap_dz < 0.0f);
    real dist2 =
        fmin(mad(cap_dx, cap_dx, cap_dz * cap_dz), mad(side_dx, side_dx, side_dz * side_dz));
    real dist = sqrt(dist2);
    return select(dist, -dist, inside);
}

/* Regular octahedron |x| + |y| + |z| <= size (vertices at distance `size` on the axes). Exact:
 * inside, the nearest face plane; outside, the nearest point of the nearest face triangle, found
 * in the positive octant after sorting out which vertex region p is in. */
inline real sd_octahedron(vec3 p, float size) {
    vec3 a = v3_abs(p);
    real m = a.x + a.y + a.z - size;
    /* Rotate coordinates so q.x is the axis whose vertex region p is beyond (if any). */
    mask beyond_x = 3.0f * a.x < m;
    mask beyond_y = !beyond_x & (3.0f * a.y < m);
    mask beyond_z = !beyond_x & !beyond_y & (3.0f * a.z < m);
    vec3 q = v3_select(a, v3(a.y, a.z, a.x), beyond_y);
    q = v3_select(q, v3(a.z, a.x, a.y), beyond_z);
    real k = clamp(0.5f * (q.z - q.y + size), 0.0f, size);
    real edge_dist = v3_length(v3(q.x, q.y - size + k, q.z - k));
    return select(m * FGR_INV_SQRT3, edge_dist, beyond_x | beyond_y | beyond_z);
}

/* Regular tetrahedron with vertices (s, s, s), (s, -s, -s), (-s, s, -s), (-s, -s, s), s = size.
 * Bound: the largest signed distance to its four face planes, exact inside and over the faces but
 * up to a factor 3 short towards a vertex, where the distance to the circumsphere (radius
 * sqrt(3) s) is the better bound; both are bounds, so their maximum is. */
inline real sd_tetrahedron(vec3 p, float size) {
    /* The faces' outward normals are (-1,-1,-1), (-1,1,1), (1,-1,1), (1,1,-1) over sqrt(3); the
     * largest of the four dot products pairs up as |x + y| - z and |x - y| + z. */
    real planes = fmax(fabs(p.x + p.y) - p.z, fabs(p.x - p.y) + p.z);
    real to_planes = (planes - size) * FGR_INV_SQRT3;
    return fmax(to_planes, v3_length(p) - FGR_SQRT3 * size);
}

/* ---------------------------------------------------------------------------------------------
 * Combinators. Inputs are distances of two shapes; the result's quality is at best the inputs'.
 */

/* Both shapes. Exact outside when both inputs are; a bound inside. */
inline real op_union(real d1, real d2) { return fmin(d1, d2); }

/* (Kernel API 3.) The union of the nearest distance so far, d, with an object whose DE `object`
 * is costly: exactly fmin(d, object), but `object` is not evaluated at all when no lane can need
 * it, that is when every lane's `lower` lies beyond d. `lower` must never exceed the object's DE
 * value: the distance to a sphere or box containing the object, less whatever the object's DE may
 * fall below the true distance (a smooth union's k/4, say), and a little for rounding (1e-5 in a
 * scene of size 1). A ray near one object then pays for that object alone: a scene of several
 * (the benchmark) or a fractal on a floor marches as fast as its nearest object. A macro, so
 * `object` is evaluated only when used; d is read twice, so pass a variable. */
#if FGR_KERNEL_API >= 3
#define op_union_culled(d, lower, object) (fgr_all((lower) > (d)) ? (d) : fmin((d), (object)))
#endif

/* Shape 1 with shape 2 carved out of it. Bound. (Note the order: IQ's opSubtraction takes the
 * carved shape first; here the kept shape comes first, as in "d1 minus d2".) */
inline real op_subtraction(real d1, real d2) { return fmax(d1, -d2); }

/* Where both shapes overlap. Bound. */
inline real op_intersection(real d1, real d2) { return fmax(d1, d2); }

/* Blend weight of the polynomial smooth minimum; k is kept away from 0 so a zero blend radius
 * degrades to the sharp operation instead of 0 / 0. */
inline real op_smooth_weight(real difference, float k) {
    return clamp(0.5f + 0.5f * difference / fmax(k, 1e-6f), 0.0f, 1.0f);
}

/* Union blended over a fillet of width about k (k = 0: op_union). Bound: its gradient is a convex
 * combination of the inputs' gradients, so it stays 1-Lipschitz. */
inline real op_smooth_union(real d1, real d2, float k) {
    real h = op_smooth_weight(d2 - d1, k);
    return mix(d2, d1, h) - k * h * (1.0f - h);
}

/* Shape 1 minus shape 2, with the cut's edge rounded over about k. Bound. */
inline real op_smooth_subtraction(real d1, real d2, float k) {
    real h = op_smooth_weight(-d1 - d2, k);
    return mix(d1, -d2, h) + k * h * (1.0f - h);
}

/* Intersection with its crease rounded over about k. Bound. */
inline real op_smooth_intersection(real d1, real d2, float k) {
    real h = op_smooth_weight(d1 - d2, k);
    return mix(d2, d1, h) + k * h * (1.0f - h);
}

/* ---------------------------------------------------------------------------------------------
 * Transforms. Each returns the point at which to evaluate the untransformed shape.
 */

#if FGR_KERNEL_API >= 2
/* A rotation by `degrees` about `axis` (Rodrigues' matrix), built once outside a loop so the loop
 * does a matrix multiply instead of trigonometry. The axis is a vec3: from a vec3 parameter
 * `rotation_about_axis(v3_uniform(param_axis), param_angle)` (API 2 and 3: `param_axis` itself),
 * or v3_splat(x, y, z) for a fixed one; it need not be unit length (a zero axis gives the
 * identity). */
typedef struct rotation3 {
    real xx, xy, xz, yx, yy, yz, zx, zy, zz; /* rows x, y, z */
} rotation3;

inline rotation3 rotation_about_axis(vec3 axis, float degrees) {
    const real length = v3_length(axis);
    const real inverse = select(1.0f / length, fgr_real(0.0f), length <= 0.0f);
    const vec3 u = v3_scale(axis, inverse);
    float c = 1.0f;
    const float s = sincos(radians(degrees), &c);
    /* A zero axis has u = 0: every term below but c vanishes, and c must become 1 there. */
    const real t = 1.0f - c, k = select(fgr_real(c), fgr_real(1.0f), length <= 0.0f);
    rotation3 m;
    m.xx = t * u.x * u.x + k, m.xy = t * u.x * u.y - s * u.z, m.xz = t * u.x * u.z + s * u.y;
    m.yx = t * u.x * u.y + s * u.z, m.yy = t * u.y * u.y + k, m.yz = t * u.y * u.z - s * u.x;
    m.zx = t * u.x * u.z - s * u.y, m.zy = t * u.y * u.z + s * u.x, m.zz = t * u.z * u.z + k;
    return m;
}

/* Applies rotation m to p. Isometry: exact stays exact. */
inline vec3 op_rotate(vec3 p, rotation3 m) {
    return v3(m.xx * p.x + m.xy * p.y + m.xz * p.z, m.yx * p.x + m.yy * p.y + m.yz * p.z,
              m.zx * p.x + m.zy * p.y + m.zz * p.z);
}

/* p turned by `degrees` about `axis` in one call: rotation_about_axis + op_rotate. It builds the
 * matrix (trigonometry, a normalisation) at every call: in a loop, build it once before the loop
 * with rotation_about_axis (in an orbit scene, between FGR_ORBIT and FGR_ITERATE). */
inline vec3 rotate_about(vec3 p, vec3 axis, float degrees) {
    return op_rotate(p, rotation_about_axis(axis, degrees));
}
#else
/* Kernel API 1: the axis as a float3 of unit length. */
typedef struct rotation3 {
    float3 row_x, row_y, row_z;
} rotation3;

inline rotation3 rotation_about_axis(float3 axis, float degrees) {
    float c = 1.0f;
    float s = sincos(radians(degrees), &c);
    float t = 1.0f - c;
    rotation3 m;
    m.row_x = (float3)(t * axis.x * axis.x + c, t * axis.x * axis.y - s * axis.z,
                       t * axis.x * axis.z + s * axis.y);
    m.row_y = (float3)(t * axis.x * axis.y + s * axis.z, t * axis.y * axis.y + c,
                       t * axis.y * axis.z - s * axis.x);
    m.row_z = (float3)(t * axis.x * axis.z - s * axis.y, t * axis.y * axis.z + s * axis.x,
                       t * axis.z * axis.z + c);
    return m;
}

inline vec3 op_rotate(vec3 p, rotation3 m) {
    return v3(m.row_x.x * p.x + m.row_x.y * p.y + m.row_x.z * p.z,
              m.row_y.x * p.x + m.row_y.y * p.y + m.row_y.z * p.z,
              m.row_z.x * p.x + m.row_z.y * p.y + m.row_z.z * p.z);
}
#endif

/* Moves a shape so its origin sits at `offset`. Isometry: exact stays exact. */
inline vec3 op_translate(vec3 p, vec3 offset) { return v3_sub(p, offset); }

/* Rotate a shape by `angle` radians about the x, y or z axis, counter-clockwise looking down the
 * axis towards the origin (right-handed). The point turns the other way. Isometries. */
inline vec3 op_rotate_x(vec3 p, float angle) {
    float c, s = sincos(angle, &c);
    return v3(p.x, c * p.y + s * p.z, c * p.z - s * p.y);
}
inline vec3 op_rotate_y(vec3 p, float angle) {
    float c, s = sincos(angle, &c);
    return v3(c * p.x - s * p.z, p.y, c * p.z + s * p.x);
}
inline vec3 op_rotate_z(vec3 p, float angle) {
    float c, s = sincos(angle, &c);
    return v3(c * p.x + s * p.y, c * p.y - s * p.x, p.z);
}

/* Uniform scaling by s > 0 is a pair, because distances scale too:
 *     op_scale_distance(sd(op_scale_point(p, s)), s)   ==   sd(p / s) * s
 * Exact stays exact. (Non-uniform scaling is not distance-preserving; use op_elongate.) */
inline vec3 op_scale_point(vec3 p, float s) { return v3_scale(p, fgr_real(1.0f / s)); }
inline real op_scale_distance(real d, float s) { return d * s; }

/* Stretches a shape by inserting a slab of width 2 * half_size[i] at its centre along each axis
 * (a sphere becomes a capsule or a rounded box). Evaluate sd(op_elongate(p, h)). Exact outside
 * for convex shapes; a bound inside (the stretched core reads as the shape's centre). */
inline vec3 op_elongate(vec3 p, vec3 half_size) {
    return v3_sub(p, v3_min(v3_max(p, v3_neg(half_size)), half_size));
}

/* The shape grown by `radius`, its edges rounded. Exact outside where d is exact. */
inline real op_round(real d, float radius) { return d - radius; }

/* A shell of half-thickness `thickness` around the surface (apply twice for nested shells). Exact
 * where d is exact. */
inline real op_onion(real d, float thickness) { return fabs(d) - thickness; }

/* Cell-local coordinate: p minus the nearest multiple of `period` on one axis; period <= 0 leaves
 * the axis unrepeated. `limit` caps the cell index to [-limit, limit]. */
inline real op_repeat_axis(real x, real period, real limit) {
    real cell = clamp(rint(x / period), -limit, limit);
    return select(x - period * cell, x, period <= 0.0f);
}

/* Infinite copies of a shape, one per cell of size `period` (per axis; 0 = not repeated). Evaluate
 * sd(op_repeat(p, period)). Only the copy in p's own cell is seen, so the result is exact for
 * shapes that are convex, mirror-symmetric in their cell's axes and inside the cell (spheres,
 * boxes, cylinders); for others keep the shape well inside the cell, or evaluate neighbours. */
inline vec3 op_repeat(vec3 p, vec3 period) {
    const float unlimited = 1e30f;
    return v3(op_repeat_axis(p.x, period.x, unlimited), op_repeat_axis(p.y, period.y, unlimited),
              op_repeat_axis(p.z, period.z, unlimited));
}

/* Copies at cells -limit .. limit per axis (limit 0: one copy on that axis), so 2 * limit + 1
 * copies along each. Same exactness as op_repeat; beyond the end cells the end copy is the
 * nearest one, so far points stay exact too. */
inline vec3 op_repeat_limited(vec3 p, vec3 period, vec3 limit) {
    return v3(op_repeat_axis(p.x, period.x, limit.x), op_repeat_axis(p.y, period.y, limit.y),
              op_repeat_axis(p.z, period.z, limit.z));
}

/* Twist about z: the shape's cross-section at height z turns by rate * z radians. Evaluate
 * sd(op_twist(p, rate)) and divide by op_twist_lipschitz(rate, reach) to keep a bound.
 * At distance rho from the axis the twist stretches space by (a + sqrt(a^2 + 4)) / 2 with
 * a = |rate| * rho (the largest singular value of its Jacobian), so the division is valid for
 * points within `reach` of the axis: clamp the rest in with op_clamp_to_cylinder. */
inline vec3 op_twist(vec3 p, float rate) {
    real angle = rate * p.z;
    real c = fgr_cos(angle), s = fgr_sin(angle);
    return v3(c * p.x + s * p.y, c * p.y - s * p.x, p.z);
}
inline float op_twist_lipschitz(float rate, float reach) {
    float a = fabs(rate) * reach;
    return 0.5f * (a + sqrt(a * a + 4.0f));
}

/* Bend: the x axis curls up (curvature > 0) or down (< 0) into a circular arc of radius
 * 1 / |curvature| through the origin, in the xz-plane; lines of constant z become arcs about the
 * bend's axis, the line x = 0, z = 1 / curvature. Evaluate sd(op_bend(p, curvature)) and divide by
 * op_bend_lipschitz(curvature, reach). Along the arcs space is stretched by 1 / (|curvature| r) at
 * distance r from the bend's axis; points no further than `reach` towards the axis
 * (sign(curvature) * z <= reach < 1 / |curvature|) have r >= 1 / |curvature| - reach, hence the
 * factor 1 / (1 - |curvature| * reach). Clamp the rest in with op_clamp_to_box. */
inline vec3 op_bend(vec3 p, float curvature) {
    if (fabs(curvature) < 1e-6f) return p; /* straight; also keeps 1 / curvature finite */
    const float sign = curvature < 0.0f ? -1.0f : 1.0f;
    const float bend_radius = 1.0f / fabs(curvature);
    real below_axis = bend_radius - sign * p.z; /* how far the bend's axis is above p */
    real angle = atan2(p.x, below_axis);
    real r = sdf_hypot(p.x, below_axis);
    return v3(angle * bend_radius, p.y, sign * (bend_radius - r));
}
inline float op_bend_lipschitz(float curvature, float reach) {
    return 1.0f / fmax(1.0f - fabs(curvature) * reach, 1e-3f);
}

/* Keeping a locally valid DE valid everywhere. Twist and bend (and any DE whose bound holds only
 * near the shape) are evaluated at q, p pulled into a convex region that contains the shape;
 * op_extend_from_clamp then adds the way back. Projection onto a convex set never lengthens
 * distances and leaves q on p's side of every shape point s: |p - s|^2 >= |p - q|^2 + |q - s|^2.
 * So sqrt(excess^2 + d(q)^2) is a bound, and 1-Lipschitz when d is 1-Lipschitz in the region.
 * Far points march in long strides too. Each clamp stores |p - q| in *excess. */
inline vec3 op_clamp_to_ball(vec3 p, float radius, real* excess) {
    real len = v3_length(p);
    *excess = fmax(len - radius, 0.0f);
    real pull = select(fgr_real(1.0f), radius / len, len > radius);
    return v3_scale(p, pull);
}
inline vec3 op_clamp_to_box(vec3 p, vec3 half_size, real* excess) {
    vec3 q = v3_min(v3_max(p, v3_neg(half_size)), half_size);
    *excess = v3_length(v3_sub(p, q));
    return q;
}
/* A cylinder along z: the disc and the height clamp independently (a product of convex sets). */
inline vec3 op_clamp_to_cylinder(vec3 p, float radius, float half_height, real* excess) {
    real rho = sdf_hypot(p.x, p.y);
    real pull = select(fgr_real(1.0f), radius / rho, rho > radius);
    real z = clamp(p.z, -half_height, half_height);
    *excess = sdf_hypot(fmax(rho - radius, 0.0f), p.z - z);
    return v3(p.x * pull, p.y * pull, z);
}
/* d: the shape's DE at the clamped point; the region must contain the shape. */
inline real op_extend_from_clamp(real d, real excess) {
    real extended = sdf_hypot(excess, fmax(d, 0.0f));
    return select(d, extended, excess > 0.0f);
}

/* Sine displacement of a surface: d + amplitude * sin(f x) sin(f y) sin(f z). The added term's
 * gradient is at most amplitude * frequency * sqrt(3) long, so the sum is divided by the
 * Lipschitz factor 1 + |amplitude * frequency| * sqrt(3): a bound again (if d was one), with the
 * displaced surface unchanged. */
inline real op_displace_sine(real d, vec3 p, float amplitude, float frequency) {
    real wave = fgr_sin(frequency * p.x) * fgr_sin(frequency * p.y) * fgr_sin(frequency * p.z);
    return (d + amplitude * wave) / (1.0f + fabs(amplitude * frequency) * FGR_SQRT3);
}
