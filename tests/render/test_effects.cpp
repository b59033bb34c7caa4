// SPDX-License-Identifier: Apache-2.0
// Effects: each compile-time effect changes the image where it should and nowhere else, measured
// on small inline scenes built for the check: shadows and their penumbrae, both ambient
// occlusions, glow, fog, reflections, depth of field, anti-aliasing over samples, effects that
// have nothing to do leaving the image bit-identical, and exposure and tone mapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "fgr/plugin.h"
#include "image/display.hpp"
#include "mandelbulb_reference.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

constexpr int kEffectsWidth = 96;
constexpr int kEffectsHeight = 64;

// Ambient term of fgr_shade.cl (FGR_AMBIENT) times the default albedo's green (0.72).
constexpr float kAmbientGreen = 0.06f * 0.72f;

class EffectTest : public test::DeviceSuite<> {
protected:
    // One program per (scene, effects), built once per run thanks to the shared memory cache.
    static std::unique_ptr<Renderer> renderer(const Scene& scene, uint64_t effects) {
        return std::make_unique<Renderer>(
            *device_, *cache_, scene,
            KernelSwitches{preferred_packet_width(device_->info), effects});
    }

    // The scene's default view with predictable colour (clamp, exposure 1) plus `assignments`.
    static FrameRequest request(const Scene& scene,
                                const std::vector<std::string>& assignments = {}, int samples = 1) {
        FrameRequest result{kEffectsWidth, kEffectsHeight, scene.cameras.front().view,
                            default_param_values(scene)};
        set_param_from_text(scene, result.params, "tone_map=clamp");
        set_param_from_text(scene, result.params, "exposure=1");
        for (const auto& assignment : assignments) {
            set_param_from_text(scene, result.params, assignment);
        }
        result.samples = samples;
        return result;
    }
};

glm::vec3 pixel_rgb(const Frame& frame, int pixel) {
    return {frame.linear[pixel * 3], frame.linear[pixel * 3 + 1], frame.linear[pixel * 3 + 2]};
}

float green(const Frame& frame, int pixel) { return frame.linear[pixel * 3 + 1]; }

// World position of each pixel's primary hit (from its depth), nullopt where the ray missed.
std::vector<std::optional<glm::vec3>> hit_points(const Frame& frame, const CameraView& view) {
    const CameraBasis basis = camera_basis(view);
    std::vector<std::optional<glm::vec3>> points(frame.depth.size());
    for (int y = 0; y < kEffectsHeight; ++y) {
        for (int x = 0; x < kEffectsWidth; ++x) {
            const int pixel = y * kEffectsWidth + x;
            if (frame.depth[pixel] < 0.0f) continue;
            const glm::vec3 dir =
                primary_ray_direction(basis, kEffectsWidth, kEffectsHeight, float(x), float(y));
            points[pixel] = glm::vec3(view.position) + dir * frame.depth[pixel];
        }
    }
    return points;
}

// Pixels whose hit point satisfies `where`.
std::vector<int> pixels_where(const std::vector<std::optional<glm::vec3>>& points,
                              const std::function<bool(glm::vec3)>& where) {
    std::vector<int> pixels;
    for (size_t i = 0; i < points.size(); ++i) {
        if (points[i] && where(*points[i])) pixels.push_back(static_cast<int>(i));
    }
    return pixels;
}

double mean_of(const std::vector<int>& pixels, const std::function<double(int)>& value) {
    double sum = 0.0;
    for (int pixel : pixels) sum += value(pixel);
    return pixels.empty() ? 0.0 : sum / static_cast<double>(pixels.size());
}

double max_abs_difference(const Frame& a, const Frame& b, const std::vector<int>& pixels) {
    double worst = 0.0;
    for (int pixel : pixels) {
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst,
                             double(std::abs(a.linear[pixel * 3 + c] - b.linear[pixel * 3 + c])));
        }
    }
    return worst;
}

double mean_squared_difference(const Frame& a, const Frame& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.linear.size(); ++i) {
        const double d = double(a.linear[i]) - double(b.linear[i]);
        sum += d * d;
    }
    return sum / static_cast<double>(a.linear.size());
}

CameraView view_from(glm::vec3 position, glm::vec3 target) {
    CameraView view;
    view.position = position;
    view.target = target;
    view.up = {0.0f, 0.0f, 1.0f};
    view.fov_degrees = 60.0f;
    return view;
}

Light directional(glm::vec3 towards, float intensity = 1.0f) {
    return Light{LightType::Directional, towards, {1.0f, 1.0f, 1.0f}, intensity};
}

ParamInfo float_param(std::string id, float default_value) {
    ParamInfo param;
    param.id = std::move(id);
    param.label = param.id;
    param.type = ParamType::Float;
    param.min_value = 0.0f;
    param.max_value = 1.0f;
    param.default_value = {default_value, 0.0f, 0.0f};
    return param;
}

// ---------------------------------------------------------------------------------------------
// Shadows: a floor at z = -0.5 and a slab hovering at z = 1.5 above it, out of the camera's view
// (every primary ray heads down from below the slab), so the whole shadow is visible. The light
// is straight above: the shadow is the slab's footprint, |x|, |y| < 0.35.

Scene shadow_scene() {
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    real ground = sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), -0.5f);
    real slab = sd_box(op_translate(p, v3_splat(0.0f, 0.0f, 1.5f)), v3_splat(0.35f, 0.35f, 0.05f));
    return op_union(ground, slab);
}
)");
    scene.cameras.front().view = view_from({0.0f, -2.0f, 1.0f}, {0.0f, 0.0f, -0.5f});
    scene.lights = {directional({0.0f, 0.0f, 1.0f})};
    return scene;
}

// Hit points lie up to a pixel footprint (hit_threshold * pixel angle * distance, about 0.04 here)
// off the surface.
bool on_floor(glm::vec3 p) { return std::abs(p.z + 0.5f) < 0.05f; }

// Outside distance from the slab's footprint (Chebyshev), negative inside it.
float footprint_distance(glm::vec3 p) { return std::max(std::abs(p.x), std::abs(p.y)) - 0.35f; }

// How much of the light reaches a floor pixel: its direct term with the effect over the direct
// term without (the ambient term, the same in both, removed).
float light_fraction(const Frame& with, const Frame& without, int pixel) {
    return (green(with, pixel) - kAmbientGreen) / (green(without, pixel) - kAmbientGreen);
}

// Floor pixels that get some but not all of the light: how wide the shadow's edge is.
int penumbra_pixels(const Frame& with, const Frame& without, const std::vector<int>& floor) {
    int count = 0;
    for (int pixel : floor) {
        const float lit = light_fraction(with, without, pixel);
        count += lit > 0.1f && lit < 0.9f;
    }
    return count;
}

TEST_F(EffectTest, ShadowsDarkenTheFloorUnderAnOccluderAndNothingElse) {
    const Scene scene = shadow_scene();
    const FrameRequest req = request(scene);
    const Frame plain = renderer(scene, 0)->render(req);
    const auto points = hit_points(plain, req.view);
    const auto under = pixels_where(
        points, [](glm::vec3 p) { return on_floor(p) && footprint_distance(p) < -0.1f; });
    const auto open = pixels_where(
        points, [](glm::vec3 p) { return on_floor(p) && footprint_distance(p) > 0.6f; });
    ASSERT_GT(under.size(), 40u);
    ASSERT_GT(open.size(), 80u);
    const double lit_under = mean_of(under, [&](int p) { return green(plain, p); });
    ASSERT_GT(lit_under, 0.5);  // the floor faces the light: bright without shadows

    for (uint64_t effect : {uint64_t{FGR_EFFECT_SHADOWS}, uint64_t{FGR_EFFECT_SOFT_SHADOWS}}) {
        SCOPED_TRACE(effect_names(effect));
        const Frame shadowed = renderer(scene, effect)->render(req);
        // Under the slab only the ambient term is left.
        EXPECT_NEAR(mean_of(under, [&](int p) { return green(shadowed, p); }), kAmbientGreen, 0.01);
        for (int pixel : under) EXPECT_LT(light_fraction(shadowed, plain, pixel), 0.05f);
        // Open floor is as lit as without shadows.
        int changed = 0;
        for (int pixel : open) {
            changed += std::abs(green(shadowed, pixel) - green(plain, pixel)) > 1e-3f;
        }
        EXPECT_LT(max_abs_difference(shadowed, plain, open), 1e-3)
            << changed << " of " << open.size() << " open floor pixels changed";
        EXPECT_EQ(shadowed.hits, plain.hits);
    }
}

TEST_F(EffectTest, OccludersBeyondAPointLightCastNoShadow) {
    // The light hangs between the floor and the slab: nothing lies between them and the floor.
    Scene scene = shadow_scene();
    scene.lights = {Light{LightType::Point, {0.0f, 0.0f, 0.8f}, {1.0f, 1.0f, 1.0f}, 1.0f}};
    const FrameRequest req = request(scene);
    const Frame plain = renderer(scene, 0)->render(req);
    const auto points = hit_points(plain, req.view);
    const auto under = pixels_where(
        points, [](glm::vec3 p) { return on_floor(p) && footprint_distance(p) < -0.1f; });
    ASSERT_GT(under.size(), 40u);
    for (uint64_t effect : {uint64_t{FGR_EFFECT_SHADOWS}, uint64_t{FGR_EFFECT_SOFT_SHADOWS}}) {
        SCOPED_TRACE(effect_names(effect));
        const Frame shadowed = renderer(scene, effect)->render(req);
        EXPECT_LT(max_abs_difference(shadowed, plain, under), 1e-3);
    }
}

// A thin plate right in front of a point light: over-relaxed shadow rays stretch their steps
// where the DE does not fall, and a stretch is checked at the point it reaches, so one that ends
// beyond the light (where the ray stops) must not be taken, or it strides over the plate.
TEST_F(EffectTest, AThinOccluderJustBeforeAPointLightShadowsAtAnyOverRelaxation) {
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    real ground = sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), -0.5f);
    real plate = sd_box(op_translate(p, v3_splat(0.0f, 0.0f, 1.5f)),
                        v3_splat(0.35f, 0.35f, 0.002f));
    return op_union(ground, plate);
}
)");
    scene.cameras.front().view = view_from({0.0f, -2.0f, 1.0f}, {0.0f, 0.0f, -0.5f});
    scene.lights = {Light{LightType::Point, {0.0f, 0.0f, 1.53f}, {1.0f, 1.0f, 1.0f}, 4.0f}};
    const FrameRequest plain_request = request(scene);
    const Frame plain = renderer(scene, 0)->render(plain_request);
    const auto points = hit_points(plain, plain_request.view);
    // The plate hides the light from every floor point in view: a floor point's line to the light
    // crosses z = 1.5 within 0.03 / 2.03 of its horizontal offset, far inside the plate's 0.35.
    const auto under = pixels_where(points, on_floor);
    ASSERT_GT(under.size(), 200u);
    for (const char* relaxation :
         {"over_relaxation=1", "over_relaxation=1.6", "over_relaxation=1.95"}) {
        for (uint64_t effect : {uint64_t{FGR_EFFECT_SHADOWS}, uint64_t{FGR_EFFECT_SOFT_SHADOWS}}) {
            SCOPED_TRACE(effect_names(effect) + " " + relaxation);
            const Frame shadowed = renderer(scene, effect)->render(request(scene, {relaxation}));
            int lit = 0;
            for (int pixel : under) lit += light_fraction(shadowed, plain, pixel) > 0.05f;
            EXPECT_EQ(lit, 0) << "of " << under.size() << " floor pixels behind the plate are lit";
        }
    }
}

TEST_F(EffectTest, SoftShadowsHaveAPenumbraThatSharpnessNarrows) {
    const Scene scene = shadow_scene();
    const FrameRequest req = request(scene);
    const Frame plain = renderer(scene, 0)->render(req);
    const auto floor = pixels_where(hit_points(plain, req.view), on_floor);
    ASSERT_GT(floor.size(), 2000u);

    const Frame hard = renderer(scene, FGR_EFFECT_SHADOWS)->render(req);
    auto soft_renderer = renderer(scene, FGR_EFFECT_SOFT_SHADOWS);
    const Frame soft = soft_renderer->render(req);  // default shadow_sharpness 12
    const Frame blurry = soft_renderer->render(request(scene, {"shadow_sharpness=3"}));
    const Frame crisp = soft_renderer->render(request(scene, {"shadow_sharpness=48"}));
    const int hard_edge = penumbra_pixels(hard, plain, floor);
    const int soft_edge = penumbra_pixels(soft, plain, floor);
    const int blurry_edge = penumbra_pixels(blurry, plain, floor);
    const int crisp_edge = penumbra_pixels(crisp, plain, floor);
    RecordProperty("penumbra_pixels", std::to_string(hard_edge) + " hard, " +
                                          std::to_string(crisp_edge) + " k=48, " +
                                          std::to_string(soft_edge) + " k=12, " +
                                          std::to_string(blurry_edge) + " k=3");
    // One ray per pixel and a hard shadow: every floor pixel is either lit or not.
    EXPECT_LE(hard_edge, 2);
    EXPECT_GT(soft_edge, hard_edge + 20);
    EXPECT_GT(blurry_edge, 2 * soft_edge);
    EXPECT_LT(crisp_edge, soft_edge);
    // The penumbra lies outside the footprint (the rays inside it hit the slab): wider penumbrae
    // darken more floor, never less.
    const auto darkness = [&](const Frame& frame) {
        return mean_of(floor, [&](int p) { return 1.0 - light_fraction(frame, plain, p); });
    };
    EXPECT_GT(darkness(blurry), darkness(soft));
    EXPECT_GT(darkness(soft), darkness(crisp));
}

// ---------------------------------------------------------------------------------------------
// Soft shadows on a fractal: the Mandelbulb's canonical view lit by its key light alone, each lit
// pixel's soft-shadow factor against a far finer march of the same shadow ray. A fractal's DE is
// no exact distance (the Mandelbulb's grows by 1 to 1.4 per unit along a ray leaving it), which
// the shadow rays' closest-approach estimate between samples must survive: it once took an
// estimate of 0 there and put black specks and contour lines on lit surfaces.

constexpr int kBulbWidth = 64;
constexpr int kBulbHeight = 48;

struct ReferenceShadow {
    double light = 1.0;    // the soft-shadow factor, through the kernel's smoothstep
    bool blocked = false;  // a hard shadow: the ray met the surface before the light
};

// light_visibility of fgr_shade.cl marched finely: the factor is the least k * DE / t over the
// ray, sampled every tenth of the DE (the kernel samples every 0.8 DE and estimates the closest
// approach between samples), and 0 where the DE falls below the hit footprint. In double, with the
// plain C++ Mandelbulb. The start needs no guard: an unblocked sample has DE >= (t + travelled)
// * footprint, so k * DE / t >= 1 over the first k * travelled * footprint, and the DE's error
// near the surface cannot dim the start.
ReferenceShadow reference_soft_shadow(glm::dvec3 start, glm::dvec3 to_light, double travelled,
                                      double footprint, double reach, double sharpness) {
    ReferenceShadow result;
    double visibility = 1.0;
    for (double t = 0.0; t <= reach;) {
        const glm::dvec3 q = start + to_light * t;
        const double dist = test::mandelbulb_de<double>(q.x, q.y, q.z, test::BulbParams{});
        if (dist < (t + travelled) * footprint) {
            result.blocked = true;
            visibility = 0.0;
            break;
        }
        if (t > 0.0) visibility = std::min(visibility, sharpness * dist / t);
        t += std::max(0.1 * dist, 0.01 * travelled * footprint);
    }
    visibility = std::clamp(visibility, 0.0, 1.0);
    result.light = visibility * visibility * (3.0 - 2.0 * visibility);
    return result;
}

// Each lit pixel's soft-shadow factor, from the kernel and from reference_soft_shadow, and
// whether the reference's march met the surface (a hard shadow); -1 where the light does not
// reach the pixel enough to read a factor (misses, faces turned away, the terminator).
struct ShadowFactors {
    std::vector<double> kernel, reference;
    std::vector<char> blocked;
};

ShadowFactors bulb_shadow_factors(const Scene& scene, const FrameRequest& req, const Frame& soft,
                                  const Frame& plain, const Frame& ambient) {
    const int pixels = kBulbWidth * kBulbHeight;
    ShadowFactors factors{std::vector<double>(pixels, -1.0), std::vector<double>(pixels, -1.0),
                          std::vector<char>(pixels, 0)};
    const CameraBasis basis = camera_basis(req.view);
    const double footprint =
        param_value(scene, req.params, "hit_threshold") * pixel_angle(basis, kBulbWidth);
    const double reach = param_value(scene, req.params, "max_distance");
    const double sharpness = param_value(scene, req.params, "shadow_sharpness");
    const glm::dvec3 to_light = glm::normalize(glm::dvec3(scene.lights.front().vector));
    const auto sum = [](const Frame& frame, int pixel) {
        return double(frame.linear[pixel * 3]) + frame.linear[pixel * 3 + 1] +
               frame.linear[pixel * 3 + 2];
    };
    for (int y = 0; y < kBulbHeight; ++y) {
        for (int x = 0; x < kBulbWidth; ++x) {
            const int pixel = y * kBulbWidth + x;
            // The light's share of the pixel, shadows aside: the factor scales exactly it.
            const double direct = sum(plain, pixel) - sum(ambient, pixel);
            if (soft.depth[pixel] < 0.0f || direct < 0.02) continue;
            factors.kernel[pixel] = (sum(soft, pixel) - sum(ambient, pixel)) / direct;
            // The kernel's shadow ray: leave_surface of fgr_shade.cl from the hit along the
            // shading normal, two hit footprints and the rounding floor out.
            const double travelled = soft.depth[pixel];
            const glm::dvec3 p = glm::dvec3(req.view.position) +
                                 glm::dvec3(primary_ray_direction(basis, kBulbWidth, kBulbHeight,
                                                                  float(x), float(y))) *
                                     travelled;
            const glm::dvec3 n = glm::normalize(glm::dvec3(
                soft.normal[pixel * 3], soft.normal[pixel * 3 + 1], soft.normal[pixel * 3 + 2]));
            const double offset = 2.0 * travelled * footprint +
                                  1e-6 * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
            const ReferenceShadow shadow = reference_soft_shadow(
                p + n * offset, to_light, travelled, footprint, reach, sharpness);
            factors.reference[pixel] = shadow.light;
            factors.blocked[pixel] = shadow.blocked;
        }
    }
    return factors;
}

TEST_F(EffectTest, SoftShadowsOnTheMandelbulbMatchAFinerMarchOfTheSameRays) {
    Scene scene = test::built_scene("mandelbulb.so");
    scene.lights.resize(1);  // the key light, from the upper left
    Scene dark = scene;
    dark.lights.front().intensity = 0.0f;
    const uint64_t occlusion = FGR_EFFECT_AMBIENT_OCCLUSION;  // the scene's own effects
    const int width = preferred_packet_width(device_->info);
    // The soft shadows with each pixel's shading normal (where its shadow ray starts); the light
    // without shadows and no light at all, from one program: the factor is their ratio.
    Renderer soft_renderer(*device_, *cache_, scene,
                           KernelSwitches{width, occlusion | FGR_EFFECT_SOFT_SHADOWS, false, false,
                                          RenderMode::Shaded, true});
    const FrameRequest req{kBulbWidth, kBulbHeight, scene.cameras.front().view,
                           default_param_values(scene)};
    const Frame plain =
        Renderer(*device_, *cache_, scene, KernelSwitches{width, occlusion}).render(req);
    const Frame ambient =
        Renderer(*device_, *cache_, dark, KernelSwitches{width, occlusion}).render(req);
    // The default sharpness, and a low one whose penumbrae cover a fifth of the lit pixels.
    for (const char* sharpness : {"shadow_sharpness=12", "shadow_sharpness=3"}) {
        SCOPED_TRACE(sharpness);
        FrameRequest soft_req = req;
        set_param_from_text(scene, soft_req.params, sharpness);
        const Frame soft = soft_renderer.render(soft_req);
        const ShadowFactors factors = bulb_shadow_factors(scene, soft_req, soft, plain, ambient);
        // The kernel estimates the closest approach between samples 0.8 DE apart where the
        // reference samples every 0.1 DE: they differ by up to 0.04 in penumbrae (k = 3); 0.1
        // leaves room for other devices' rounding. A ray grazing the surface within a footprint
        // can be blocked in one march and not the other, which a percent of the pixels may show.
        // The specks were errors of 1 on 4% of the lit pixels.
        int lit = 0, far_off = 0;
        double worst = 0.0;
        for (size_t pixel = 0; pixel < factors.kernel.size(); ++pixel) {
            if (factors.kernel[pixel] < 0.0) continue;
            const double error = std::abs(factors.kernel[pixel] - factors.reference[pixel]);
            ++lit;
            far_off += error > 0.1;
            worst = std::max(worst, error);
        }
        ASSERT_GT(lit, 1000);
        EXPECT_LE(far_off, lit / 100) << "lit pixels whose factor is more than 0.1 off the "
                                         "finer march's, of "
                                      << lit << " (worst " << worst << ")";
        // No isolated dark pixel on a surface the light reaches (the reference's march, a finer
        // hard shadow, met nothing): none darker than all 8 of its lit neighbours by half the
        // light, which no penumbra 64 pixels wide makes.
        int specks = 0;
        for (int y = 1; y + 1 < kBulbHeight; ++y) {
            for (int x = 1; x + 1 < kBulbWidth; ++x) {
                const int pixel = y * kBulbWidth + x;
                if (factors.kernel[pixel] < 0.0 || factors.blocked[pixel]) continue;
                double brightest_below = 1e9;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        if (dx == 0 && dy == 0) continue;
                        const double neighbour = factors.kernel[pixel + dy * kBulbWidth + dx];
                        brightest_below = std::min(brightest_below, neighbour);
                    }
                }
                specks += factors.kernel[pixel] + 0.5 < brightest_below;
            }
        }
        EXPECT_EQ(specks, 0) << "isolated dark pixels on lit surfaces";
        RecordProperty(std::string("factor_") + sharpness,
                       std::to_string(far_off) + " of " + std::to_string(lit) +
                           " lit pixels off by more than 0.1, worst " + std::to_string(worst));
    }
}

// ---------------------------------------------------------------------------------------------
// Ambient occlusion: a cube resting on a floor, lit by the ambient term alone (the one light has
// intensity 0), so a pixel's colour is albedo * ambient * occlusion.

Scene crease_scene() {
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    real ground = sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), -0.5f);
    real cube = sd_box(op_translate(p, v3_splat(0.0f, 0.0f, -0.1f)), v3_splat(0.4f, 0.4f, 0.4f));
    return op_union(ground, cube);
}
)");
    scene.cameras.front().view = view_from({0.0f, -1.6f, 2.4f}, {0.0f, 0.0f, -0.3f});
    scene.lights = {directional({0.3f, -0.5f, 1.0f}, 0.0f)};
    return scene;
}

TEST_F(EffectTest, BothOcclusionsDarkenTheCreaseMoreThanAnOpenFace) {
    const Scene scene = crease_scene();
    // Step-count occlusion darkens by steps / max_steps: rays reach the crease in about 7 steps
    // and the open face in 3 to 4, which out of the default 256 is a difference of 0.03. Out of
    // 48 (still plenty for every ray here) it is 0.1.
    const FrameRequest req = request(scene, {"max_steps=48"});
    const Frame plain = renderer(scene, 0)->render(req);
    const auto points = hit_points(plain, req.view);
    // Floor just in front of the cube's front face (which is at y = -0.4).
    const auto crease = pixels_where(points, [](glm::vec3 p) {
        return on_floor(p) && p.y > -0.46f && p.y < -0.4f && std::abs(p.x) < 0.3f;
    });
    // The middle of the cube's top, open to the sky.
    const auto open = pixels_where(points, [](glm::vec3 p) {
        return std::abs(p.z - 0.3f) < 0.05f && std::abs(p.x) < 0.25f && std::abs(p.y) < 0.25f;
    });
    ASSERT_GT(crease.size(), 10u);
    ASSERT_GT(open.size(), 50u);
    // Only the ambient term lights the scene.
    EXPECT_NEAR(mean_of(open, [&](int p) { return green(plain, p); }), kAmbientGreen, 1e-4);

    for (uint64_t effect :
         {uint64_t{FGR_EFFECT_AMBIENT_OCCLUSION}, uint64_t{FGR_EFFECT_SAMPLED_OCCLUSION}}) {
        SCOPED_TRACE(effect_names(effect));
        const Frame occluded = renderer(scene, effect)->render(req);
        const auto kept = [&](int p) { return green(occluded, p) / green(plain, p); };
        const double crease_kept = mean_of(crease, kept);
        const double open_kept = mean_of(open, kept);
        RecordProperty(effect_names(effect), "crease keeps " + std::to_string(crease_kept) +
                                                 ", open face " + std::to_string(open_kept));
        EXPECT_LT(crease_kept, open_kept - 0.05);
        EXPECT_GT(open_kept, 0.8);
        for (int pixel : crease) EXPECT_LE(green(occluded, pixel), green(plain, pixel) + 1e-6f);
    }
}

TEST_F(EffectTest, SampledOcclusionReachesAsFarAsItsRadius) {
    // Floor pixels 0.15 to 0.3 in front of the cube are beyond the default radius (0.1) but
    // within a radius of 0.5.
    const Scene scene = crease_scene();
    const FrameRequest req = request(scene);
    const Frame plain = renderer(scene, 0)->render(req);
    const auto band = pixels_where(hit_points(plain, req.view), [](glm::vec3 p) {
        return on_floor(p) && p.y > -0.7f && p.y < -0.55f && std::abs(p.x) < 0.3f;
    });
    ASSERT_GT(band.size(), 10u);
    auto occlusion = renderer(scene, FGR_EFFECT_SAMPLED_OCCLUSION);
    const Frame near = occlusion->render(req);
    const Frame far = occlusion->render(request(scene, {"ao_radius=0.5"}));
    EXPECT_LT(max_abs_difference(near, plain, band), 1e-6);
    EXPECT_LT(mean_of(band, [&](int p) { return green(far, p) / green(plain, p); }), 0.9);
}

// ---------------------------------------------------------------------------------------------
// Glow: a sphere of radius 0.4 against the sky.

// Chebyshev distance in pixels from each pixel to the nearest hit (0 on hits), capped at 99.
std::vector<int> pixels_to_surface(const Frame& frame) {
    std::vector<int> distance(frame.depth.size(), 99);
    for (int y = 0; y < kEffectsHeight; ++y) {
        for (int x = 0; x < kEffectsWidth; ++x) {
            if (frame.depth[y * kEffectsWidth + x] < 0.0f) continue;
            for (int v = std::max(0, y - 12); v < std::min(kEffectsHeight, y + 13); ++v) {
                for (int u = std::max(0, x - 12); u < std::min(kEffectsWidth, x + 13); ++u) {
                    int& d = distance[v * kEffectsWidth + u];
                    d = std::min(d, std::max(std::abs(u - x), std::abs(v - y)));
                }
            }
        }
    }
    return distance;
}

TEST_F(EffectTest, GlowBrightensNearMissesOnly) {
    const Scene scene = test::sphere_scene();
    // Glow turns the cone prepass off (it needs the whole ray's closest approach): the plain
    // frame marches its rays from the eye too, so hits are the same pixel for pixel.
    FrameRequest req = request(scene);
    req.prepass.enabled = false;
    const Frame plain = renderer(scene, 0)->render(req);
    const Frame glowing = renderer(scene, FGR_EFFECT_GLOW)->render(req);
    ASSERT_EQ(glowing.hits, plain.hits);
    ASSERT_GT(plain.hits, 200);

    const auto distance = pixels_to_surface(plain);
    std::vector<int> hits, next_to, further, corners;
    for (int pixel = 0; pixel < kEffectsWidth * kEffectsHeight; ++pixel) {
        if (distance[pixel] == 0) hits.push_back(pixel);
        if (distance[pixel] == 1) next_to.push_back(pixel);
        if (distance[pixel] == 6) further.push_back(pixel);
    }
    for (int y : {0, 1, 2, kEffectsHeight - 3, kEffectsHeight - 2, kEffectsHeight - 1}) {
        for (int x : {0, 1, 2, kEffectsWidth - 3, kEffectsWidth - 2, kEffectsWidth - 1})
            corners.push_back(y * kEffectsWidth + x);
    }
    EXPECT_EQ(max_abs_difference(glowing, plain, hits), 0.0);
    EXPECT_LT(max_abs_difference(glowing, plain, corners), 1e-3);
    const auto gain = [&](int p) { return green(glowing, p) - green(plain, p); };
    for (int pixel : next_to) EXPECT_GT(gain(pixel), 0.05f) << "pixel " << pixel;
    // The default glow colour is blue-ish: blue gains the most.
    EXPECT_GT(mean_of(next_to,
                      [&](int p) { return glowing.linear[p * 3 + 2] - plain.linear[p * 3 + 2]; }),
              mean_of(next_to, [&](int p) { return glowing.linear[p * 3] - plain.linear[p * 3]; }));
    // Fading with distance from the surface.
    EXPECT_GT(mean_of(next_to, gain), 2.0 * mean_of(further, gain));
}

// ---------------------------------------------------------------------------------------------
// Fog: a floor receding from the default camera to the horizon (beyond max_distance: sky).

Scene floor_scene() {
    return test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    return sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), -0.5f);
}
)");
}

TEST_F(EffectTest, FogTakesFarSurfacesTowardsTheFogColourByDistance) {
    const Scene scene = floor_scene();
    const std::vector<std::string> fog = {"fog_colour=0.9,0.1,0.8", "fog_density=0.2"};
    const Frame plain = renderer(scene, 0)->render(request(scene, fog));
    const Frame fogged = renderer(scene, FGR_EFFECT_FOG)->render(request(scene, fog));
    ASSERT_EQ(fogged.hits, plain.hits);
    const glm::vec3 fog_colour(0.9f, 0.1f, 0.8f);
    std::vector<int> near, far;
    double worst = 0.0;
    // How far along from its own colour towards the fog's each pixel went.
    const auto fogginess = [&](int p) {
        const glm::vec3 own = pixel_rgb(plain, p);
        return glm::dot(pixel_rgb(fogged, p) - own, fog_colour - own) /
               glm::dot(fog_colour - own, fog_colour - own);
    };
    for (int pixel = 0; pixel < kEffectsWidth * kEffectsHeight; ++pixel) {
        const float depth = plain.depth[pixel];
        if (depth < 0.0f) continue;
        if (depth < 2.5f) near.push_back(pixel);
        if (depth > 6.0f) far.push_back(pixel);
        worst = std::max(worst, std::abs(fogginess(pixel) - (1.0 - std::exp(-0.2 * depth))));
    }
    ASSERT_GT(near.size(), 300u);
    ASSERT_GT(far.size(), 100u);
    EXPECT_GT(mean_of(far, fogginess), mean_of(near, fogginess) + 0.3);
    EXPECT_LT(worst, 2e-3);  // exp(-density * distance) of the surface's own colour remains
}

TEST_F(EffectTest, FogOfDensityZeroLeavesSurfacesAsWithoutFog) {
    // Surfaces at every pixel: a floor and a wall behind it.
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    return op_union(sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), -0.5f),
                    sd_plane(p, v3_splat(0.0f, -1.0f, 0.0f), -3.0f));
}
)");
    const Frame plain = renderer(scene, 0)->render(request(scene));
    const Frame clear = renderer(scene, FGR_EFFECT_FOG)->render(request(scene, {"fog_density=0"}));
    ASSERT_EQ(plain.hits, kEffectsWidth * kEffectsHeight);
    EXPECT_EQ(clear.image.rgb, plain.image.rgb);
    // mix(fog, colour, 1) rounds: the same up to float precision.
    std::vector<int> all(kEffectsWidth * kEffectsHeight);
    for (int pixel = 0; pixel < kEffectsWidth * kEffectsHeight; ++pixel) all[pixel] = pixel;
    EXPECT_LT(max_abs_difference(clear, plain, all), 1e-6);
}

TEST_F(EffectTest, FogOfDensityZeroLeavesTheSkyAsWithoutFog) {
    // No fog between the camera and the sky either: density 0 should change nothing.
    const Scene scene = floor_scene();
    const Frame plain = renderer(scene, 0)->render(request(scene));
    const Frame clear = renderer(scene, FGR_EFFECT_FOG)->render(request(scene, {"fog_density=0"}));
    ASSERT_LT(plain.hits,
              kEffectsWidth * kEffectsHeight / 2 + kEffectsWidth * 4);  // the upper half is sky
    std::vector<int> sky;
    for (int pixel = 0; pixel < kEffectsWidth * kEffectsHeight; ++pixel) {
        if (plain.depth[pixel] < 0.0f) sky.push_back(pixel);
    }
    EXPECT_LT(max_abs_difference(clear, plain, sky), 1e-6)
        << "sky pixel 0: " << plain.linear[0] << "," << plain.linear[1] << "," << plain.linear[2]
        << " without fog, " << clear.linear[0] << "," << clear.linear[1] << "," << clear.linear[2]
        << " with fog of density 0";
}

// ---------------------------------------------------------------------------------------------
// Reflections: a red sphere above a floor that is a perfect mirror (floor_mirror, default 1);
// sphere_mirror (default 0) makes the sphere a mirror too. The light comes from the camera's side
// and slightly below, so it lights the sphere's underside that the floor reflects.

Scene mirror_scene() {
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    return op_union(sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), -0.5f), sd_sphere(p, 0.4f));
}
#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    (void)fgr_params;
    return v3_select(v3_splat(0.9f, 0.05f, 0.05f), v3_splat(0.5f, 0.5f, 0.5f), p.z < -0.45f);
}
#define FGR_SCENE_HAS_REFLECTIVITY
real scene_reflectivity(vec3 p, PARAMS) {
    return select(fgr_real(param_sphere_mirror), fgr_real(param_floor_mirror), p.z < -0.45f);
}
)");
    scene.params.insert(scene.params.begin(),
                        {float_param("floor_mirror", 1.0f), float_param("sphere_mirror", 0.0f)});
    scene.cameras.front().view = view_from({0.0f, -3.0f, 0.6f}, {0.0f, 0.0f, -0.3f});
    scene.lights = {directional({0.0f, -1.0f, -0.2f})};
    return scene;
}

// Distance from the sphere's centre (the origin) of the mirror image of a floor pixel's ray.
float reflected_miss_distance(glm::vec3 eye, glm::vec3 floor_point) {
    glm::vec3 dir = glm::normalize(floor_point - eye);
    dir.z = -dir.z;
    const float along = std::max(glm::dot(-floor_point, dir), 0.0f);
    return glm::length(floor_point + dir * along);
}

float redness(const Frame& frame, int p) {
    return frame.linear[p * 3] - 0.5f * (frame.linear[p * 3 + 1] + frame.linear[p * 3 + 2]);
}

TEST_F(EffectTest, AMirrorFloorShowsTheSphereAboveIt) {
    const Scene scene = mirror_scene();
    const FrameRequest req = request(scene);
    const Frame plain = renderer(scene, 0)->render(req);
    auto mirrors = renderer(scene, FGR_EFFECT_REFLECTIONS);
    const Frame reflected = mirrors->render(req);
    const auto points = hit_points(plain, req.view);
    const glm::vec3 eye(req.view.position);
    const auto shows_sphere = pixels_where(
        points, [&](glm::vec3 p) { return on_floor(p) && reflected_miss_distance(eye, p) < 0.3f; });
    const auto shows_sky = pixels_where(
        points, [&](glm::vec3 p) { return on_floor(p) && reflected_miss_distance(eye, p) > 0.6f; });
    ASSERT_GT(shows_sphere.size(), 30u);
    ASSERT_GT(shows_sky.size(), 300u);

    const double plain_red = mean_of(shows_sphere, [&](int p) { return redness(plain, p); });
    const double mirror_red = mean_of(shows_sphere, [&](int p) { return redness(reflected, p); });
    RecordProperty("floor_redness",
                   std::to_string(plain_red) + " -> " + std::to_string(mirror_red));
    EXPECT_NEAR(plain_red, 0.0, 1e-3);  // a grey floor
    EXPECT_GT(mirror_red, 0.2);
    for (int pixel : shows_sphere) EXPECT_GT(redness(reflected, pixel), 0.05f) << "pixel " << pixel;
    // Where the floor mirrors the sky it turns no redder.
    EXPECT_LT(mean_of(shows_sky, [&](int p) { return redness(reflected, p); }), 0.01);
    // The sphere is not a mirror: it looks the same.
    const auto sphere = pixels_where(points, [](glm::vec3 p) { return p.z > -0.4f; });
    ASSERT_GT(sphere.size(), 100u);
    EXPECT_LT(max_abs_difference(reflected, plain, sphere), 1e-6);

    // A second bounce matters only where the first one met a mirror.
    const Frame one_bounce = mirrors->render(request(scene, {"reflection_bounces=1"}));
    const Frame two_bounces = mirrors->render(request(scene, {"reflection_bounces=2"}));
    EXPECT_EQ(two_bounces.linear, one_bounce.linear);  // only the floor is a mirror
    const Frame facing_one = mirrors->render(request(scene, {"sphere_mirror=1"}));
    const Frame facing_two =
        mirrors->render(request(scene, {"sphere_mirror=1", "reflection_bounces=2"}));
    EXPECT_LT(max_abs_difference(facing_two, facing_one, shows_sky), 1e-6);
    EXPECT_GT(mean_of(shows_sphere,
                      [&](int p) {
                          return glm::length(pixel_rgb(facing_two, p) - pixel_rgb(facing_one, p));
                      }),
              0.02);
}

// ---------------------------------------------------------------------------------------------
// Depth of field: a small sphere 2 from the camera (in focus) and a larger one 6 away, both lit
// from above so their top silhouettes are bright against the sky.

Scene two_spheres_scene() {
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    return op_union(sd_sphere(op_translate(p, v3_splat(-0.5f, -1.0f, 0.0f)), 0.3f),
                    sd_sphere(op_translate(p, v3_splat(1.2f, 3.0f, 0.0f)), 0.6f));
}
)");
    scene.lights = {directional({0.0f, 0.0f, 1.0f})};
    return scene;
}

struct EdgeProfile {
    int transition_rows = 0;  // rows between 10% and 90% of the way from sky to surface
    float steepest = 0.0f;    // largest change between neighbouring rows, as a fraction
};

// Green down columns x-1..x+1 across the top silhouette at row `top`, normalised by the sharp
// image's sky (8 rows above) and surface (3 rows below).
EdgeProfile edge_profile(const Frame& frame, const Frame& sharp, int x, int top) {
    EdgeProfile profile;
    for (int column = x - 1; column <= x + 1; ++column) {
        const float sky = green(sharp, (top - 8) * kEffectsWidth + column);
        const float surface = green(sharp, (top + 3) * kEffectsWidth + column);
        float previous = 0.0f;
        for (int row = top - 7; row <= top + 3; ++row) {
            const float f = (green(frame, row * kEffectsWidth + column) - sky) / (surface - sky);
            profile.transition_rows += f > 0.1f && f < 0.9f;
            if (row > top - 7)
                profile.steepest = std::max(profile.steepest, std::abs(f - previous));
            previous = f;
        }
    }
    return profile;
}

TEST_F(EffectTest, DepthOfFieldBlursOnlyWhatIsOutOfFocus) {
    const Scene scene = two_spheres_scene();
    const auto req = request(scene, {"aperture=0.15", "focus_distance=2"}, 32);
    const Frame sharp = renderer(scene, 0)->render(req);  // anti-aliased, pinhole
    const Frame focused = renderer(scene, FGR_EFFECT_DEPTH_OF_FIELD)->render(req);

    // Each sphere's topmost pixel, found in the sharp image by its depth.
    const auto top_of = [&](float min_depth, float max_depth, int* x, int* y) {
        for (int pixel = 0; pixel < kEffectsWidth * kEffectsHeight; ++pixel) {
            const float depth = sharp.depth[pixel];
            if (depth >= min_depth && depth <= max_depth) {
                *x = pixel % kEffectsWidth;
                *y = pixel / kEffectsWidth;
                return true;
            }
        }
        return false;
    };
    int near_x = 0, near_y = 0, far_x = 0, far_y = 0;
    ASSERT_TRUE(top_of(1.0f, 2.5f, &near_x, &near_y));
    ASSERT_TRUE(top_of(4.5f, 7.0f, &far_x, &far_y));
    ASSERT_GE(std::min(near_y, far_y), 8);

    const EdgeProfile near_sharp = edge_profile(sharp, sharp, near_x, near_y);
    const EdgeProfile near_dof = edge_profile(focused, sharp, near_x, near_y);
    const EdgeProfile far_sharp = edge_profile(sharp, sharp, far_x, far_y);
    const EdgeProfile far_dof = edge_profile(focused, sharp, far_x, far_y);
    RecordProperty("transition_rows", "near " + std::to_string(near_sharp.transition_rows) +
                                          " -> " + std::to_string(near_dof.transition_rows) +
                                          ", far " + std::to_string(far_sharp.transition_rows) +
                                          " -> " + std::to_string(far_dof.transition_rows));
    EXPECT_LE(near_dof.transition_rows, near_sharp.transition_rows + 2);
    EXPECT_GT(near_dof.steepest, 0.7f * near_sharp.steepest);
    EXPECT_GE(far_dof.transition_rows, far_sharp.transition_rows + 6);
    EXPECT_LT(far_dof.steepest, 0.5f * far_sharp.steepest);
}

// ---------------------------------------------------------------------------------------------
// Anti-aliasing: more samples per pixel converge, as 1 / N.

// Jittered samples are independent and uniform in the pixel, so an image of N of them differs
// from an independent image of M by, in expectation, v (1/N + 1/M) per value squared, v the
// pixel's variance of one sample. Two independent M-sample references differ by 2 v / M, so for
// every pixel E[(image - a)^2 - (M/N + 1)/2 (a - b)^2] = 0. Each image is rendered from its own
// samples (first_sample): none is shared by construction. The mean of that per-pixel difference
// must be within 4 standard errors of 0 (pixels are independent), at N = 4 and N = 64: the error
// falls as 1 / N, which images sharing samples (an N-sample image inside the reference) do not
// show.
TEST_F(EffectTest, MoreSamplesConvergeAsOneOverTheSampleCount) {
    const Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    vec3 q = op_repeat_limited(p, v3_splat(0.15f, 0.0f, 0.15f), v3_splat(8.0f, 0.0f, 4.0f));
    return sd_sphere(q, 0.05f);
}
)");
    auto plain = renderer(scene, 0);
    // 17 x 9 small balls at 384 x 256: many edge pixels, where most of the variance is.
    const auto samples = [&](int first, int count) {
        FrameRequest req = request(scene, {}, count);
        req.width = 384;
        req.height = 256;
        req.first_sample = first;
        return plain->render(req);
    };
    constexpr int kReference = 128;
    const Frame a = samples(1, kReference);  // sample 0, the unjittered centre, is left out
    const Frame b = samples(1 + kReference, kReference);
    ASSERT_GT(samples(0, 1).hits, 5000) << "hits are counted by sample 0 only";
    int next = 1 + 2 * kReference;
    double previous_error = 0.0;
    for (int count : {4, 64}) {
        const Frame image = samples(next, count);
        next += count;
        const double c = (double(kReference) / count + 1.0) / 2.0;
        double sum = 0.0, sum_squares = 0.0;
        long varying = 0;
        for (size_t pixel = 0; pixel * 3 < a.linear.size(); ++pixel) {
            double x = 0.0, reference_spread = 0.0;
            for (size_t i = 3 * pixel; i < 3 * pixel + 3; ++i) {
                const double d = double(image.linear[i]) - double(a.linear[i]);
                const double r = double(a.linear[i]) - double(b.linear[i]);
                x += d * d - c * r * r;
                reference_spread += r * r;
            }
            varying += reference_spread > 0.0;
            sum += x;
            sum_squares += x * x;
        }
        const double n = double(a.linear.size() / 3);
        const double mean = sum / n;
        const double standard_error = std::sqrt((sum_squares / n - mean * mean) / n);
        const double error = mean_squared_difference(image, a);
        std::printf(
            "%d spp: mse %.4g, excess over the 1/N prediction %.3g +- %.2g (%ld varying "
            "pixels)\n",
            count, error, mean, standard_error, varying);
        EXPECT_LT(std::abs(mean), 4.0 * standard_error) << count << " spp";
        ASSERT_GT(varying, 5000) << "too few pixels vary between samples to judge";
        if (previous_error > 0.0) {
            EXPECT_LT(error, previous_error / 4.0) << "16 times the samples";
        }
        previous_error = error;
    }
}

// ---------------------------------------------------------------------------------------------
// Specialisation and the colour pipeline.

TEST_F(EffectTest, ReflectionsWithNoMirrorsRenderTheSameImageAsWithout) {
    const Scene scene = mirror_scene();
    const FrameRequest req = request(scene, {"floor_mirror=0", "sphere_mirror=0"});
    const Frame plain = renderer(scene, 0)->render(req);
    const Frame reflecting = renderer(scene, FGR_EFFECT_REFLECTIONS)->render(req);
    EXPECT_EQ(reflecting.image.rgb, plain.image.rgb);
    EXPECT_EQ(reflecting.hits, plain.hits);
}

// IEC 61966-2-1: V = 12.92 L for L <= 0.0031308, else 1.055 L^(1/2.4) - 0.055; code round(255 V).
// Worked by hand (double precision): 0.001 -> 3.2946 -> 3; 0.0031308 -> 10.3147 -> 10 (the end
// of the linear segment); 0.18 (mid grey) -> 1.055 * 0.48945 - 0.055 = 0.46136 -> 117.646 -> 118;
// 0.5 -> 1.055 * 0.74915 - 0.055 = 0.73536 -> 187.516 -> 188; 0.9 -> 243.445 -> 243. A plain
// 2.2 gamma would give 19, 117 and 186 at 0.0031308, 0.18 and 0.5.
double srgb_code(double linear) {
    const double v =
        linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return 255.0 * v;
}

TEST(SrgbEncoding, MatchesTheStandardsValues) {
    const auto code_of = [](float linear) { return int(encode_srgb(linear)); };
    EXPECT_EQ(code_of(0.0f), 0);
    EXPECT_EQ(code_of(0.001f), 3);
    EXPECT_EQ(code_of(0.0031308f), 10);
    EXPECT_EQ(code_of(0.18f), 118);
    EXPECT_EQ(code_of(0.5f), 188);
    EXPECT_EQ(code_of(0.9f), 243);
    EXPECT_EQ(code_of(1.0f), 255);
    EXPECT_EQ(code_of(7.0f), 255);
    EXPECT_EQ(code_of(-0.25f), 0);
    EXPECT_EQ(code_of(std::nanf("")), 0);
    // Each code's own linear value (the standard's inverse) encodes to that code exactly.
    for (int code = 0; code <= 255; ++code) {
        const double v = code / 255.0;
        const double linear = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
        EXPECT_EQ(code_of(static_cast<float>(linear)), code) << "linear " << linear;
    }
    // Everywhere else within one code of the formula, and never decreasing. (encode_srgb looks
    // values up in a table of 4097 steps: half a step moves the curve by at most 0.41 codes, where
    // it is steepest, so values within 0.41 of a rounding boundary may land on the neighbour.)
    int previous = 0;
    for (int i = 0; i <= 100000; ++i) {
        const float linear = static_cast<float>(i) / 100000.0f;
        const int code = code_of(linear);
        ASSERT_LE(std::abs(code - srgb_code(linear)), 0.5 + 0.41) << "linear " << linear;
        ASSERT_GE(code, previous) << "linear " << linear;
        previous = code;
    }
}

TEST_F(EffectTest, ExposureAndToneMappingActAfterTheLinearImage) {
    EXPECT_FLOAT_EQ(tone_map(1.0f, ToneMap::Reinhard), 0.5f);
    EXPECT_FLOAT_EQ(tone_map(3.0f, ToneMap::Reinhard), 0.75f);
    EXPECT_FLOAT_EQ(tone_map(0.25f, ToneMap::Clamp), 0.25f);
    EXPECT_FLOAT_EQ(tone_map(4.0f, ToneMap::Clamp), 1.0f);
    EXPECT_NEAR(tone_map(1.0f, ToneMap::Aces), 0.80, 0.01);
    EXPECT_EQ(encode_srgb(tone_map(1.0f, ToneMap::Reinhard)), encode_srgb(0.5f));

    const Scene scene = test::sphere_scene();
    auto plain = renderer(scene, 0);
    const Frame base = plain->render(request(scene));
    const Frame bright = plain->render(request(scene, {"exposure=2"}));
    const Frame reinhard = plain->render(request(scene, {"tone_map=reinhard"}));
    const Frame aces = plain->render(request(scene, {"tone_map=aces"}));
    EXPECT_EQ(bright.linear, base.linear);  // exposure acts after the linear image
    long brighter = 0, total_base = 0, total_bright = 0;
    for (size_t i = 0; i < base.linear.size(); ++i) {
        const float value = base.linear[i];
        ASSERT_EQ(base.image.rgb[i], encode_srgb(std::min(value, 1.0f))) << i;
        ASSERT_EQ(bright.image.rgb[i], encode_srgb(std::min(2.0f * value, 1.0f))) << i;
        ASSERT_EQ(reinhard.image.rgb[i], encode_srgb(value / (1.0f + value))) << i;
        ASSERT_EQ(aces.image.rgb[i], encode_srgb(tone_map(value, ToneMap::Aces))) << i;
        ASSERT_GE(bright.image.rgb[i], base.image.rgb[i]) << i;
        brighter += bright.image.rgb[i] > base.image.rgb[i];
        total_base += base.image.rgb[i];
        total_bright += bright.image.rgb[i];
    }
    EXPECT_GT(brighter, static_cast<long>(base.linear.size()) * 9 / 10);
    EXPECT_GT(total_bright, total_base);
}

// ---------------------------------------------------------------------------------------------
// Refraction: a glass sphere in front of a wall that is red on the left (x < 0) and blue on the
// right, seen from the front. A sphere is a lens that flips what is behind it.

Scene glass_scene() {
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    return fmin(sd_sphere(p, 0.6f), sd_plane(p, v3_splat(0.0f, -1.0f, 0.0f), -1.5f));
}
#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    vec3 wall = v3_select(v3_splat(0.1f, 0.1f, 0.9f), v3_splat(0.9f, 0.1f, 0.1f), p.x < 0.0f);
    return v3_select(v3_splat(0.8f, 0.8f, 0.8f), wall, p.y > 1.0f);
}
#define FGR_SCENE_HAS_TRANSMISSION
real scene_transmission(vec3 p, PARAMS) {
    return select(fgr_real(0.0f), fgr_real(1.0f), p.y < 1.0f);  /* the sphere is clear glass */
}
)");
    scene.lights = {directional({0.0f, -1.0f, 0.3f})};
    return scene;
}

float redness_minus_blueness(const Frame& frame, int pixel) {
    const glm::vec3 rgb = pixel_rgb(frame, pixel);
    return rgb.r - rgb.b;
}

TEST_F(EffectTest, RefractionShowsWhatIsBehindTheGlassFlipped) {
    const Scene scene = glass_scene();
    auto plain = renderer(scene, 0);
    auto glass = renderer(scene, FGR_EFFECT_REFRACTION);
    const FrameRequest req = request(scene, {"absorption=0"});
    const Frame opaque = plain->render(req);
    const Frame clear_flat = glass->render(request(scene, {"absorption=0", "ior=1"}));
    const Frame lens = glass->render(req);
    // A pixel a little left of the sphere's centre, on the sphere in every image.
    const int left_of_centre =
        (kEffectsHeight / 2) * kEffectsWidth + kEffectsWidth / 2 - kEffectsWidth / 16;
    ASSERT_GT(opaque.depth[left_of_centre], 0.0f);
    ASSERT_LT(opaque.depth[left_of_centre], 3.0f);  // the sphere, not the wall
    // Opaque: the sphere's own grey. Index 1: rays pass straight through to the red wall half.
    // Index 1.5: the lens flips the view, so left of centre sees the blue half.
    EXPECT_NEAR(redness_minus_blueness(opaque, left_of_centre), 0.0f, 0.05f);
    EXPECT_GT(redness_minus_blueness(clear_flat, left_of_centre), 0.2f);
    EXPECT_LT(redness_minus_blueness(lens, left_of_centre), -0.2f);
    // The wall itself, seen beside the sphere, is untouched.
    EXPECT_EQ(pixel_rgb(lens, kEffectsWidth * 2), pixel_rgb(opaque, kEffectsWidth * 2));
    // Absorption darkens what is seen through the glass.
    const Frame absorbing = glass->render(request(scene, {"absorption=4"}));
    EXPECT_LT(glm::length(pixel_rgb(absorbing, left_of_centre)),
              glm::length(pixel_rgb(lens, left_of_centre)) * 0.8f);
}

// A bubble (index 0.6 against its surroundings) seen from outside: a ray meeting it at impact
// parameter b (distance from the centre to the ray's line) enters at sin(incidence) = b / R, so
// beyond b = 0.6 R light cannot enter at all (total internal reflection on the dense side) and the
// rim shows a ring with the surface's own colour, while the middle shows the wall behind.
TEST_F(EffectTest, ABubbleShowsATotalReflectionRingAtTheCriticalAngle) {
    const Scene scene = glass_scene();
    constexpr int width = 256, height = 192;
    constexpr float radius = 0.6f, ior = 0.6f;
    FrameRequest req = request(scene, {"absorption=0", "ior=0.6"});
    req.width = width;
    req.height = height;
    const Frame opaque = renderer(scene, 0)->render(req);
    const Frame bubble = renderer(scene, FGR_EFFECT_REFRACTION)->render(req);
    const CameraBasis basis = camera_basis(req.view);
    // Impact parameter per pixel in units of R, and how much it changes from pixel to pixel.
    const float b_step = float(glm::length(basis.eye)) * pixel_angle(basis, width) / radius;
    float ring_start = 2.0f;  // smallest b / R on the sphere where nothing passes
    int ring = 0, middle = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int pixel = y * width + x;
            if (opaque.depth[pixel] < 0.0f || opaque.depth[pixel] > 3.0f) continue;  // sphere only
            const glm::vec3 dir = primary_ray_direction(basis, width, height, float(x), float(y));
            const float b = glm::length(glm::cross(-glm::vec3(basis.eye), dir)) / radius;
            const bool same =
                glm::length(pixel_rgb(bubble, pixel) - pixel_rgb(opaque, pixel)) < 1e-5f;
            if (same) ring_start = std::min(ring_start, b);
            if (b > ior + 2.0f * b_step && b < 1.0f - 2.0f * b_step) {
                ++ring;
                EXPECT_TRUE(same) << "light passes at b/R " << b << " beyond the critical " << ior;
            } else if (b < ior - 2.0f * b_step) {
                ++middle;
                EXPECT_GT(glm::length(pixel_rgb(bubble, pixel) - pixel_rgb(opaque, pixel)), 0.01f)
                    << "no light passes at b/R " << b << " inside the critical " << ior;
            }
        }
    }
    ASSERT_GT(ring, 500);
    ASSERT_GT(middle, 500);
    // The measured inner edge of the ring lies at the critical angle, within two pixels.
    EXPECT_NEAR(ring_start, ior, 2.0f * b_step);
}

// A float as text that parses back to the same float (std::to_string keeps 6 decimals only).
std::string exact_text(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    return text;
}

int pixels_off_by_more_than_1_lsb(const Image8& a, const Image8& b) {
    int differ = 0;
    for (size_t i = 0; i < a.rgb.size(); i += 3) {
        for (size_t c = 0; c < 3; ++c) {
            if (std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])) > 1) {
                ++differ;
                break;
            }
        }
    }
    return differ;
}

// The same glass scene at 1/1000 of the size, camera and lengths (max distance, absorption per
// unit length) scaled with it, renders the same image: nothing in refraction is a length in
// scene units.
TEST_F(EffectTest, RefractionLooksTheSameAtAThousandthOfTheScale) {
    Scene scene = test::inline_scene(R"(
real glass_de(vec3 p) {
    return fmin(sd_sphere(p, 0.6f), sd_plane(p, v3_splat(0.0f, -1.0f, 0.0f), -1.5f));
}
real scene_de(vec3 p, PARAMS) { return param_scale * glass_de(v3_scale(p, 1.0f / param_scale)); }
#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    vec3 q = v3_scale(p, 1.0f / param_scale);
    vec3 wall = v3_select(v3_splat(0.1f, 0.1f, 0.9f), v3_splat(0.9f, 0.1f, 0.1f), q.x < 0.0f);
    return v3_select(v3_splat(0.8f, 0.8f, 0.8f), wall, q.y > 1.0f);
}
#define FGR_SCENE_HAS_TRANSMISSION
real scene_transmission(vec3 p, PARAMS) {
    return select(fgr_real(0.0f), fgr_real(1.0f), p.y < param_scale);
}
)");
    ParamInfo scale = float_param("scale", 1.0f);
    scene.params.insert(scene.params.begin(), scale);
    scene.lights = {directional({0.0f, -1.0f, 0.3f})};
    const auto render_at = [&](float s) {
        FrameRequest req =
            request(scene, {"absorption=" + exact_text(2.0f / s), "scale=" + exact_text(s),
                            "max_distance=" + exact_text(100.0f * s)});
        req.view.position *= s;
        req.view.target *= s;
        return renderer(scene, FGR_EFFECT_REFRACTION)->render(req);
    };
    const Frame full = render_at(1.0f);
    const Frame small = render_at(1e-3f);
    const int differ = pixels_off_by_more_than_1_lsb(full.image, small.image);
    EXPECT_LE(differ, int(full.image.rgb.size() / 3 / 100))
        << differ << " of " << full.image.rgb.size() / 3 << " pixels differ by more than 1 LSB";
}

// Every effect at 1/100000 of the scene's size (where a constant of 1e-6 units is as large as the
// offsets and steps it sits beside), with the camera, point lights and every length
// parameter (and per-length rate) scaled alike, renders the same image: no effect hides a
// length in scene units.
TEST_F(EffectTest, EveryEffectLooksTheSameAtAHundredThousandthOfTheScale) {
    Scene scene = test::inline_scene(R"(
real unit_de(vec3 p) {
    real ground = sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), -0.5f);
    real ball = sd_sphere(op_translate(p, v3_splat(0.3f, 0.2f, -0.1f)), 0.4f);
    real slab = sd_box(op_translate(p, v3_splat(-0.4f, -0.2f, 0.6f)), v3_splat(0.3f, 0.3f, 0.04f));
    return op_union(op_union(ground, ball), slab);
}
real scene_de(vec3 p, PARAMS) { return param_scale * unit_de(v3_scale(p, 1.0f / param_scale)); }
)");
    scene.params.insert(scene.params.begin(), float_param("scale", 1.0f));
    scene.cameras.front().view = view_from({0.4f, -2.2f, 1.1f}, {0.0f, 0.0f, -0.2f});
    struct Case {
        uint64_t effect;
        std::vector<std::pair<std::string, float>> lengths;  // parameter, value at scale 1
        int samples = 1;
    };
    const std::vector<Case> cases = {
        {FGR_EFFECT_SHADOWS, {}},
        {FGR_EFFECT_SOFT_SHADOWS, {}},
        {FGR_EFFECT_AMBIENT_OCCLUSION, {}},
        {FGR_EFFECT_SAMPLED_OCCLUSION, {{"ao_radius", 0.2f}}},
        {FGR_EFFECT_GLOW, {{"glow_radius", 0.1f}}},
        {FGR_EFFECT_FOG, {{"fog_density", 0.3f}}},
        {FGR_EFFECT_REFLECTIONS, {}},
        {FGR_EFFECT_DEPTH_OF_FIELD, {{"aperture", 0.05f}, {"focus_distance", 2.0f}}, 4},
    };
    const glm::vec3 point_light{-0.6f, -0.8f, 1.4f};
    for (const Case& c : cases) {
        SCOPED_TRACE(effect_names(c.effect));
        const auto render_at = [&](float s) {
            Scene scaled = scene;
            scaled.lights = {
                directional({0.3f, -0.4f, 1.0f}, 0.7f),
                Light{LightType::Point, point_light * s, {1.0f, 0.9f, 0.8f}, 0.8f * s * s}};
            std::vector<std::string> assignments = {"scale=" + exact_text(s),
                                                    "max_distance=" + exact_text(50.0f * s)};
            for (const auto& [id, value] : c.lengths) {
                const float scaled_value = id == "fog_density" ? value / s : value * s;
                assignments.push_back(id + "=" + exact_text(scaled_value));
            }
            FrameRequest req = request(scaled, assignments, c.samples);
            req.view.position *= s;
            req.view.target *= s;
            return renderer(scaled, c.effect)->render(req);
        };
        const Frame full = render_at(1.0f);
        const Frame small = render_at(1e-5f);
        ASSERT_GT(full.hits, kEffectsWidth * kEffectsHeight / 2);
        const int differ = pixels_off_by_more_than_1_lsb(full.image, small.image);
        EXPECT_LE(differ, kEffectsWidth * kEffectsHeight / 100)
            << differ << " of " << kEffectsWidth * kEffectsHeight
            << " pixels differ by more than 1 LSB";
    }
}

// Seen through the top face of a glass cube (index 1.5) nothing can leave through a side: a ray
// refracted in at the top meets a side at over 48 degrees, beyond the critical 41.8, so it is
// totally reflected and goes on inside until it leaves through the bottom. Every pixel of the top
// face therefore shows the red floor under the cube, never the blue floor around it or the
// inside of the glass.
TEST_F(EffectTest, TheTopOfAGlassCubeShowsOnlyWhatLiesUnderIt) {
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    real cube = sd_box(op_translate(p, v3_splat(0.0f, 0.0f, 0.55f)), v3_splat(0.5f, 0.5f, 0.5f));
    return fmin(cube, sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), 0.0f));
}
#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    (void)fgr_params;
    mask under = (fabs(p.x) < 0.6f) & (fabs(p.y) < 0.6f);
    vec3 floor_colour = v3_select(v3_splat(0.1f, 0.1f, 0.9f), v3_splat(0.9f, 0.1f, 0.1f), under);
    return v3_select(floor_colour, v3_splat(0.8f, 0.8f, 0.8f), p.z > 0.03f);
}
#define FGR_SCENE_HAS_TRANSMISSION
real scene_transmission(vec3 p, PARAMS) {
    (void)fgr_params;
    return select(fgr_real(0.0f), fgr_real(1.0f), p.z > 0.03f);
}
)");
    scene.cameras.front().view = view_from({0.0f, -2.2f, 2.6f}, {0.0f, 0.0f, 0.6f});
    scene.lights = {directional({0.2f, -0.3f, 1.0f})};
    FrameRequest req = request(scene, {"absorption=0", "ior=1.5"});
    const Frame glass = renderer(scene, FGR_EFFECT_REFRACTION)->render(req);
    const auto points = hit_points(glass, req.view);
    // The middle strip of the top face, |x| < 0.2, across its whole depth in y: rays refracted in
    // there run towards the far (+y) side and the bottom, and stay more than a hit footprint
    // (about 0.05 at that path length) from the x sides, whose edges a footprint-wide march and
    // normal stencil cannot resolve.
    const auto top = pixels_where(points, [](glm::vec3 p) {
        return std::abs(p.z - 1.05f) < 0.02f && std::abs(p.x) < 0.2f && std::abs(p.y) < 0.45f;
    });
    ASSERT_GT(top.size(), 80u);
    int not_red = 0;
    for (int pixel : top) not_red += redness_minus_blueness(glass, pixel) < 0.2f;
    EXPECT_EQ(not_red, 0) << "of " << top.size() << " top-face pixels do not show the red floor";
}

}  // namespace
}  // namespace fgr
