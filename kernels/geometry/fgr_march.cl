// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: sphere tracing of a packet of rays.
 *
 * A ray hits when the distance estimate falls below the pixel's footprint at that distance:
 * DE(p) < hit_threshold * t * pixel_angle. Surfaces are resolved exactly as finely as the image
 * can show them, no finer, which is what makes far detail cheap.
 *
 * Over-relaxation: with over_relaxation w > 1 a ray may stretch a step beyond its safe distance
 * (step_factor * DE), by up to w times. How far depends on how the DE fell over the last step: on
 * a plane met at cosine c the DE falls by c per unit travelled, and the safe balls of successive
 * points keep overlapping for steps up to 2 / (1 + c) times the safe one, so grazing rays take
 * long strides and rays heading straight at a surface take plain steps. As in Keinert et al.'s
 * "Enhanced Sphere Tracing" (2014), each stretched step is checked: its ball and the previous
 * one, both shrunk by the hit footprint, must overlap; where they leave a gap the step may have
 * jumped over the surface or a sub-pixel feature, so the ray goes back and takes the plain step
 * instead, judging nothing at the rejected point. At w = 1 this is plain sphere tracing,
 * operation for operation.
 *
 * A camera on the surface: where the DE at the eye is 0 or less (the eye on the surface, like the
 * Mandelbox's camera at the origin, its fixed point, or inside a solid with a signed DE), the hit
 * footprint there is 0 and steps of DE never move the ray, so every ray would spend max_steps at
 * the eye. Such rays march out instead: while the DE is <= 0 they ignore the surface and step by
 * the larger of |DE| and FGR_ESCAPE_STEP of max_distance (or the footprint, further out), and
 * from the first point where it is positive they march on as rays leaving a surface
 * (march_rays_departing): a hit counts only where the DE falls, so the surface the camera sits on
 * never stops them. With a signed DE the camera sees out of the solid it is in, as if it were cut
 * away at the eye; in a fractal's solid interior, where the DE is tiny but positive (the
 * Mandelbox's round the origin), the rays meet the solid within a few steps. */

/* A ray starting on the surface steps at least this fraction of max_distance while it is in it:
 * enough to move a float eye several units from the origin, too little to skip a visible
 * feature. */
#define FGR_ESCAPE_STEP 1e-5f

typedef struct march_result {
    real t;     /* distance along the ray of the last evaluated point */
    mask hit;   /* lanes that met the surface */
    mask steps; /* DE evaluations taken per lane (an int per lane) */
#ifdef FGR_EFFECT_GLOW
    real closest; /* smallest DE met along the ray: how near a miss passed the surface */
#endif
#ifdef FGR_GEOMETRY_IFS
    /* IFS scenes know their surface where they hit it (fgr_ifs.cl): steps counts nodes visited */
    vec3 normal;
    vec3 albedo;
    mask heap_peak;  /* most nodes a lane's heap held */
    mask leaf_depth; /* the level of the node hit (-1 where the ray missed) */
#endif
} march_result;

/* How far and how finely rays march: the built-in quality parameters, read once per kernel. */
typedef struct march_limits {
    float footprint; /* hit when DE < footprint * t: hit_threshold * pixel_angle */
    int max_steps;
    float max_distance;
    float step_factor; /* rays advance step_factor * DE */
    float relaxation;  /* over-relaxation: step_factor * DE * relaxation while it is safe */
} march_limits;

inline march_limits scene_march_limits(float pixel_angle, PARAMS) {
    march_limits limits;
    limits.footprint = param_hit_threshold * pixel_angle;
    limits.max_steps = param_max_steps;
    limits.max_distance = param_max_distance;
    limits.step_factor = param_step_factor;
    limits.relaxation = param_over_relaxation;
    return limits;
}

/* Marches every lane of `active` from origin along dir until it hits, passes `reach` (per lane:
 * max_distance, or the distance to a point light for shadow rays), or has taken max_steps.
 * Inactive lanes are not evaluated for hits and keep t = 0. `travelled` is the distance the ray
 * covered before origin (a reflected ray's first leg): the hit footprint grows with the whole
 * path, so secondary rays resolve no finer than the pixel they end up in. */
#ifdef FGR_GEOMETRY_IFS
/* IFS scenes are traced exactly instead (fgr_ifs.cl, after this file). */
march_result ifs_trace_rays(vec3 origin, vec3 dir, mask active, real travelled, real reach,
                            march_limits limits, int any_hit, PARAMS);
#endif

inline march_result march_rays_core(vec3 origin, vec3 dir, mask active, real start, real travelled,
                                    real reach, march_limits limits, int departing, PARAMS) {
#ifdef FGR_GEOMETRY_IFS
    (void)departing; /* an exact hit ahead of the origin never is the surface the ray leaves */
    (void)start;     /* the prepass never runs for IFS scenes */
    return ifs_trace_rays(origin, dir, active, travelled, reach, limits, 0, PARAMS_PASS);
#else
    march_result result;
    /* A start past the eye comes from the cone prepass (fgr_prepass.cl): the space before it is
     * clear, and a lane starting past its reach has nothing to march. */
    result.t = start;
    active &= start <= reach;
    result.hit = (mask)(0);
    result.steps = (mask)(0);
#ifdef FGR_EFFECT_GLOW
    result.closest = fgr_real(1e20f);
#endif
    /* Per lane: the safe radius at the last point, the step that left it (<= 0 after a
     * rejected step: the next one is plain), and whether that step went beyond the safe radius
     * (only such steps need checking). */
    real last_radius = fgr_real(0.0f);
    real last_step = fgr_real(0.0f);
    /* The DE at the last point, for `departing` rays (infinite before the first). */
    real last_dist = fgr_real(INFINITY);
    mask stretched = (mask)(0);
    const bool relaxing = limits.relaxation > 1.0f;
    /* Lanes that started on or in the surface (the eye's DE <= 0, see the top of the file):
     * `escaping` while their DE is still <= 0, `leaving` from then on (every lane of a departing
     * march). */
    mask escaping = (mask)(0);
    mask leaving = departing ? FGR_TRUE : (mask)(0);
    int any_leaving = departing;
    for (int step = 0; step < limits.max_steps; ++step) {
        if (!fgr_any(active)) break;
        const real t_here = result.t;
        real dist = scene_de(v3_mad(origin, dir, t_here), PARAMS_PASS);
        if (step == 0) {
            /* Only at the eye itself: no distance covered before, so no footprint there. */
            escaping = active & (dist <= 0.0f) & (travelled <= 0.0f) & (t_here <= 0.0f);
            leaving |= escaping;
            any_leaving |= fgr_any(escaping);
        }
        /* A relaxed march first checks the stretched step that led here. */
        real radius = fgr_real(0.0f), shrink = fgr_real(0.0f);
        mask overshot = (mask)(0);
        if (relaxing) {
            radius = fabs(dist) * limits.step_factor;
            shrink = 2.0f * limits.step_factor * limits.footprint * (result.t + travelled);
            overshot = stretched & active & (radius + last_radius - shrink < last_step);
        }
#ifdef FGR_EFFECT_GLOW
        /* Not the surface a ray starting in it is still leaving. */
        result.closest = select(result.closest, fmin(result.closest, dist),
                                active & !overshot & !(escaping & (dist <= 0.0f)));
#endif
        mask now_hit = active & !overshot & (dist < (result.t + travelled) * limits.footprint);
        if (any_leaving) {
            escaping &= dist <= 0.0f;
            now_hit &= !escaping;
        }
        if (departing) {
            /* A ray leaving a surface may start within the footprint of a wall beside it (in a
             * crevice): only a surface it approaches (the DE falling) stops it. */
            now_hit &= dist < last_dist;
            last_dist = select(last_dist, dist, active & !overshot);
        } else if (any_leaving) {
            now_hit &= (dist < last_dist) | !leaving;
            last_dist = select(last_dist, dist, leaving & active & !overshot);
        }
        result.hit |= now_hit;
        active &= !now_hit;
        if (relaxing) {
            /* The stride for a plane met at cosine c, shrunk by the footprint and with 0.1 left
             * for curvature: (1.9 radius - shrink) / (1 + c), where c = fall / (step_factor *
             * last_step) as the radii carry step_factor; one division. Plain after a rejected
             * step. */
            real travel = limits.step_factor * last_step;
            real fall = fmax(last_radius - radius, 0.0f);
            real stride =
                (1.9f * radius - shrink) * travel / fmax(travel + fall, fgr_real(FGR_MIN_LENGTH));
            stride =
                select(radius, clamp(stride, radius, radius * limits.relaxation), last_step > 0.0f);
            /* A stretched step is checked at the point it reaches, but a ray stops once past
             * `reach` (a shadow ray at its light): a stretch that would end there is never
             * checked and could jump an occluder just before the light, so it is taken plain. */
            stride = select(stride, radius, result.t + stride > reach);
            /* Rejected: back over the failed step, then the last point's safe radius forward. */
            real next_step = select(stride, last_radius - last_step, overshot);
            last_radius = select(last_radius, radius, active & !overshot);
            last_step = select(last_step, next_step, active);
            stretched = active & !overshot & (stride > radius);
            result.t = select(result.t, result.t + next_step, active);
        } else {
            result.t = select(result.t, mad(dist, limits.step_factor, result.t), active);
        }
        if (any_leaving && fgr_any(escaping & active)) {
            /* Still in the surface: out by |DE|, or at least the escape step, never relaxed. */
            real escape = fmax(
                fabs(dist) * limits.step_factor,
                fmax(t_here * limits.footprint, fgr_real(FGR_ESCAPE_STEP * limits.max_distance)));
            mask in_surface = escaping & active;
            result.t = select(result.t, t_here + escape, in_surface);
            last_step = select(last_step, fgr_real(0.0f), in_surface);
            last_radius = select(last_radius, fgr_real(0.0f), in_surface);
            stretched &= !in_surface;
        }
        fgr_count_if(result.steps, active | now_hit);
        active &= result.t <= reach;
    }
    return result;
#endif
}

inline march_result march_rays_within(vec3 origin, vec3 dir, mask active, real travelled,
                                      real reach, march_limits limits, PARAMS) {
    return march_rays_core(origin, dir, active, fgr_real(0.0f), travelled, reach, limits, 0,
                           PARAMS_PASS);
}

/* march_rays_within for a ray leaving a surface point (the path tracer's bounces and shadow rays,
 * which must see the same occluders): a hit counts only where the DE fell since the last step, so
 * a wall the ray starts beside and moves away from never stops it. */
inline march_result march_rays_departing(vec3 origin, vec3 dir, mask active, real travelled,
                                         real reach, march_limits limits, PARAMS) {
    return march_rays_core(origin, dir, active, fgr_real(0.0f), travelled, reach, limits, 1,
                           PARAMS_PASS);
}

/* Whether anything blocks the ray before `reach` (shadow rays): march_rays_within, except that
 * an IFS scene stops at the first leaf it finds instead of the nearest. */
inline march_result march_rays_occluded(vec3 origin, vec3 dir, mask active, real travelled,
                                        real reach, march_limits limits, int departing, PARAMS) {
#ifdef FGR_GEOMETRY_IFS
    (void)departing;
    return ifs_trace_rays(origin, dir, active, travelled, reach, limits, 1, PARAMS_PASS);
#else
    return march_rays_core(origin, dir, active, fgr_real(0.0f), travelled, reach, limits, departing,
                           PARAMS_PASS);
#endif
}

inline march_result march_rays_after(vec3 origin, vec3 dir, mask active, real travelled,
                                     march_limits limits, PARAMS) {
    return march_rays_within(origin, dir, active, travelled, fgr_real(limits.max_distance), limits,
                             PARAMS_PASS);
}

inline march_result march_rays(vec3 origin, vec3 dir, mask active, march_limits limits, PARAMS) {
    return march_rays_after(origin, dir, active, fgr_real(0.0f), limits, PARAMS_PASS);
}

/* A camera ray's march from `start` along it (the cone prepass's distance for its block, see
 * fgr_prepass.cl; 0 starts at the eye). */
inline march_result march_camera_rays(vec3 origin, vec3 dir, mask active, real start,
                                      march_limits limits, PARAMS) {
    return march_rays_core(origin, dir, active, start, fgr_real(0.0f),
                           fgr_real(limits.max_distance), limits, 0, PARAMS_PASS);
}

/* Surface normal from the DE's gradient, with the four-tap tetrahedron stencil (four DE
 * evaluations instead of six for central differences). `eps` is per lane so the stencil scales
 * with the pixel footprint at the hit. */
inline vec3 estimate_normal(vec3 p, real eps, PARAMS) {
    real a, b, c, d;
    scene_de_pair(v3(p.x + eps, p.y - eps, p.z - eps), v3(p.x - eps, p.y - eps, p.z + eps), &a, &b,
                  PARAMS_PASS);
    scene_de_pair(v3(p.x - eps, p.y + eps, p.z - eps), v3(p.x + eps, p.y + eps, p.z + eps), &c, &d,
                  PARAMS_PASS);
    return v3_normalize(v3(a - b - c + d, -a - b + c + d, -a + b - c + d));
}

/* The surface normal where `hit` met the surface at p: the DE's gradient, or for IFS scenes the
 * one the trace found. */
inline vec3 surface_normal(march_result hit, vec3 p, real eps, PARAMS) {
#ifdef FGR_GEOMETRY_IFS
    (void)p;
    (void)eps;
    (void)fgr_params;
    return hit.normal;
#else
    (void)hit;
    return estimate_normal(p, eps, PARAMS_PASS);
#endif
}

#ifndef FGR_GEOMETRY_IFS
/* --- A march one DE evaluation at a time, each lane its own ray at its own step: march_rays_core
 * lane by lane, for a caller that evaluates the DE of many rays' points at once and starts a new
 * ray in a lane as soon as its last one ends (the path tracer's regrouped packets). A lane's ray
 * takes exactly the steps march_rays_core takes it (departing or not, relaxed or not), so it
 * meets the same surface at the same t. */
typedef struct march_lanes {
    vec3 origin, dir;
    real t; /* the point the next evaluation is at; where the ray hit once it has */
    real travelled, reach;
    real last_radius, last_step, last_dist; /* as march_rays_core's */
    mask stretched, escaping, leaving;
    mask steps;    /* DE evaluations so far */
    mask marching; /* lanes whose ray is still on its way */
    mask hit;      /* lanes whose ray met the surface (once it stopped) */
} march_lanes;

inline march_lanes march_lanes_none(void) {
    march_lanes m;
    m.origin = m.dir = v3_splat(0.0f, 0.0f, 0.0f);
    m.t = m.travelled = m.reach = m.last_radius = m.last_step = fgr_real(0.0f);
    m.last_dist = fgr_real(INFINITY);
    m.stretched = m.escaping = m.leaving = m.steps = m.marching = m.hit = (mask)(0);
    return m;
}

/* The lanes of `lanes` start a ray: from `start` along it (a camera ray's prepass distance; 0
 * for others), having `travelled` before origin, up to `reach`; `departing` lanes leave a
 * surface (march_rays_departing). A ray starting past its reach ends at once, having missed. */
inline void march_lanes_start(march_lanes* m, mask lanes, vec3 origin, vec3 dir, real start,
                              real travelled, real reach, mask departing) {
    m->origin = v3_select(m->origin, origin, lanes);
    m->dir = v3_select(m->dir, dir, lanes);
    m->t = select(m->t, start, lanes);
    m->travelled = select(m->travelled, travelled, lanes);
    m->reach = select(m->reach, reach, lanes);
    m->last_radius = select(m->last_radius, fgr_real(0.0f), lanes);
    m->last_step = select(m->last_step, fgr_real(0.0f), lanes);
    m->last_dist = select(m->last_dist, fgr_real(INFINITY), lanes);
    m->stretched &= ~lanes;
    m->escaping &= ~lanes;
    m->leaving = select(m->leaving, departing, lanes);
    m->steps = select(m->steps, (mask)(0), lanes);
    m->hit &= ~lanes;
    m->marching = select(m->marching, start <= reach, lanes);
}

/* Where each marching lane evaluates the DE next. */
inline vec3 march_lanes_point(const march_lanes* m) { return v3_mad(m->origin, m->dir, m->t); }

/* One step of the lanes of m->marching, given the DE at their points: march_rays_core's loop
 * body. Lanes whose ray hits, passes its reach or takes its last step stop marching. */
inline void march_lanes_step(march_lanes* m, real dist, march_limits limits) {
    mask active = m->marching;
    const real t_here = m->t;
    /* Only at the eye itself: no distance covered before, so no footprint there. */
    const mask first = active & (m->steps == (mask)(0));
    m->escaping =
        select(m->escaping, (dist <= 0.0f) & (m->travelled <= 0.0f) & (t_here <= 0.0f), first);
    m->leaving |= m->escaping & first;
    real radius = fgr_real(0.0f), shrink = fgr_real(0.0f);
    mask overshot = (mask)(0);
    const bool relaxing = limits.relaxation > 1.0f;
    if (relaxing) {
        radius = fabs(dist) * limits.step_factor;
        shrink = 2.0f * limits.step_factor * limits.footprint * (m->t + m->travelled);
        overshot = m->stretched & active & (radius + m->last_radius - shrink < m->last_step);
    }
    mask now_hit = active & !overshot & (dist < (m->t + m->travelled) * limits.footprint);
    m->escaping &= dist <= 0.0f;
    now_hit &= !m->escaping;
    now_hit &= (dist < m->last_dist) | !m->leaving;
    m->last_dist = select(m->last_dist, dist, m->leaving & active & !overshot);
    m->hit |= now_hit;
    active &= !now_hit;
    if (relaxing) {
        real travel = limits.step_factor * m->last_step;
        real fall = fmax(m->last_radius - radius, 0.0f);
        real stride =
            (1.9f * radius - shrink) * travel / fmax(travel + fall, fgr_real(FGR_MIN_LENGTH));
        stride =
            select(radius, clamp(stride, radius, radius * limits.relaxation), m->last_step > 0.0f);
        stride = select(stride, radius, m->t + stride > m->reach);
        real next_step = select(stride, m->last_radius - m->last_step, overshot);
        m->last_radius = select(m->last_radius, radius, active & !overshot);
        m->last_step = select(m->last_step, next_step, active);
        m->stretched = active & !overshot & (stride > radius);
        m->t = select(m->t, m->t + next_step, active);
    } else {
        m->t = select(m->t, mad(dist, limits.step_factor, m->t), active);
    }
    const mask in_surface = m->escaping & active;
    if (fgr_any(in_surface)) {
        real escape =
            fmax(fabs(dist) * limits.step_factor,
                 fmax(t_here * limits.footprint, fgr_real(FGR_ESCAPE_STEP * limits.max_distance)));
        m->t = select(m->t, t_here + escape, in_surface);
        m->last_step = select(m->last_step, fgr_real(0.0f), in_surface);
        m->last_radius = select(m->last_radius, fgr_real(0.0f), in_surface);
        m->stretched &= !in_surface;
    }
    fgr_count_if(m->steps, m->marching);
    active &= m->t <= m->reach;
    m->marching = active & (m->steps < (mask)(limits.max_steps));
}

#ifndef FGR_EFFECT_GLOW
/* What march_lanes holds of a finished march, as march_rays_core returns it. */
inline march_result march_lanes_result(const march_lanes* m) {
    march_result result;
    result.t = m->t;
    result.hit = m->hit;
    result.steps = m->steps;
    return result;
}

/* Two packets of camera rays marched side by side, each exactly as march_camera_rays marches it
 * (the same steps, hits and t): while both have rays on their way, one scene_de_pair call takes
 * a step of each, so that a scene iterating both points in one loop overlaps the two chains of
 * dependent operations; then the packet left marches alone. (No glow: march_lanes keeps no
 * closest approach.) */
inline void march_camera_ray_pair(vec3 origin_a, vec3 dir_a, mask active_a, real start_a,
                                  vec3 origin_b, vec3 dir_b, mask active_b, real start_b,
                                  march_limits limits, march_result* a, march_result* b, PARAMS) {
    const real reach = fgr_real(limits.max_distance);
    march_lanes ma = march_lanes_none(), mb = march_lanes_none();
    /* Every lane starts, as in march_rays_core (t = start even where the lane is inactive). */
    march_lanes_start(&ma, FGR_TRUE, origin_a, dir_a, start_a, fgr_real(0.0f), reach, (mask)(0));
    march_lanes_start(&mb, FGR_TRUE, origin_b, dir_b, start_b, fgr_real(0.0f), reach, (mask)(0));
    ma.marching &= active_a;
    mb.marching &= active_b;
    for (;;) {
        const int marching_a = fgr_any(ma.marching), marching_b = fgr_any(mb.marching);
        if (marching_a && marching_b) {
            real dist_a, dist_b;
            scene_de_pair(march_lanes_point(&ma), march_lanes_point(&mb), &dist_a, &dist_b,
                          PARAMS_PASS);
            march_lanes_step(&ma, dist_a, limits);
            march_lanes_step(&mb, dist_b, limits);
        } else if (marching_a) {
            march_lanes_step(&ma, scene_de(march_lanes_point(&ma), PARAMS_PASS), limits);
        } else if (marching_b) {
            march_lanes_step(&mb, scene_de(march_lanes_point(&mb), PARAMS_PASS), limits);
        } else {
            break;
        }
    }
    *a = march_lanes_result(&ma);
    *b = march_lanes_result(&mb);
}
#endif
#endif
