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
inline float julia_set_radius(float c_length) {
    return 0.5f * (1.0f + sqrt(1.0f + 4.0f * c_length));
}

/* The orbit's estimate 0.5 r log(r) / dr is G / (2 |G'|) for the potential G = log(r) / 2^n.
 * Near the set (G -> 0) it is the distance; far out it grows like r log r, faster than the
 * distance. Koebe's bound for Julia sets, sinh(G) / (2 e^G |G'|), is the same near the set and
 * saturates far out: it is the estimate times (1 - e^(-2G)) / (2G). */
inline real potential_bound(real r, real dr, real potential_scale) {
    real log_r = log(r);
    real potential = log_r * potential_scale;
    real estimate = 0.5f * r * log_r / dr;
    real koebe_factor = (1.0f - exp(-2.0f * potential)) / (2.0f * potential);
    /* Inside (r < 1) and at G -> 0 the factor is 1; r = 0 or dr = 0 only occur inside. */
    real bound = select(estimate, estimate * koebe_factor, potential > 1e-4f);
    return select(bound, fgr_real(0.0f), r <= 0.0f | dr <= 0.0f);
}

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
    real potential_scale = fgr_real(1.0f); /* 2^-n after n iterations */
    for (int i = 0; i < param_iterations; ++i) {
        mask active = r <= bailout;
        if (!fgr_any(active)) break;
        quaternion_packet next = quaternion_square(q);
        dr = select(dr, 2.0f * r * dr, active);
        potential_scale = select(potential_scale, 0.5f * potential_scale, active);
        q.x = select(q.x, next.x + c_x, active);
        q.y = select(q.y, next.y + c_y, active);
        q.z = select(q.z, next.z + c_z, active);
        q.w = select(q.w, next.w + c_w, active);
        r = quaternion_length(q);
        if (record) *trap = trap_update(*trap, v3(q.x, q.y, q.z), active);
    }
    /* Far from the set the bounding ball is the better bound; both never overestimate. */
    float c_length = sqrt(c_x * c_x + c_y * c_y + c_z * c_z + c_w * c_w);
    real ball_bound = v3_length(p) - julia_set_radius(c_length);
    return fmax(potential_bound(r, dr, potential_scale), ball_bound);
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(julia_iterate)
