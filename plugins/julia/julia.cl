/* Quaternion Julia set: the iteration q -> q^2 + c on quaternions q = x + y i + z j + w k, seen as
 * the 3D slice w = slice_w of the 4D set.
 *
 * Distance estimate: DE = 0.5 |q| log|q| / |q'| with the running derivative q' -> 2 q q'. The
 * quaternion norm is multiplicative, so |q'| -> 2 |q| |q'| exactly and one scalar stands in for the
 * whole derivative. */

typedef struct quaternion_packet {
    real x, y, z, w; /* x is the real part */
} quaternion_packet;

/* q^2 = (x^2 - y^2 - z^2 - w^2, 2xy, 2xz, 2xw): a square needs no general product. */
inline quaternion_packet quaternion_square(quaternion_packet q) {
    quaternion_packet s;
    s.x = q.x * q.x - q.y * q.y - q.z * q.z - q.w * q.w;
    s.y = 2.0f * q.x * q.y;
    s.z = 2.0f * q.x * q.z;
    s.w = 2.0f * q.x * q.w;
    return s;
}

inline real quaternion_length(quaternion_packet q) {
    return sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
}

/* Every orbit leaving the ball of radius R = (1 + sqrt(1 + 4|c|)) / 2 escapes: beyond it
 * |q^2 + c| >= |q|^2 - |c| > |q| and the gap only grows. So the whole set lies inside it. */
inline float julia_set_radius(float c_length) { return 0.5f * (1.0f + sqrt(1.0f + 4.0f * c_length)); }

/* Iterates q -> q^2 + c from q = (p, slice_w); returns the DE and, when `record` is set, fills
 * *trap with the orbit's x, y, z. */
inline real julia_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float c_x = param_c_x, c_y = param_c_y, c_z = param_c_z, c_w = param_c_w;
    const float bailout = param_bailout;
    quaternion_packet q;
    q.x = p.x;
    q.y = p.y;
    q.z = p.z;
    q.w = fgr_real(param_slice_w);
    real r = quaternion_length(q);
    real dr = fgr_real(1.0f);
    for (int i = 0; i < param_iterations; ++i) {
        mask active = r <= bailout;
        if (!fgr_any(active)) break;
        quaternion_packet next = quaternion_square(q);
        dr = select(dr, 2.0f * r * dr, active);
        q.x = select(q.x, next.x + c_x, active);
        q.y = select(q.y, next.y + c_y, active);
        q.z = select(q.z, next.z + c_z, active);
        q.w = select(q.w, next.w + c_w, active);
        r = quaternion_length(q);
        if (record) *trap = trap_update(*trap, v3(q.x, q.y, q.z), active);
    }
    /* An orbit through 0 has dr = 0 and r log r = 0: guard both (such lanes are inside). */
    real orbit_bound = select(0.5f * r * log(r) / dr, fgr_real(0.0f), r <= 0.0f | dr <= 0.0f);
    /* Far from the set one or two iterations escape and r log r / dr grows faster than the
     * distance; the set's bounding ball is exact there and never overestimates. */
    float c_length = sqrt(c_x * c_x + c_y * c_y + c_z * c_z + c_w * c_w);
    real ball_bound = v3_length(p) - julia_set_radius(c_length);
    return fmax(orbit_bound, ball_bound);
}

real scene_de(vec3 p, PARAMS) {
    orbit_trap unused;
    return julia_iterate(p, PARAMS_PASS, 0, &unused);
}

#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    orbit_trap trap = trap_init();
    julia_iterate(p, PARAMS_PASS, 1, &trap);
    return trap_colour(trap, param_colour_mode, param_palette, param_base_colour);
}
