// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: what a scene's surface is, for the code after the scene's source.
 *
 * A scene gives a distance estimator, `real scene_de(vec3 p, PARAMS)`, an inside test,
 * `mask scene_inside(vec3 p, PARAMS)` (after `#define FGR_SCENE_HAS_INSIDE`), or both. A scene with
 * the inside test alone says `#define FGR_SCENE_INSIDE_ONLY` (which implies FGR_SCENE_HAS_INSIDE):
 * many escape-time formulas have no known DE, and the brute-force mode (fgr_mode_brute.cl) renders
 * them from the test alone. The brute-force mode's question, surface_inside(p, footprint), is
 * answered for both kinds of scene:
 *   - for a scene with an inside test, that test;
 *   - for a DE scene, whether the DE is below `footprint` (the hit threshold times the pixel's
 *     footprint at p's distance): the DE's sign, taken against the surface the sphere tracer stops
 *     at. (The bare sign would be poor for escape-time DEs, whose estimate is negative only where
 *     the orbit ends inside the unit ball: a dust of the set's interior, not its surface.)
 * An inside-only scene gets a stand-in DE for the code every mode's program holds (the probes,
 * the march library): 0 inside, FGR_NO_DISTANCE outside. The host renders such a scene only in
 * the brute-force mode and refuses to probe its DE. */

#ifdef FGR_SCENE_INSIDE_ONLY
#ifndef FGR_SCENE_HAS_INSIDE
#define FGR_SCENE_HAS_INSIDE
#endif
#define FGR_NO_DISTANCE 1e30f
inline real scene_de(vec3 p, PARAMS) {
    return select(fgr_real(FGR_NO_DISTANCE), fgr_real(0.0f), scene_inside(p, PARAMS_PASS) != 0);
}
#endif

/* The DE at two points. A scene whose DE loops may give its own, after
 * `#define FGR_SCENE_HAS_DE_PAIR` on a line of its own: one loop over both points' iterations
 * overlaps two independent chains, where two calls run one after the other. It must give each
 * lane what scene_de gives it. */
#ifndef FGR_SCENE_HAS_DE_PAIR
inline void scene_de_pair(vec3 a, vec3 b, real* da, real* db, PARAMS) {
    *da = scene_de(a, PARAMS_PASS);
    *db = scene_de(b, PARAMS_PASS);
}
#endif

/* Whether p is in the solid, as a canonical mask (all bits set in true vector lanes, 1 for
 * scalars), so two answers compare with ==. */
inline mask surface_inside(vec3 p, real footprint, PARAMS) {
#ifdef FGR_SCENE_HAS_INSIDE
    (void)footprint;
    return scene_inside(p, PARAMS_PASS) != 0;
#else
    return scene_de(p, PARAMS_PASS) < footprint;
#endif
}
