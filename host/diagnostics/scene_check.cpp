// SPDX-License-Identifier: Apache-2.0
// The checks of `fgr check` (diagnostics/scene_check.hpp). Each one measures, keeps the first
// problem it meets (and how many there were) and turns the measurement into advice for the scene's
// author. The tolerances are those of tests/diagnostics/test_scene_stability.cpp, which runs these
// same functions on every built scene; each check's comment says why its tolerance is what it is.
#include "diagnostics/scene_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>

#include "camera/camera.hpp"
#include "render/environment.hpp"
#include "scene/parameters.hpp"

namespace fgr {
namespace {

std::string point_text(glm::vec3 p) {
    return fmt::format("({:.4g}, {:.4g}, {:.4g})", p.x, p.y, p.z);
}

std::string value_text(float value) {
    if (std::isnan(value)) return "NaN";
    return std::isinf(value) ? (value > 0 ? "+Inf" : "-Inf") : fmt::format("{:g}", value);
}

// The largest step_factor, rounded down to hundredths, at which `ratio` (step_factor * something
// / what it may not exceed) would come down to `limit`.
std::string safe_step_factor(float step_factor, float ratio, float limit = 1.0f) {
    const float safe = std::floor(100.0f * step_factor * limit / ratio) / 100.0f;
    return fmt::format("{:.2f}", std::max(safe, 0.01f));
}

// The problems one check met: the first is described, the rest counted.
class Problems {
public:
    void add(const std::string& problem) {
        if (count_++ == 0) first_ = problem;
    }
    bool any() const { return count_ > 0; }
    std::string summary() const {
        return count_ == 1 ? first_ : fmt::format("{} (and {} more)", first_, count_ - 1);
    }

private:
    long count_ = 0;
    std::string first_;
};

// The first non-finite value of a render, described ("pixel (3, 7) is NaN"), or "".
std::string first_non_finite(const Frame& frame) {
    const int width = std::max(frame.image.width, 1);
    for (size_t i = 0; i < frame.linear.size(); ++i) {
        if (!std::isfinite(frame.linear[i])) {
            const long pixel = long(i / 3);
            return fmt::format("pixel ({}, {}) is {}", pixel % width, pixel / width,
                               value_text(frame.linear[i]));
        }
    }
    for (size_t i = 0; i < frame.depth.size(); ++i) {
        if (!std::isfinite(frame.depth[i])) {
            return fmt::format("the depth of pixel ({}, {}) is {}", long(i) % width,
                               long(i) / width, value_text(frame.depth[i]));
        }
    }
    return "";
}

const char* kNanAdvice =
    "a NaN or Inf comes from a division by zero, a log, sqrt or pow of zero or a negative number, "
    "or an overflow: guard the DE where that can happen (e.g. max(r, 1e-6f) before log(r), a "
    "bailout before the orbit overflows), or narrow the parameter's range";

// A DE that jumps (SceneChecker::lipschitz_sample tells a jump from a steep slope).
const char* kJumpAdvice =
    "the DE is discontinuous, which no step factor makes safe. In an iterated fractal that is "
    "the bailout stopping neighbouring points at different iterations, so their distances are "
    "measured at different depths: remove the bailout (FGR_ORBIT(n, FGR_NO_BAILOUT); a folding "
    "fractal such as a KIFS stays bounded without one) or run the same number of iterations in "
    "every lane";

CheckResult result(const std::string& name, const std::string& title) {
    CheckResult made;
    made.name = name;
    made.title = title;
    return made;
}

CheckResult& fail(CheckResult& made, const std::string& detail, const std::string& advice) {
    made.status = CheckStatus::Failed;
    made.detail = detail;
    made.advice = advice;
    return made;
}

CheckResult& pass(CheckResult& made, const std::string& detail) {
    made.status = CheckStatus::Passed;
    made.detail = detail;
    return made;
}

// `count` unit vectors spread evenly over the sphere (a Fibonacci lattice).
std::vector<glm::vec3> sphere_directions(int count) {
    std::vector<glm::vec3> directions;
    const float golden = 2.39996323f;  // pi (3 - sqrt 5)
    for (int i = 0; i < count; ++i) {
        const float z = 1.0f - 2.0f * (float(i) + 0.5f) / float(count);
        const float rho = std::sqrt(std::max(0.0f, 1.0f - z * z));
        directions.emplace_back(rho * std::cos(golden * float(i)),
                                rho * std::sin(golden * float(i)), z);
    }
    return directions;
}

// `count` unit vectors within `angle` radians of `axis`, spread evenly over that cap.
std::vector<glm::vec3> cap_directions(glm::vec3 axis, float angle, int count) {
    const glm::vec3 side = glm::normalize(glm::cross(axis, least_aligned_axis(axis)));
    const glm::vec3 other = glm::cross(axis, side);
    std::vector<glm::vec3> directions;
    const float golden = 2.39996323f;
    for (int i = 0; i < count; ++i) {
        const float polar = angle * std::sqrt((float(i) + 0.5f) / float(count));
        const float around = golden * float(i);
        directions.push_back(std::cos(polar) * axis + std::sin(polar) * (std::cos(around) * side +
                                                                         std::sin(around) * other));
    }
    return directions;
}

// The distance from each centre to the surface, measured without trusting the DE's size: along
// each of directions[c] the DE is sampled at 32 even steps out to 4 * steps[c]; the first sample
// inside the surface is bisected 14 times against the one before, and the nearest crossing over
// the directions is the centre's distance (infinity where no ray crossed within reach). "Inside"
// is DE <= steps[c] / 1000: inside a fractal the DE is not reliably negative (the Mandelbulb's is
// a tiny positive number where the orbit stays bounded above 1), and that level set lies within
// a thousandth of a step of the zero set for a 1-Lipschitz DE.
std::vector<float> surface_distance(Renderer& renderer, const std::vector<float>& params,
                                    const std::vector<glm::vec3>& centres,
                                    const std::vector<std::vector<glm::vec3>>& directions,
                                    const std::vector<float>& steps, glm::vec3* nearest_direction) {
    constexpr int kSamples = 32, kBisections = 14;
    constexpr float kReach = 4.0f, kInside = 1e-3f;
    struct Ray {
        size_t centre;
        glm::vec3 direction;
        float outside = 0.0f, inside = 0.0f;  // distances along the ray bracketing the crossing
    };
    std::vector<Ray> rays;
    std::vector<glm::vec3> points;
    for (size_t c = 0; c < centres.size(); ++c) {
        for (const glm::vec3& d : directions[c]) {
            rays.push_back({c, d});
            for (int k = 1; k <= kSamples; ++k) {
                points.push_back(centres[c] + d * (kReach * steps[c] * float(k) / kSamples));
            }
        }
    }
    const std::vector<float> samples = renderer.probe_de(points, params);
    std::vector<size_t> crossing;  // rays that went inside within reach
    for (size_t r = 0; r < rays.size(); ++r) {
        const float step = steps[rays[r].centre];
        for (int k = 1; k <= kSamples; ++k) {
            if (samples[r * kSamples + size_t(k - 1)] <= kInside * step) {
                rays[r].outside = kReach * step * float(k - 1) / kSamples;
                rays[r].inside = kReach * step * float(k) / kSamples;
                crossing.push_back(r);
                break;
            }
        }
    }
    for (int i = 0; i < kBisections && !crossing.empty(); ++i) {
        std::vector<glm::vec3> middles;
        for (size_t r : crossing) {
            const Ray& ray = rays[r];
            middles.push_back(centres[ray.centre] +
                              ray.direction * (0.5f * (ray.outside + ray.inside)));
        }
        const std::vector<float> middle_de = renderer.probe_de(middles, params);
        for (size_t j = 0; j < crossing.size(); ++j) {
            Ray& ray = rays[crossing[j]];
            const bool inside = middle_de[j] <= kInside * steps[ray.centre];
            (inside ? ray.inside : ray.outside) = 0.5f * (ray.outside + ray.inside);
        }
    }
    std::vector<float> nearest(centres.size(), std::numeric_limits<float>::infinity());
    for (size_t r : crossing) {
        const Ray& ray = rays[r];
        if (ray.inside < nearest[ray.centre]) {
            nearest[ray.centre] = ray.inside;
            if (nearest_direction) nearest_direction[ray.centre] = ray.direction;
        }
    }
    return nearest;
}

// How two renders of the same request differ, pixel by pixel.
struct PixelDifference {
    int largest = 0;           // the largest difference of one 8-bit channel
    long over_one = 0;         // pixels with a channel more than 1 level apart
    long hit_mismatch = 0;     // pixels hit in one and missed in the other
    long first_over_one = -1;  // the first such pixel (row-major), -1 if none
};

PixelDifference pixel_difference(const Frame& a, const Frame& b) {
    PixelDifference d;
    for (size_t pixel = 0; pixel < a.depth.size(); ++pixel) {
        int worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            worst = std::max(
                worst, std::abs(int(a.image.rgb[3 * pixel + c]) - int(b.image.rgb[3 * pixel + c])));
        }
        d.largest = std::max(d.largest, worst);
        if (worst > 1) {
            if (d.over_one == 0) d.first_over_one = long(pixel);
            ++d.over_one;
        }
        d.hit_mismatch += (a.depth[pixel] >= 0.0f) != (b.depth[pixel] >= 0.0f);
    }
    return d;
}

}  // namespace

bool SceneCheckReport::passed() const {
    return std::none_of(results.begin(), results.end(),
                        [](const CheckResult& r) { return r.status == CheckStatus::Failed; });
}

const std::vector<std::string>& scene_check_names() {
    static const std::vector<std::string> names{
        "hard-points",       "hard-cameras",    "parameter-extremes",
        "lipschitz",         "march-safety",    "packet-agreement",
        "de-pair",           "normals-at-hits", "relaxed-steps",
        "cameras-and-paths", "default-view"};
    return names;
}

SceneChecker::SceneChecker(const ComputeDevice& device, ProgramCache& cache, const Scene& scene,
                           int packet_width, std::vector<float> params)
    : device_(device),
      cache_(cache),
      scene_(scene),
      params_(params.empty() ? default_param_values(scene) : std::move(params)) {
    if (params_.size() != default_param_values(scene).size()) {
        throw std::invalid_argument(
            fmt::format("scene '{}': {} parameter values for a buffer of {}", scene.id,
                        params_.size(), default_param_values(scene).size()));
    }
    // An inside-only scene renders only by brute force.
    const RenderMode mode = scene.inside_only() ? RenderMode::Brute : RenderMode::Shaded;
    const int width = packet_width > 0 ? packet_width : preferred_packet_width(device.info);
    renderer_ = std::make_unique<Renderer>(
        device, cache, scene, KernelSwitches{width, scene.effects, false, false, mode});
}

SceneChecker::~SceneChecker() = default;

Frame SceneChecker::render(const CameraView& view, const std::vector<float>& params, int width,
                           int height) {
    return renderer_->render(FrameRequest{width, height, view, params});
}

// Points around the default camera's target, within the camera's distance of it: the region the
// default view looks at, and everything between it and the camera.
std::vector<glm::vec3> SceneChecker::region_points(int count, unsigned seed) const {
    const CameraView& view = scene_.cameras.front().view;
    const float radius = float(glm::length(view.position - view.target));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> points;
    for (int i = 0; i < count; ++i) {
        points.push_back(glm::vec3(view.target) +
                         radius * glm::vec3(unit(rng), unit(rng), unit(rng)));
    }
    return points;
}

std::optional<CheckResult> SceneChecker::skip_without_de(const std::string& name,
                                                         const std::string& title) {
    if (!scene_.inside_only()) return std::nullopt;
    CheckResult skipped = result(name, title);
    skipped.status = CheckStatus::Skipped;
    skipped.detail = "the scene is inside-only: it has no distance estimator";
    return skipped;
}

CheckResult SceneChecker::finite_at_hard_points() {
    const std::string name = "hard-points", title = "DE and normal finite at hard points";
    if (auto skipped = skip_without_de(name, title)) return *skipped;
    CheckResult made = result(name, title);
    const auto& checked = params_;
    const CameraView& view = scene_.cameras.front().view;
    const std::vector<glm::vec3> points{
        {0, 0, 0},          {-0.0f, -0.0f, -0.0f}, {1, 0, 0},     {0, 1, 0},    {0, 0, 1},
        {0, 0, -1},         {1e6f, 0, 0},          {0, -1e6f, 0}, {0, 0, 1e6f}, {1e6f, 1e6f, 1e6f},
        {-1e12f, 1e12f, 0}, {1e-30f, 0, 0},        view.position, view.target};
    const auto distances = renderer_->probe_de(points, checked);
    const auto normals = renderer_->probe_normals(points, checked, 1e-4f);
    Problems problems;
    for (size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(distances[i])) {
            problems.add(
                fmt::format("DE is {} at {}", value_text(distances[i]), point_text(points[i])));
        }
        const glm::vec3& n = normals[i];
        if (!(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z))) {
            problems.add(fmt::format("the normal is not finite at {}", point_text(points[i])));
        }
    }
    if (problems.any())
        return fail(made, problems.summary() + " (at the checked parameters)", kNanAdvice);
    return pass(made, fmt::format("{} points, including the origin and 1e12", points.size()));
}

CheckResult SceneChecker::finite_for_hard_cameras() {
    CheckResult made = result("hard-cameras", "renders finite from hard camera placements");
    const auto& checked = params_;
    const CameraView& home = scene_.cameras.front().view;
    Problems problems;
    const auto expect_finite = [&](const Frame& frame, const std::string& what) {
        if (const std::string problem = first_non_finite(frame); !problem.empty()) {
            problems.add(what + ": " + problem);
        }
    };
    CameraView inside = home;  // at the origin: inside most fractals, looking outwards
    inside.position = {0.0f, 0.0f, 0.0f};
    inside.target = {1.0f, 0.3f, 0.2f};
    expect_finite(render(inside, checked), "camera at the origin");
    CameraView through_origin = home;  // the centre pixel's ray passes exactly through 0
    through_origin.target = {0.0f, 0.0f, 0.0f};
    expect_finite(render(through_origin, checked, 33, 33), "ray through the origin");
    CameraView grazing = home;  // a narrow view along the silhouette
    const glm::vec3 side =
        glm::normalize(glm::cross(glm::vec3(home.target - home.position), home.up));
    grazing.target =
        home.target + glm::dvec3(side) * glm::length(home.target - home.position) * 0.5;
    grazing.fov_degrees = 5.0f;
    expect_finite(render(grazing, checked), "grazing view");
    CameraView far_away = home;
    far_away.position = home.target + (home.position - home.target) * 1000.0;
    expect_finite(render(far_away, checked), "distant camera");
    if (problems.any()) return fail(made, problems.summary(), kNanAdvice);
    return pass(made, "camera at the origin, a ray through it, grazing, 1000x away");
}

CheckResult SceneChecker::finite_at_parameter_extremes() {
    CheckResult made = result("parameter-extremes", "finite at every parameter's extremes");
    const bool probe_de = !scene_.inside_only();
    const auto offsets = param_offsets(scene_);
    Problems problems;
    int settings = 0;
    for (size_t i = 0; i < scene_.params.size(); ++i) {
        const ParamInfo& param = scene_.params[i];
        for (float extreme : {param.min_value, param.max_value}) {
            std::vector<float> values = params_;
            for (int c = 0; c < param_components(param.type); ++c) values[offsets[i] + c] = extreme;
            const std::string what = fmt::format("with {} = {:g}", param.id, extreme);
            ++settings;
            const std::string pixel =
                first_non_finite(render(scene_.cameras.front().view, values, 24, 16));
            if (!pixel.empty()) problems.add(fmt::format("{} {} (default view)", pixel, what));
            if (!probe_de) continue;
            const std::vector<glm::vec3> origin{{0, 0, 0}, {0.5f, 0.5f, 0.5f}};
            const auto distances = renderer_->probe_de(origin, values);
            for (size_t p = 0; p < origin.size(); ++p) {
                if (!std::isfinite(distances[p])) {
                    problems.add(fmt::format("DE is {} at {} {}", value_text(distances[p]),
                                             point_text(origin[p]), what));
                }
            }
        }
    }
    if (problems.any()) return fail(made, problems.summary(), kNanAdvice);
    return pass(made, fmt::format("{} settings of {} parameters{}", settings, scene_.params.size(),
                                  probe_de ? ", DE at 2 points each" : ""));
}

// Pairs of points around the default view, 1e-3 to 10^-0.5 of the camera's distance apart.
// The march advances step_factor * DE, so that is what must not grow faster than the distance.
//
// Where it does, the pairs over the bound (the worst kJumpPairs of them) are told apart: a DE that
// is steep, with Lipschitz constant L however large, differs across a pair by at most L times
// their distance, so halving the pair (kept on the side where the DE changes more) halves the
// difference; a DE that jumps, taking different values on the two sides of a surface, differs by
// as much however close the points get. After kHalvings halvings (1/1024 of the distance) a steep
// pair keeps about 1/1024 of its difference, and a pair keeping 1/8 of it or more is a jump: the
// DE would have to be 128 times steeper there than on average across the pair to look like one.
// Iterated fractals jump where a bailout stops neighbouring points at different iterations, and
// measures their distance at different depths; no step factor makes a jump safe.
const SceneChecker::LipschitzSample& SceneChecker::lipschitz_sample() {
    if (lipschitz_sample_) return *lipschitz_sample_;
    constexpr size_t kJumpPairs = 64;
    constexpr int kHalvings = 10;
    LipschitzSample& sample = lipschitz_sample_.emplace();
    const auto& checked = params_;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const auto first = region_points(3000, 5);
    const CameraView& view = scene_.cameras.front().view;
    const float radius = float(glm::length(view.position - view.target));
    std::vector<glm::vec3> second;
    for (const auto& p : first) {
        const glm::vec3 direction =
            glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + 1e-6f);
        const float step = radius * std::pow(10.0f, -3.0f + 2.5f * (unit(rng) + 1.0f) * 0.5f);
        second.push_back(p + direction * step);
    }
    const auto de_first = renderer_->probe_de(first, checked);
    const auto de_second = renderer_->probe_de(second, checked);
    sample.step_factor = param_value(scene_, checked, "step_factor");
    sample.pairs = first.size();
    // Inside the set a DE's value is not a distance (the march stops there): compare the
    // distances to the set, max(DE, 0).
    const auto outside = [](float de) { return std::max(de, 0.0f); };
    std::vector<std::pair<float, size_t>> over;  // (ratio, pair) over the bound
    for (size_t i = 0; i < first.size(); ++i) {
        if (!std::isfinite(de_first[i]) || !std::isfinite(de_second[i])) {
            const bool first_bad = !std::isfinite(de_first[i]);
            sample.non_finite =
                fmt::format("DE is {} at {}", value_text(first_bad ? de_first[i] : de_second[i]),
                            point_text(first_bad ? first[i] : second[i]));
            return sample;
        }
        const float separation = glm::length(first[i] - second[i]);
        const float ratio = sample.step_factor *
                            std::abs(outside(de_first[i]) - outside(de_second[i])) / separation;
        if (ratio > sample.worst) {
            sample.worst = ratio;
            sample.worst_near = first[i];
        }
        // Float rounding of two DE values near |p| ~ radius allows a small absolute slack.
        if (ratio > 1.02f + 2e-6f * radius / separation) over.emplace_back(ratio, i);
    }
    sample.violations = long(over.size());
    std::sort(over.begin(), over.end(), std::greater<>());
    const size_t examined = std::min(over.size(), kJumpPairs);
    std::vector<glm::vec3> a, b;
    std::vector<float> da, db, start;
    for (size_t k = 0; k < examined; ++k) {
        const size_t i = over[k].second;
        a.push_back(first[i]);
        b.push_back(second[i]);
        da.push_back(outside(de_first[i]));
        db.push_back(outside(de_second[i]));
        start.push_back(std::abs(da.back() - db.back()));
    }
    for (int h = 0; h < kHalvings && examined > 0; ++h) {
        std::vector<glm::vec3> middles;
        for (size_t k = 0; k < examined; ++k) middles.push_back(0.5f * (a[k] + b[k]));
        const auto de_middle = renderer_->probe_de(middles, checked);
        for (size_t k = 0; k < examined; ++k) {
            const float dm = std::isfinite(de_middle[k]) ? outside(de_middle[k]) : da[k];
            if (std::abs(da[k] - dm) >= std::abs(dm - db[k])) {
                b[k] = middles[k], db[k] = dm;
            } else {
                a[k] = middles[k], da[k] = dm;
            }
        }
    }
    // The pairs not examined are less steep than these, and taken to be of the same kinds.
    sample.examined = long(examined);
    for (size_t k = 0; k < examined; ++k) {
        const float kept = std::abs(da[k] - db[k]);
        if (kept >= start[k] / 8.0f) {
            ++sample.jumps;
            if (kept > sample.largest_jump) {
                sample.largest_jump = kept;
                sample.jump_near = 0.5f * (a[k] + b[k]);
            }
        } else {
            sample.worst_steep = std::max(sample.worst_steep, over[k].first);
        }
    }
    return sample;
}

std::string SceneChecker::jump_text() {
    const LipschitzSample& sample = lipschitz_sample();
    return fmt::format(
        "the DE jumps by up to {:.3g} near {} ({} of the {} worst pairs still differ by over "
        "an eighth as much 1024 times closer: a discontinuity, not a steep slope)",
        sample.largest_jump, point_text(sample.jump_near), sample.jumps, sample.examined);
}

std::string SceneChecker::step_factor_advice(const std::string& step_advice) {
    const LipschitzSample& sample = lipschitz_sample();
    if (sample.jumps == 0) return step_advice;
    if (sample.jumps == sample.examined) return kJumpAdvice;
    return std::string(kJumpAdvice) + "; then, where the DE is steep rather than broken, " +
           step_advice;
}

CheckResult SceneChecker::lipschitz() {
    const std::string name = "lipschitz",
                      title = "DE is 1-Lipschitz (grows no faster than distance)";
    if (auto skipped = skip_without_de(name, title)) return *skipped;
    CheckResult made = result(name, title);
    const LipschitzSample& sample = lipschitz_sample();
    if (!sample.non_finite.empty()) return fail(made, sample.non_finite, kNanAdvice);
    const float step_factor = sample.step_factor;
    const std::string measured = fmt::format(
        "largest step_factor * |dDE| / |dp| = {:.3f} over {} pairs", sample.worst, sample.pairs);
    if (sample.violations > 0) {
        std::string detail = fmt::format(
            "{}: the DE changes up to {:.2f}x faster than distance near {} ({} pairs over 1.02)",
            measured, sample.worst, point_text(sample.worst_near), sample.violations);
        if (sample.jumps > 0) detail += "; " + jump_text();
        // Where the DE only jumps, the step factor that would be safe is that of its steep parts.
        const float steep = sample.jumps > 0 ? sample.worst_steep : sample.worst;
        return fail(
            made, detail,
            step_factor_advice(fmt::format("set step_factor <= {} (now {:g}), or fix the "
                                           "DE's derivative estimate",
                                           safe_step_factor(step_factor, steep), step_factor)));
    }
    return pass(made, measured);
}

// The march steps step_factor * DE from any point outside the surface, so nothing inside may lie
// nearer than that: step_factor * DE <= the true distance to the surface. The true distance is
// measured by bisection along rays (surface_distance): 128 directions spread over the sphere (at
// most 0.2 rad from any direction, which overstates a flat surface's distance by 2%), then 48
// more within 0.25 rad of the nearest crossing found (0.04 rad apart: 0.1%). The centres are
// points of the default view's region and points in front of its hits (1/300, 1/30 and 1/3 of the
// way back to the camera), where the march takes its last steps. Allowed: 1% (the inside level
// 0.1% of a step, bisection to 2^-19 of the reach, float rounding of probe points under 0.2% for
// steps over 1e-4 of the view's scale). A DE 10% too large fails in every scene whose
// step_factor * DE comes within 8% of the truth somewhere (exact DEs at step factor 1 reach 1.00;
// a scene with a lower step factor keeps its margin).
CheckResult SceneChecker::march_safety() {
    const std::string name = "march-safety",
                      title = "march steps never reach the surface (DE measured by bisection)";
    if (auto skipped = skip_without_de(name, title)) return *skipped;
    CheckResult made = result(name, title);
    const auto& checked = params_;
    const float step_factor = param_value(scene_, checked, "step_factor");
    const CameraView& view = scene_.cameras.front().view;
    const float radius = float(glm::length(view.position - view.target));
    std::vector<glm::vec3> candidates = region_points(120, 21);
    {
        constexpr int width = 48, height = 32;
        const Frame frame = render(view, checked, width, height);
        const CameraBasis basis = camera_basis(view);
        for (int pixel = 0; pixel < width * height; pixel += 7) {
            const float t = frame.depth[size_t(pixel)];
            if (t < 0.0f) continue;
            const glm::vec3 dir = primary_ray_direction(basis, width, height, float(pixel % width),
                                                        float(pixel / width));
            for (float back : {1.0f / 300.0f, 1.0f / 30.0f, 1.0f / 3.0f}) {
                candidates.push_back(glm::vec3(basis.eye) + dir * (t * (1.0f - back)));
            }
        }
    }
    const auto de = renderer_->probe_de(candidates, checked);
    std::vector<glm::vec3> centres;
    std::vector<float> steps;
    for (size_t i = 0; i < candidates.size(); ++i) {
        if (de[i] * step_factor > 1e-4f * radius) {
            centres.push_back(candidates[i]);
            steps.push_back(de[i] * step_factor);
        }
    }
    if (centres.size() <= 100u) {
        const long not_finite =
            std::count_if(de.begin(), de.end(), [](float d) { return !std::isfinite(d); });
        const std::string detail = fmt::format(
            "only {} points of the default view are outside the surface (at least "
            "101 needed to judge)",
            centres.size());
        if (not_finite > 0) {
            return fail(made,
                        fmt::format("{}: the DE is not finite at {} of {} points", detail,
                                    not_finite, de.size()),
                        kNanAdvice);
        }
        return fail(made, detail,
                    "the default camera should look at the fractal from outside it, with the "
                    "fractal filling part of the view; check the DE is positive outside");
    }
    const std::vector<std::vector<glm::vec3>> everywhere(centres.size(), sphere_directions(128));
    std::vector<glm::vec3> best(centres.size());
    std::vector<float> distance =
        surface_distance(*renderer_, checked, centres, everywhere, steps, best.data());
    std::vector<std::vector<glm::vec3>> around;
    for (size_t c = 0; c < centres.size(); ++c) {
        around.push_back(std::isfinite(distance[c]) ? cap_directions(best[c], 0.25f, 48)
                                                    : std::vector<glm::vec3>{});
    }
    const std::vector<float> refined =
        surface_distance(*renderer_, checked, centres, around, steps, nullptr);
    std::vector<float> ratios;
    float worst = 0.0f;
    size_t worst_centre = 0;
    for (size_t c = 0; c < centres.size(); ++c) {
        distance[c] = std::min(distance[c], refined[c]);
        if (!std::isfinite(distance[c])) continue;  // the surface is over 4 steps away
        ratios.push_back(steps[c] / distance[c]);
        if (ratios.back() > worst) {
            worst = ratios.back();
            worst_centre = c;
        }
    }
    if (ratios.size() < 50u) {
        return fail(made,
                    fmt::format("only {} of {} points see the surface within 4 march steps (at "
                                "least 50 needed to judge)",
                                ratios.size(), centres.size()),
                    "the DE may be far too small (the march would crawl): check it approaches "
                    "the distance to the surface");
    }
    std::nth_element(ratios.begin(), ratios.begin() + long(ratios.size() / 2), ratios.end());
    const std::string measured = fmt::format(
        "step_factor {:.2f}: step / distance to the surface largest {:.4f}, median {:.4f} over "
        "{} points",
        step_factor, worst, ratios[ratios.size() / 2], ratios.size());
    if (worst > 1.01f) {
        return fail(
            made,
            fmt::format("DE overestimates by up to {:.2f}x near {} (step {:.3g}, surface "
                        "at {:.3g}); {}",
                        worst, point_text(centres[worst_centre]), steps[worst_centre],
                        distance[worst_centre], measured),
            step_factor_advice(fmt::format("set step_factor <= {} (now {:g}) in "
                                           "FGR_MARCH, or make the DE smaller where it "
                                           "overestimates",
                                           safe_step_factor(step_factor, worst), step_factor)));
    }
    return pass(made, measured);
}

// The GPU layout (one ray per work-item) compiles the same scene source without packets: it must
// render the same picture as the CPU's packets, pixel for pixel within one 8-bit level (rounding
// of the same maths in another order), the same pixels hit, at a size whose partial right and
// bottom tiles (41 = 10 x 4 + 1, 30 = 7 x 4 + 2 for 4x4 tiles) are on the image.
CheckResult SceneChecker::packet_agreement() {
    CheckResult made = result("packet-agreement", "one ray per work-item renders the same image");
    const int width = renderer_->switches().packet_width;
    if (scene_.inside_only()) {
        made.status = CheckStatus::Skipped;
        made.detail = "the brute mode of an inside-only scene samples randomly";
        return made;
    }
    Renderer scalar(device_, cache_, scene_, KernelSwitches{1, scene_.effects});
    const FrameRequest request{41, 30, scene_.cameras.front().view, params_};
    const Frame one = scalar.render(request);
    const Frame packets = renderer_->render(request);
    const PixelDifference d = pixel_difference(one, packets);
    const std::string measured = fmt::format(
        "width 1 vs {}: largest difference {} levels, {} pixels over 1 level, {} "
        "hit in one and missed in the other",
        width, d.largest, d.over_one, d.hit_mismatch);
    if (d.hit_mismatch > 0 || d.over_one > 0) {
        const long first = d.first_over_one;
        return fail(made,
                    measured + (first >= 0 ? fmt::format(" (first at pixel ({}, {}))", first % 41,
                                                         first / 41)
                                           : ""),
                    "the scene's code treats the lanes of a packet differently from single rays: "
                    "use the per-lane helpers (fgr_any, select, the v3_* functions) instead of "
                    "branching on one lane's value");
    }
    return pass(made, measured);
}

// A scene's own scene_de_pair gives each point exactly what scene_de gives it, as the first point
// of a pair and as the second, at points around the default view: each packet is paired with one
// half the points away, so that the two orbits escape at different iterations.
CheckResult SceneChecker::de_pair() {
    const std::string name = "de-pair", title = "scene_de_pair gives what scene_de gives";
    if (auto skipped = skip_without_de(name, title)) return *skipped;
    CheckResult made = result(name, title);
    if (scene_.ifs || !scene_.pairs_distances()) {
        made.status = CheckStatus::Skipped;
        made.detail = "the scene gives no scene_de_pair of its own";
        return made;
    }
    const std::vector<glm::vec3> points = region_points(4096, 31);
    const std::vector<float> alone = renderer_->probe_de(points, params_);
    const PairedDistances paired = renderer_->probe_de_pairs(points, params_);
    const auto same = [](float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    long differing = 0;
    size_t first = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        if (!same(paired.first[i], alone[i]) || !same(paired.second[i], alone[i])) {
            if (differing++ == 0) first = i;
        }
    }
    if (differing > 0) {
        return fail(made,
                    fmt::format("{} of {} points get another DE from scene_de_pair than from "
                                "scene_de (first at {}: {} as the first of a pair, {} as the "
                                "second, against {})",
                                differing, points.size(), point_text(points[first]),
                                value_text(paired.first[first]), value_text(paired.second[first]),
                                value_text(alone[first])),
                    "give each lane what scene_de gives it: iterate each point's orbit under "
                    "its own lanes' mask, and let the orbit still going when the other is done "
                    "finish its iterations alone");
    }
    return pass(made, fmt::format("{} points, each the first of one pair and the second of another",
                                  points.size()));
}

// Wherever a primary ray hits, the shading normal (the kernel's own stencil and eps) is finite and
// of unit length. The probe points are the hits themselves: each pixel's centre ray (the ray
// sample 0 traced) at the pixel's depth, so the DE there is under the hit footprint, as the march
// found it (1% slack for the host's and the kernel's float rounding of the ray).
CheckResult SceneChecker::normals_at_hits() {
    const std::string name = "normals-at-hits", title = "the normal at every hit is a unit vector";
    if (auto skipped = skip_without_de(name, title)) return *skipped;
    CheckResult made = result(name, title);
    if (scene_.ifs) {
        made.status = CheckStatus::Skipped;
        made.detail = "an IFS scene has no distance estimate to take normals from";
        return made;
    }
    const auto& checked = params_;
    const CameraView& view = scene_.cameras.front().view;
    const int width = 64, height = 48;
    const Frame frame = render(view, checked, width, height);
    const CameraBasis basis = camera_basis(view);
    const float pixel = pixel_angle(basis, width);
    const float footprint = param_value(scene_, checked, "hit_threshold") * pixel;
    std::vector<glm::vec3> hits;
    std::vector<float> depths;
    float eps = 1.0f;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float t = frame.depth[static_cast<size_t>(y * width + x)];
            if (t < 0.0f) continue;
            // Pixel (x, y): primary_ray_direction adds the half pixel to reach its centre.
            const glm::vec3 direction =
                primary_ray_direction(basis, width, height, float(x), float(y));
            hits.push_back(glm::vec3(basis.eye) + direction * t);
            depths.push_back(t);
            eps = std::min(eps, std::max(t * pixel * 0.5f, 1e-7f));
        }
    }
    if (hits.size() <= 20u) {
        return fail(made,
                    fmt::format("only {} of {} pixels of the default view hit", hits.size(),
                                width * height),
                    "point the default camera at the fractal (if the DE is NaN, see the "
                    "hard-points check: no ray ever stops)");
    }
    // Each hit is probed in a packet of copies of itself, so a scene that skips an object for a
    // whole packet of far lanes takes the same shortcuts here as the march could.
    const size_t lanes = static_cast<size_t>(renderer_->switches().packet_width);
    std::vector<glm::vec3> copies;
    for (const glm::vec3& hit : hits) copies.insert(copies.end(), lanes, hit);
    const auto distances = renderer_->probe_de(copies, checked);
    for (size_t i = 0; i < hits.size(); ++i) {
        if (!(std::abs(distances[i * lanes]) < 1.01f * footprint * depths[i])) {
            return fail(made,
                        fmt::format("the DE at the hit {} (depth {:.4g}) is {}, over the hit "
                                    "footprint {:.3g}: the probe and the march disagree",
                                    point_text(hits[i]), depths[i],
                                    value_text(distances[i * lanes]), footprint * depths[i]),
                        "the DE must depend only on the point and the parameters (no state kept "
                        "between calls, nothing read from other lanes)");
        }
    }
    const auto normals = renderer_->probe_normals(hits, checked, eps);
    for (size_t i = 0; i < hits.size(); ++i) {
        const glm::vec3& n = normals[i];
        const bool finite = std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);
        if (!finite || std::abs(glm::length(n) - 1.0f) > 1e-3f) {
            return fail(
                made,
                fmt::format("the normal at the hit {} is ({}, {}, {})", point_text(hits[i]),
                            value_text(n.x), value_text(n.y), value_text(n.z)),
                std::string("the DE is not finite or is flat around the hit; ") + kNanAdvice);
        }
    }
    return pass(made, fmt::format("{} hits of a {}x{} view", hits.size(), width, height));
}

// Neither the scene's step factor nor over-relaxation opens holes or lands inside the surface:
// against a cautious plain march (steps of half the scene's step factor, at most 0.5 DE, four
// times the steps) the hit/miss verdict
// agrees on at least 99.5% of pixels, and where both hit, at least 99% of depths agree within
// four pixel footprints (a step that jumped over a thin part would stop behind it, deeper), at
// the checked values, at over-relaxation 1.5 and at the largest allowed, 1.95.
CheckResult SceneChecker::relaxed_steps() {
    const std::string name = "relaxed-steps",
                      title = "the march agrees with a cautious one (no holes, no overshoot)";
    if (auto skipped = skip_without_de(name, title)) return *skipped;
    CheckResult made = result(name, title);
    const auto& checked = params_;
    const CameraView& view = scene_.cameras.front().view;
    // Half the scene's own step factor (a scene that already steps 0.45 DE needs a march finer
    // than that to check against), never over 0.5 nor under the parameter's range.
    const float cautious_step =
        std::max(scene_.find_param("step_factor")->min_value,
                 std::min(0.5f, 0.5f * param_value(scene_, checked, "step_factor")));
    auto cautious_params = checked;
    set_param_from_text(scene_, cautious_params, fmt::format("step_factor={}", cautious_step));
    set_param_from_text(scene_, cautious_params, "over_relaxation=1");
    const int max_steps = int(param_value(scene_, checked, "max_steps"));
    set_param_from_text(scene_, cautious_params,
                        "max_steps=" + std::to_string(std::min(4 * max_steps, 4096)));
    const Frame cautious = render(view, cautious_params, 96, 72);
    // Hits are within hit_threshold * pixel_angle * t of the surface.
    const float footprint =
        param_value(scene_, checked, "hit_threshold") * pixel_angle(camera_basis(view), 96);
    Problems problems;
    std::string measured;
    for (const char* relaxation : {"", "over_relaxation=1.5", "over_relaxation=1.95"}) {
        auto params = checked;
        if (*relaxation) set_param_from_text(scene_, params, relaxation);
        const Frame relaxed = render(view, params, 96, 72);
        const std::string what = *relaxation
                                     ? relaxation
                                     : fmt::format("over_relaxation={:g}",
                                                   param_value(scene_, checked, "over_relaxation"));
        long disagree = 0, both = 0, deeper = 0;
        for (size_t i = 0; i < relaxed.depth.size(); ++i) {
            const float t = relaxed.depth[i], t_cautious = cautious.depth[i];
            disagree += (t >= 0.0f) != (t_cautious >= 0.0f);
            if (t < 0.0f || t_cautious < 0.0f) continue;
            ++both;
            deeper += std::abs(t - t_cautious) > 4.0f * footprint * t_cautious;
        }
        const long pixels = long(relaxed.depth.size());
        measured += fmt::format("{}{}: {} of {} pixels disagree, {} of {} depths differ",
                                measured.empty() ? "" : "; ", what, disagree, pixels, deeper, both);
        if (double(disagree) > 0.005 * double(pixels)) {
            problems.add(
                fmt::format("at {}, {} of {} pixels hit in one march and miss in the "
                            "other (0.5% allowed)",
                            what, disagree, pixels));
        }
        if (double(deeper) > 0.01 * double(both)) {
            problems.add(
                fmt::format("at {}, {} of {} depths differ by over 4 pixel footprints "
                            "(1% allowed)",
                            what, deeper, both));
        }
    }
    if (problems.any()) {
        const float step_factor = param_value(scene_, checked, "step_factor");
        return fail(made, problems.summary(),
                    step_factor_advice(
                        fmt::format("the DE overestimates in places the march jumps over: lower "
                                    "step_factor (now {:g}; `fgr check` measures a safe one under "
                                    "march-safety) or make the DE smaller there",
                                    step_factor)));
    }
    return pass(made, measured);
}

CheckResult SceneChecker::cameras_and_paths() {
    CheckResult made = result("cameras-and-paths", "every camera and camera path sees the scene");
    const auto& checked = params_;
    Problems problems;
    const auto expect_picture = [&](const Frame& frame, const std::string& what) {
        if (const std::string problem = first_non_finite(frame); !problem.empty()) {
            problems.add(what + ": " + problem);
        }
        if (frame.hits <= 0) problems.add(what + " sees nothing");
    };
    for (const auto& camera : scene_.cameras) {
        expect_picture(render(camera.view, checked), "camera '" + camera.name + "'");
    }
    if (scene_.camera_paths.empty()) problems.add("the scene has no camera path");
    int moments = 0;
    for (const auto& path : scene_.camera_paths) {
        const float start = path.keyframes.front().time;
        for (float fraction : {0.0f, 0.37f, 0.81f, 1.0f}) {
            const float time = start + fraction * path.duration();
            ++moments;
            expect_picture(render(evaluate_camera_path(path, time), checked),
                           fmt::format("path '{}' at {:g} s", path.name, time));
        }
    }
    if (problems.any()) {
        return fail(made, problems.summary(),
                    "aim each camera and keyframe at the fractal from outside it (a camera inside "
                    "or behind it sees nothing), give the scene at least one camera path "
                    "(FGR_CAMERA_PATH), and see the NaN advice of the other checks if pixels are "
                    "not finite");
    }
    return pass(made, fmt::format("{} cameras, {} camera paths at {} moments",
                                  scene_.cameras.size(), scene_.camera_paths.size(), moments));
}

CheckResult SceneChecker::default_view() {
    const std::string name = "default-view", title = "the default view is a real picture";
    if (scene_.inside_only()) {
        CheckResult skipped = result(name, title);
        skipped.status = CheckStatus::Skipped;
        skipped.detail = "judged for marched scenes only: brute force renders a noisy estimate";
        return skipped;
    }
    CheckResult made = result(name, title);
    const Frame frame = render(scene_.cameras.front().view, params_, 96, 64);
    if (const std::string problem = first_non_finite(frame); !problem.empty()) {
        return fail(made, problem, kNanAdvice);
    }
    const double hit_fraction = double(frame.hits) / (96 * 64);
    double mean = 0.0, mean_square = 0.0;
    for (uint8_t value : frame.image.rgb) {
        mean += value;
        mean_square += double(value) * value;
    }
    mean /= double(frame.image.rgb.size());
    mean_square /= double(frame.image.rgb.size());
    const double spread = std::sqrt(std::max(mean_square - mean * mean, 0.0));
    const std::string measured =
        fmt::format("{:.1f}% of pixels hit, mean level {:.1f}, spread {:.1f}", 100.0 * hit_fraction,
                    mean, spread);
    if (hit_fraction <= 0.05) {
        return fail(made, measured + ": the fractal covers almost none of the view",
                    frame.hits == 0
                        ? std::string("nothing was hit: if the DE is NaN everywhere no ray ever "
                                      "stops (see hard-points); else move the default camera "
                                      "closer or aim it at the fractal")
                        : std::string("move the default camera closer or aim it at the fractal"));
    }
    // A closed scene (its own environment black: nothing outside lights it, menger-room) shows
    // walls wherever one looks.
    const bool enclosed = !scene_.environment.empty() &&
                          parse_environment(scene_.environment).kind == EnvironmentKind::Uniform &&
                          parse_environment(scene_.environment).radiance == glm::vec3(0.0f);
    if (hit_fraction >= 0.97 && !enclosed) {
        return fail(made, measured + ": the fractal covers the whole view",
                    "move the default camera back, or out of the fractal");
    }
    if (spread <= 10.0) {
        return fail(made, measured + ": the image is nearly uniform",
                    "check the lights and the scene's colour");
    }
    if (mean <= 15.0) {
        return fail(made, measured + ": the image is nearly black",
                    "check the lights point at the visible side, and the scene's colour");
    }
    return pass(made, measured);
}

SceneCheckReport SceneChecker::run_all(const std::optional<std::string>& only) {
    using Check = CheckResult (SceneChecker::*)();
    static const std::map<std::string, Check> checks{
        {"hard-points", &SceneChecker::finite_at_hard_points},
        {"hard-cameras", &SceneChecker::finite_for_hard_cameras},
        {"parameter-extremes", &SceneChecker::finite_at_parameter_extremes},
        {"lipschitz", &SceneChecker::lipschitz},
        {"march-safety", &SceneChecker::march_safety},
        {"packet-agreement", &SceneChecker::packet_agreement},
        {"de-pair", &SceneChecker::de_pair},
        {"normals-at-hits", &SceneChecker::normals_at_hits},
        {"relaxed-steps", &SceneChecker::relaxed_steps},
        {"cameras-and-paths", &SceneChecker::cameras_and_paths},
        {"default-view", &SceneChecker::default_view}};
    SceneCheckReport report;
    report.scene_id = scene_.id;
    report.settings = changed_params(scene_, params_);
    for (const std::string& name : scene_check_names()) {
        if (only && *only != name) continue;
        report.results.push_back((this->*checks.at(name))());
    }
    return report;
}

std::string format_check_report(const SceneCheckReport& report) {
    std::string text;
    std::string settings;
    for (const std::string& setting : report.settings) {
        settings += (settings.empty() ? "" : ", ") + setting;
    }
    text += report.settings.empty()
                ? "checked at the scene's default parameters\n"
                : fmt::format("checked at {} (the other parameters at their defaults)\n", settings);
    int failed = 0, skipped = 0;
    for (const CheckResult& check : report.results) {
        const char* verdict = check.status == CheckStatus::Passed   ? "ok     "
                              : check.status == CheckStatus::Failed ? "FAILED "
                                                                    : "skipped";
        text += fmt::format("{} {}: {}\n", verdict, check.name, check.title);
        text += fmt::format("        {}\n", check.detail);
        if (check.status == CheckStatus::Failed) {
            ++failed;
            text += fmt::format("        fix: {}\n", check.advice);
        }
        skipped += check.status == CheckStatus::Skipped;
    }
    const size_t run = report.results.size() - size_t(skipped);
    if (failed > 0) {
        text += fmt::format("{}: {} of {} checks FAILED\n", report.scene_id, failed, run);
    } else {
        text += fmt::format("{}: all {} checks passed{}\n", report.scene_id, run,
                            skipped ? fmt::format(" ({} skipped)", skipped) : "");
    }
    return text;
}

}  // namespace fgr
