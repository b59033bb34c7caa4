// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: materials and their BSDFs, for the path tracer.
 *
 * A material is a diffuse (Lambertian) lobe plus a glossy GGX microfacet lobe:
 *
 *   f(wo, wi) = (1 - max(specular)) albedo / pi  +  D(h) G2(wo, wi) F(wo.h) / (4 |n.wo| |n.wi|)
 *
 *   D   Trowbridge-Reitz (GGX), alpha = roughness^2 (Walter et al. 2007)
 *   G2  height-correlated Smith masking-shadowing (Heitz 2014, "Understanding the
 *       Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2))
 *   F   Schlick's Fresnel with F0 = specular; its grazing value F90 fades to 0 with F0 below 2%
 *       (no real material reflects less than water's 2%), so specular 0 means no glossy lobe at
 *       all (Filament's "specular occlusion" of f90; Schuler 2009, ShaderX7)
 *
 * Sampling picks one lobe per sample (the glossy one with probability p_glossy, from the lobes'
 * luminance weights at wo) and draws the glossy lobe's microfacet normal from GGX's distribution
 * of visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)),
 * the diffuse lobe's direction from the cosine-weighted hemisphere. The pdf is the one-sample
 * mixture p_glossy p_glossy_lobe + (1 - p_glossy) p_diffuse, so bsdf_pdf is what MIS needs.
 * Below alpha = FGR_BSDF_MIN_ALPHA the glossy lobe is a perfect mirror: a delta lobe that only
 * bsdf_sample_direction returns (flagged `delta`), and that bsdf_eval and bsdf_pdf leave out.
 *
 * Conventions: n is the unit shading normal; wo the unit direction back along the arriving ray
 * (minus the ray direction); wi the unit direction leaving the surface. A wo or wi with
 * n.w <= FGR_BSDF_MIN_COS (below the surface, or on it) makes the sample invalid: weight, eval
 * and pdf are 0 and the path ends. An integrator whose shading normal can face away from wo (a
 * DE's gradient at a grazing hit) loses that path; bending n towards wo first keeps it.
 * Colours are linear RGB per lane. The BSDF ignores emission (the integrator adds it).
 *
 * Needs only the prelude's types and maths (fgr_types.cl, fgr_math.cl, fgr_vec3.cl). */

typedef struct material {
    vec3 albedo;    /* diffuse reflectance, [0, 1] per channel */
    vec3 specular;  /* the glossy lobe's reflectance at normal incidence (F0), [0, 1]; 0 = none
                       (a metal: albedo 0 and specular its colour; a plastic: specular ~0.04) */
    real roughness; /* [0, 1]; GGX alpha = roughness^2; 0 = a perfect mirror */
    vec3 emission;  /* emitted radiance (the integrator reads it; the BSDF ignores it) */
} material;

/* A Lambertian material: what a scene without scene_material gets from its colour. */
inline material diffuse_material(vec3 albedo) {
    material m;
    m.albedo = albedo;
    m.specular = v3_splat(0.0f, 0.0f, 0.0f);
    m.roughness = fgr_real(1.0f);
    m.emission = v3_splat(0.0f, 0.0f, 0.0f);
    return m;
}

typedef struct bsdf_sample {
    vec3 wi;     /* unit, away from the surface (n where invalid) */
    vec3 weight; /* f(wo, wi) |n.wi| / pdf: the throughput factor; 0 where invalid */
    real pdf;    /* the mixture's solid-angle pdf at wi (for MIS); a delta sample: its lobe's
                    probability */
    mask delta;  /* the mirror lobe was sampled: no light sampling, no MIS */
    mask valid;
} bsdf_sample;

/* Below this GGX alpha (roughness ~0.032) the glossy lobe is a perfect mirror, as pbrt-v4's
 * TrowbridgeReitzDistribution::EffectivelySmooth has it. Such a lobe is under 0.06 degrees wide:
 * narrower than a pixel of any view fgr renders (a 60-degree view 1000 pixels wide has 0.06-degree
 * pixels), so it reflects as a mirror does; and its peak D = 1/(pi alpha^2) > 3e5 would make
 * light-sampled estimates (f of a light direction near the peak) fireflies that MIS cannot
 * tame, while the delta lobe is sampled exactly. */
#define FGR_BSDF_MIN_ALPHA 1e-3f

/* Directions closer to the horizon than this cosine count as below it. Their contributions are
 * at most this fraction of a normal one's, and above it every quantity stays well inside float's
 * range: |wo + wi|^2 >= 4e-18 however opposed their tangential parts are, so the half vector of
 * two grazing directions never underflows to zero (it would at cosines below 1e-19, and a float
 * denormal of 1e-40 reached it). */
#define FGR_BSDF_MIN_COS 1e-9f

/* Rec. 709 luminance of linear RGB. */
inline real bsdf_luminance(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

inline real bsdf_max3(vec3 c) { return fmax(c.x, fmax(c.y, c.z)); }

inline vec3 bsdf_saturate(vec3 c) {
    return v3_min(v3_max(c, v3_splat(0.0f, 0.0f, 0.0f)), v3_splat(1.0f, 1.0f, 1.0f));
}

/* The local frame (s, t, n) of a unit normal: Duff et al. 2017, "Building an Orthonormal Basis,
 * Revisited" (JCGT 6(1)), branchless and accurate for every n, n.z = -1 included. */
typedef struct bsdf_frame {
    vec3 s, t, n;
} bsdf_frame;

inline bsdf_frame bsdf_frame_of(vec3 n) {
    const real sign = copysign(fgr_real(1.0f), n.z);
    const real a = -1.0f / (sign + n.z);
    const real b = n.x * n.y * a;
    bsdf_frame f;
    f.s = v3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.t = v3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

inline vec3 bsdf_to_local(bsdf_frame f, vec3 v) {
    return v3(v3_dot(v, f.s), v3_dot(v, f.t), v3_dot(v, f.n));
}

inline vec3 bsdf_to_world(bsdf_frame f, vec3 v) {
    return v3_mad(v3_mad(v3_scale(f.s, v.x), f.t, v.y), f.n, v.z);
}

/* What sampling and evaluation need from a material at one wo, its inputs clamped to their
 * ranges (so a scene's stray value cannot make a weight negative or a pdf NaN). */
typedef struct bsdf_lobes {
    vec3 kd;       /* diffuse reflectance: (1 - max(F0)) albedo */
    vec3 f0;       /* the glossy lobe's F0 */
    real f90;      /* its Fresnel at grazing: 1, fading to 0 for F0 below 2% */
    real alpha;    /* GGX alpha */
    mask delta;    /* alpha below FGR_BSDF_MIN_ALPHA: the glossy lobe is a mirror */
    real p_glossy; /* probability of sampling the glossy lobe */
} bsdf_lobes;

/* Schlick's Fresnel at cos_d = wo.h (in [0, 1]): F0 + (F90 - F0) (1 - cos_d)^5. */
inline vec3 bsdf_fresnel(bsdf_lobes l, real cos_d) {
    const real x = 1.0f - clamp(cos_d, 0.0f, 1.0f);
    const real x2 = x * x;
    const real x5 = x2 * x2 * x;
    return v3(mad(l.f90 - l.f0.x, x5, l.f0.x), mad(l.f90 - l.f0.y, x5, l.f0.y),
              mad(l.f90 - l.f0.z, x5, l.f0.z));
}

/* The lobes of m seen from a direction whose cosine to the normal is cos_o. The glossy lobe is
 * sampled in proportion to the luminance of its Fresnel at the macro-normal (roughly the
 * reflectance it will return), the diffuse lobe to that of kd; a black material samples the
 * diffuse lobe (its weight is 0 either way). */
inline bsdf_lobes bsdf_lobes_of(material m, real cos_o) {
    bsdf_lobes l;
    l.f0 = bsdf_saturate(m.specular);
    const real max_f0 = bsdf_max3(l.f0);
    l.kd = v3_scale(bsdf_saturate(m.albedo), 1.0f - max_f0);
    l.f90 = fmin(50.0f * max_f0, 1.0f);
    const real roughness = fmin(fmax(m.roughness, 0.0f), 1.0f); /* NaN becomes 0: a mirror */
    l.alpha = roughness * roughness;
    l.delta = l.alpha < FGR_BSDF_MIN_ALPHA;
    const real glossy = bsdf_luminance(bsdf_fresnel(l, cos_o));
    const real diffuse = bsdf_luminance(l.kd);
    const real total = glossy + diffuse;
    l.p_glossy = select(glossy / total, fgr_real(0.0f), total <= 0.0f);
    return l;
}

/* f |n.wi| and the sampling pdf of the non-delta lobes, in the local frame (z along n); both 0
 * where wo or wi is not above the surface. Written so nothing overflows or divides by zero for
 * any wo, wi above the surface, however grazing. */
inline void bsdf_eval_pdf_local(bsdf_lobes l, vec3 wo, vec3 wi, vec3* value, real* pdf) {
    const mask above = (wo.z > FGR_BSDF_MIN_COS) & (wi.z > FGR_BSDF_MIN_COS);
    const real zo = fmax(wo.z, 0.0f);
    const real zi = fmax(wi.z, 0.0f);

    /* Diffuse: f = kd / pi, pdf = cos / pi. Both share zi / pi, so a white diffuse material's
     * weight f cos / pdf is exactly 1. */
    const real cos_over_pi = zi * FGR_LANES(M_1_PI_F, M_1_PI);
    vec3 f = v3_scale(l.kd, cos_over_pi);
    real p = (1.0f - l.p_glossy) * cos_over_pi;

    /* Glossy. With unit h, D = alpha^2 / (pi (h.x^2 + h.y^2 + alpha^2 h.z^2)^2), whose
     * denominator is at least alpha^4: accurate from the lobe's tip to its tail. */
    const vec3 h = v3_normalize(v3_add(wo, wi));
    const real a2 = l.alpha * l.alpha;
    const real d_den = mad(a2, h.z * h.z, mad(h.x, h.x, h.y * h.y));
    const real d = a2 / (FGR_LANES(M_PI_F, M_PI) * d_den * d_den);
    /* Height-correlated Smith: with r = sqrt(z^2 + alpha^2 (x^2 + y^2)) for each direction,
     * Lambda = (r - z) / (2 z), so G2 = 1 / (1 + Lambda_o + Lambda_i) = 2 zo zi / (ro zi + ri zo)
     * and f cos_i = D F G2 / (4 zo) = D F zi / (2 (ro zi + ri zo)). */
    const real ro = sqrt(mad(a2, mad(wo.x, wo.x, wo.y * wo.y), zo * zo));
    const real ri = sqrt(mad(a2, mad(wi.x, wi.x, wi.y * wi.y), zi * zi));
    const real g_cos = 0.5f * zi / fmax(mad(ro, zi, ri * zo), FGR_LANES(FLT_MIN, DBL_MIN));
    const vec3 fresnel = bsdf_fresnel(l, v3_dot(wo, h));
    const mask glossy = above & !l.delta;
    f = v3_select(f, v3_mad(f, fresnel, d * g_cos), glossy);
    /* The visible-normal pdf of h is G1(wo) max(wo.h, 0) D(h) / zo; reflection divides by
     * 4 wo.h, and G1(wo) = 2 zo / (zo + ro): p = D / (2 (zo + ro)). */
    p = select(p, mad(l.p_glossy, d / (2.0f * (zo + ro)), p), glossy);

    *value = v3_select(v3_splat(0.0f, 0.0f, 0.0f), f, above);
    *pdf = select(fgr_real(0.0f), p, above);
}

/* f(wo, wi) max(n.wi, 0) of the non-delta lobes. */
inline vec3 bsdf_eval(material m, vec3 n, vec3 wo, vec3 wi) {
    const bsdf_frame frame = bsdf_frame_of(n);
    const vec3 lo = bsdf_to_local(frame, wo);
    const bsdf_lobes l = bsdf_lobes_of(m, lo.z);
    vec3 value;
    real pdf;
    bsdf_eval_pdf_local(l, lo, bsdf_to_local(frame, wi), &value, &pdf);
    return value;
}

/* The solid-angle pdf with which bsdf_sample_direction returns wi, non-delta lobes. */
inline real bsdf_pdf(material m, vec3 n, vec3 wo, vec3 wi) {
    const bsdf_frame frame = bsdf_frame_of(n);
    const vec3 lo = bsdf_to_local(frame, wo);
    const bsdf_lobes l = bsdf_lobes_of(m, lo.z);
    vec3 value;
    real pdf;
    bsdf_eval_pdf_local(l, lo, bsdf_to_local(frame, wi), &value, &pdf);
    return pdf;
}

/* A visible microfacet normal of GGX seen from wo (local, above the surface), from two uniform
 * numbers: Heitz 2018. Stretch wo to the alpha = 1 configuration, sample the projected
 * hemisphere there (a disk whose lower half is squeezed by the hemisphere's tilt), lift the
 * point onto the hemisphere and unstretch. */
inline vec3 bsdf_sample_visible_normal(vec3 wo, real alpha, real u1, real u2) {
    const vec3 vh = v3_normalize(v3(alpha * wo.x, alpha * wo.y, wo.z));
    const real len2 = mad(vh.x, vh.x, vh.y * vh.y);
    const real inv_len = rsqrt(len2);
    const mask tilted = len2 > 0.0f;
    const vec3 t1 = v3(select(fgr_real(1.0f), -vh.y * inv_len, tilted),
                       select(fgr_real(0.0f), vh.x * inv_len, tilted), fgr_real(0.0f));
    const vec3 t2 = v3_cross(vh, t1);
    const real r = sqrt(u1);
    const real phi = (2.0f * FGR_LANES(M_PI_F, M_PI)) * u2;
    const real p1 = r * fgr_cos(phi);
    const real s = 0.5f * (1.0f + vh.z);
    const real p2 = mad(1.0f - s, sqrt(fmax(1.0f - p1 * p1, 0.0f)), s * r * fgr_sin(phi));
    const real lift = sqrt(fmax(1.0f - p1 * p1 - p2 * p2, 0.0f));
    const vec3 nh = v3_mad(v3_mad(v3_scale(t1, p1), t2, p2), vh, lift);
    return v3_normalize(v3(alpha * nh.x, alpha * nh.y, fmax(nh.z, 0.0f)));
}

/* One direction from the BSDF: u_lobe picks the lobe, (u1, u2) the direction in it; all three in
 * [0, 1). The weight is f |n.wi| / pdf, computed from the same f and pdf as bsdf_eval and
 * bsdf_pdf return at wi (their ratio, to rounding); a mirror sample's is F / p_glossy. */
inline bsdf_sample bsdf_sample_direction(material m, vec3 n, vec3 wo, real u_lobe, real u1,
                                         real u2) {
    const bsdf_frame frame = bsdf_frame_of(n);
    const vec3 lo = bsdf_to_local(frame, wo);
    const bsdf_lobes l = bsdf_lobes_of(m, lo.z);
    const mask glossy = u_lobe < l.p_glossy;
    const mask mirror = glossy & l.delta;

    /* Diffuse: a uniform point on the unit disk lifted onto the hemisphere (Malley). */
    const real r = sqrt(u1);
    const real phi = (2.0f * FGR_LANES(M_PI_F, M_PI)) * u2;
    const vec3 diffuse = v3(r * fgr_cos(phi), r * fgr_sin(phi), sqrt(fmax(1.0f - u1, 0.0f)));
    /* Glossy: wo reflected about a visible microfacet normal. */
    const vec3 h = bsdf_sample_visible_normal(lo, l.alpha, u1, u2);
    const vec3 reflected = v3_sub(v3_scale(h, 2.0f * v3_dot(lo, h)), lo);
    vec3 wi = v3_normalize(bsdf_to_world(frame, v3_select(diffuse, reflected, glossy)));
    /* Mirror: the exact reflection of wo about n, in world space. */
    const vec3 mirrored = v3_sub(v3_scale(n, 2.0f * v3_dot(n, wo)), wo);
    wi = v3_select(wi, mirrored, mirror);

    /* Weight and pdf from the direction as bsdf_eval and bsdf_pdf will see it. */
    const vec3 li = bsdf_to_local(frame, wi);
    vec3 value;
    real pdf;
    bsdf_eval_pdf_local(l, lo, li, &value, &pdf);
    /* Divided, not multiplied by 1 / pdf: a white diffuse lobe's weight is then exactly 1. */
    const real divisor = select(pdf, fgr_real(1.0f), pdf <= 0.0f);
    vec3 weight = v3(value.x / divisor, value.y / divisor, value.z / divisor);
    const mask above = (lo.z > FGR_BSDF_MIN_COS) & (li.z > FGR_BSDF_MIN_COS);
    const real inv_p_glossy = select(1.0f / l.p_glossy, fgr_real(0.0f), l.p_glossy <= 0.0f);
    weight = v3_select(weight, v3_scale(bsdf_fresnel(l, lo.z), inv_p_glossy), mirror);
    pdf = select(pdf, l.p_glossy, mirror);

    const mask finite = isfinite(weight.x) & isfinite(weight.y) & isfinite(weight.z) &
                        isfinite(pdf) & isfinite(wi.x) & isfinite(wi.y) & isfinite(wi.z);
    bsdf_sample sample;
    sample.valid = above & (pdf > 0.0f) & finite;
    sample.delta = mirror & sample.valid;
    sample.wi = v3_select(n, wi, sample.valid);
    sample.weight = v3_select(v3_splat(0.0f, 0.0f, 0.0f), weight, sample.valid);
    sample.pdf = select(fgr_real(0.0f), pdf, sample.valid);
    return sample;
}
