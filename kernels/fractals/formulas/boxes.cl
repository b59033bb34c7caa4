// SPDX-License-Identifier: Apache-2.0
/* fgr formula library: boxes. Folds (isometries), a sphere fold that inverts (its scale goes
 * into dr) and a scale, plus c: the orbit grows linearly once it escapes, so the distance is
 * r / |dr| (Tom Lowe's Mandelbox, fractalforums.com, 2010; the estimate as Rrrola and Tglad gave
 * it there). */

/* |scale| <= 1 never escapes: magnitudes below this are raised to it (as the Mandelbox scene). */
#define FORMULA_BOX_MIN_ABS_SCALE 1.2f

inline float formula_box_scale(float requested) {
    const float magnitude = fmax(fabs(requested), FORMULA_BOX_MIN_ABS_SCALE);
    return requested < 0.0f ? -magnitude : magnitude;
}

/* The Mandelbox's fold and scale: z <- scale * sphere_fold(box_fold(z)), dr to match. */
inline vec3 box_step(vec3 z, real* dr, float scale, float folding_limit, float min_radius,
                     float fixed_radius) {
    const float fixed2 = fixed_radius * fixed_radius;
    const float min2 = fmin(min_radius * min_radius, fixed2);
    real fold_dr = *dr;
    const vec3 folded = fold_sphere(fold_box(z, folding_limit), &fold_dr, min2, fixed2);
    *dr = fold_dr * fabs(scale);
    return v3_scale(folded, fgr_real(scale));
}

/* Mandelbox (Tom Lowe, 2010): z <- scale * sphere_fold(box_fold(z)) + c. */
inline void formula_mandelbox(vec3* z, real* w, real* dr, const vec3 c, float scale,
                              float folding_limit, float min_radius, float fixed_radius) {
    (void)w;
    const float s = formula_box_scale(scale);
    *z = v3_add(box_step(*z, dr, s, folding_limit, min_radius, fixed_radius), c);
    *dr += 1.0f;
}

/* Mandelbox with a Julia constant: + julia instead of + c. */
inline void formula_mandelbox_julia(vec3* z, real* w, real* dr, const vec3 c, float scale,
                                    float folding_limit, float min_radius, float fixed_radius,
                                    vec3 julia) {
    (void)w;
    (void)c;
    const float s = formula_box_scale(scale);
    *z = v3_add(box_step(*z, dr, s, folding_limit, min_radius, fixed_radius), julia);
}

/* Amazing Box (Tglad's name for the Mandelbox, fractalforums.com 2010) with a rotation after the
 * folds, as Mandelbulber 2's "Amazing Box" offers: rotations are isometries. */
inline void formula_amazing_box(vec3* z, real* w, real* dr, const vec3 c, float scale,
                                float folding_limit, float min_radius, float fixed_radius,
                                rotation3 turn) {
    (void)w;
    const float s = formula_box_scale(scale);
    const vec3 folded = box_step(*z, dr, s, folding_limit, min_radius, fixed_radius);
    *z = v3_add(op_rotate(folded, turn), c);
    *dr += 1.0f;
}

/* Amazing Surf (Kali and M. Benesi, fractalforums.com 2011; Mandelbulb 3D's and Mandelbulber 2's
 * "Amazing Surf"): the box fold on x and y only, so the set spreads into a surface along z; then
 * the sphere fold (fixed radius 1), the scale and a rotation, and c times c_scale added with its
 * x and y exchanged, as the original does. */
inline void formula_amazing_surf(vec3* z, real* w, real* dr, const vec3 c, float scale, vec3 fold,
                                 float min_radius, float c_scale, rotation3 turn) {
    (void)w;
    vec3 p = *z;
    p.x = fabs(p.x + fold.x) - fabs(p.x - fold.x) - p.x;
    p.y = fabs(p.y + fold.y) - fabs(p.y - fold.y) - p.y;
    real fold_dr = *dr;
    p = fold_sphere(p, &fold_dr, fmin(min_radius * min_radius, 1.0f), 1.0f);
    const float s = formula_box_scale(scale);
    *dr = fold_dr * fabs(s) + 1.0f;
    const vec3 c_swapped = v3(c.y, c.x, c.z);
    *z = v3_add(op_rotate(v3_scale(p, fgr_real(s)), turn), v3_scale(c_swapped, fgr_real(c_scale)));
}

/* ABox with per-axis folds (Mandelbulber 2's "ABox Mod", after Tglad's box fold): each axis folds
 * at a limit of its own. */
inline void formula_abox(vec3* z, real* w, real* dr, const vec3 c, float scale, vec3 limits,
                         float min_radius, float fixed_radius) {
    (void)w;
    const float s = formula_box_scale(scale);
    const float fixed2 = fixed_radius * fixed_radius;
    real fold_dr = *dr;
    const vec3 folded = fold_sphere(fold_box_axes(*z, limits), &fold_dr,
                                    fmin(min_radius * min_radius, fixed2), fixed2);
    *dr = fold_dr * fabs(s) + 1.0f;
    *z = v3_mad(c, folded, fgr_real(s));
}

/* Amazing Box with a Julia constant: + julia instead of + c. */
inline void formula_amazing_box_julia(vec3* z, real* w, real* dr, const vec3 c, float scale,
                                      float folding_limit, float min_radius, float fixed_radius,
                                      vec3 julia, rotation3 turn) {
    (void)w;
    (void)c;
    const float s = formula_box_scale(scale);
    const vec3 folded = box_step(*z, dr, s, folding_limit, min_radius, fixed_radius);
    *z = v3_add(op_rotate(folded, turn), julia);
}

/* ABox with a Julia constant. */
inline void formula_abox_julia(vec3* z, real* w, real* dr, const vec3 c, float scale, vec3 limits,
                               float min_radius, float fixed_radius, vec3 julia) {
    (void)w;
    (void)c;
    const float s = formula_box_scale(scale);
    const float fixed2 = fixed_radius * fixed_radius;
    real fold_dr = *dr;
    const vec3 folded = fold_sphere(fold_box_axes(*z, limits), &fold_dr,
                                    fmin(min_radius * min_radius, fixed2), fixed2);
    *dr = fold_dr * fabs(s);
    *z = v3_mad(julia, folded, fgr_real(s));
}
