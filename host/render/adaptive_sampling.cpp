// SPDX-License-Identifier: Apache-2.0
#include "render/adaptive_sampling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace fgr {

// One pixel's state between rounds.
struct AdaptivePixel {
    double estimate[3] = {0.0, 0.0, 0.0};      // sum of weight * round mean
    double weight = 0.0;                       // committed weights so far; 1 once done
    double weight_terms = 0.0;                 // sum of weight^2 / round samples (the variance's)
    double sum[3] = {0.0, 0.0, 0.0};           // plain sum of every sample (planning only)
    double variance_sum[3] = {0.0, 0.0, 0.0};  // per-sample variance estimates, one a round
    int variance_rounds = 0;
    // The last round's estimate (negative: none): the one round no decision looked at, so the
    // variance reported for the final estimate is free of the selection the decisions made.
    double last_variance[3] = {-1.0, -1.0, -1.0};
    long samples = 0;
    bool done = false;
    // This round's plan.
    long take = 0;
    double round_weight = 0.0;
};

namespace {

// A pixel's per-sample relative variance (channels' mean variance over the squared mean value),
// from its rounds so far.
double relative_sample_variance(const AdaptivePixel& pixel) {
    if (pixel.samples == 0) return 0.0;
    double variance = 0.0, mean = 0.0;
    for (int c = 0; c < 3; ++c) {
        if (pixel.variance_rounds > 0) variance += pixel.variance_sum[c] / pixel.variance_rounds;
        mean += pixel.sum[c] / double(pixel.samples);
    }
    variance /= 3.0;
    mean = std::max(mean / 3.0, double(kRelativeErrorFloor));
    return variance / (mean * mean);
}

// Each pixel's relative variance, the larger of its own and its 3x3 neighbourhood's mean: one
// pixel's estimate has a degree of freedom a round, and a bright light one pixel saw is likely
// near its neighbours too.
std::vector<double> planning_variances(const std::vector<AdaptivePixel>& pixels, int width,
                                       int height) {
    std::vector<double> own(pixels.size());
    for (size_t i = 0; i < pixels.size(); ++i) own[i] = relative_sample_variance(pixels[i]);
    std::vector<double> planned(pixels.size());
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            double sum = 0.0;
            int count = 0;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    sum += own[static_cast<size_t>(ny) * width + nx];
                    ++count;
                }
            }
            const size_t i = static_cast<size_t>(y) * width + x;
            planned[i] = std::max(own[i], sum / count);
        }
    }
    return planned;
}

// How close to its floor a pixel that cannot reach the threshold is taken. With m more samples
// sharing the weight left, rest, a pixel's relative variance is relative * (weight_terms +
// rest^2 / m): it never falls below relative * weight_terms, what the rounds already weighted
// carry. Where the threshold lies below that floor (a round planned from a variance estimate
// that came out low gave its few samples much weight), every sample the cap leaves would bring it
// only nearer the floor: the pixel takes enough for the rest to add a quarter of the floor (its
// error then within 12% of the least it can have) and stops, instead of taking the cap.
constexpr double kFloorMargin = 0.25;

// The samples a pixel still needs for its final estimate's relative variance to reach
// threshold^2, if the remaining weight were spread over them evenly, given the relative
// per-sample variance `relative` (or to come within kFloorMargin of its floor, where the
// threshold lies below it); at least `least` (a last round that rests on a sample or two would
// carry most of the pixel's weight on them) and at most what the cap leaves.
long samples_needed(const AdaptivePixel& pixel, double relative, double threshold, long least,
                    long cap) {
    const long left = cap - pixel.samples;
    if (left <= least) return std::max(left, 1L);
    if (relative <= 0.0) return least;
    const double room = std::max(threshold * threshold / relative - pixel.weight_terms,
                                 kFloorMargin * pixel.weight_terms);
    if (room <= 0.0) return left;
    const double rest = 1.0 - pixel.weight;
    const double needed = std::ceil(rest * rest / room);
    return static_cast<long>(std::clamp(needed, double(least), double(left)));
}

// The seed of round `round`: the request's own for the first, so that its samples are a fixed
// render's first ones, then well mixed (a murmur3 finaliser) so that rounds never share a
// sequence.
uint32_t round_seed(uint32_t seed, int round) {
    if (round == 0) return seed;
    uint32_t h = seed ^ (static_cast<uint32_t>(round) * 0x9e3779b9u);
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

}  // namespace

double relative_error(const float* rgb, const float* variance) {
    double mean = 0.0, var = 0.0;
    for (int c = 0; c < 3; ++c) {
        mean += rgb[c];
        var += std::max(variance[c], 0.0f);
    }
    mean = std::max(mean / 3.0, double(kRelativeErrorFloor));
    return std::sqrt(var / 3.0) / mean;
}

int default_min_samples(int cap) { return std::min(cap, std::max(4, cap / 32)); }

AdaptiveSampler::AdaptiveSampler(const FrameRequest& request, AdaptiveRule rule)
    : request_(request), rule_(rule) {
    const PixelRegion region = rendered_region(request);
    width_ = region.width;
    height_ = region.height;
    count_ = static_cast<size_t>(region.pixels());
    cap_ = request.samples;
    threshold_ = request.path.noise_threshold;
    min_samples_ =
        std::clamp<long>(request.path.min_samples > 0 ? request.path.min_samples
                                                      : default_min_samples(request.samples),
                         std::min(2L, cap_), cap_);
    pixels_.resize(count_);
    round_ = request;
    round_.path.noise_threshold = 0.0f;
    round_.on_sample = {};
    round_.on_progress = {};
    round_.enough = {};
    round_.sample_limits.assign(count_, 0.0f);
    albedo_.assign(count_ * 3, 0.0);
    normal_.assign(count_ * 3, 0.0);
    alpha_.assign(count_, 0.0);
}

AdaptiveSampler::~AdaptiveSampler() = default;
AdaptiveSampler::AdaptiveSampler(AdaptiveSampler&&) noexcept = default;
AdaptiveSampler& AdaptiveSampler::operator=(AdaptiveSampler&&) noexcept = default;

const FrameRequest* AdaptiveSampler::next_round() {
    // Plan the round from the earlier ones alone.
    batch_ = rounds_ == 0 ? min_samples_
                          : std::min(std::max(min_samples_, started_ / 2), cap_ - started_);
    const std::vector<double> relative = rounds_ > 0 && rule_ == AdaptiveRule::Unbiased
                                             ? planning_variances(pixels_, width_, height_)
                                             : std::vector<double>(count_, 0.0);
    bool any = false;
    for (size_t i = 0; i < count_; ++i) {
        AdaptivePixel& pixel = pixels_[i];
        pixel.take = 0;
        round_.sample_limits[i] = 0.0f;
        if (pixel.done) continue;
        any = true;
        pixel.take = batch_;
        if (rule_ == AdaptiveRule::Unbiased) {
            // The weight this round's mean gets: its share of what the pixel is now expected to
            // need, so that the rounds of a pixel that keeps needing every sample get
            // plain-average weights; a pixel's last round takes all the weight left.
            const long needed =
                rounds_ == 0 ? cap_
                             : samples_needed(pixel, relative[i], threshold_, min_samples_, cap_);
            long planned = std::max(needed, 1L);
            if (finishing_) planned = std::min(planned, batch_);
            pixel.take = std::min(planned, batch_);
            pixel.round_weight = (1.0 - pixel.weight) * double(pixel.take) / double(planned);
            if (pixel.take == planned) pixel.done = true;  // its last round
        }
        round_.sample_limits[i] = static_cast<float>(pixel.take);
    }
    if (!any || batch_ <= 0) {
        finished_ = true;
        return nullptr;
    }
    // Each round draws samples 0 .. batch - 1 of sequences scrambled afresh: stratified among
    // themselves and independent of the earlier rounds its plan came from (later points of one
    // scrambled sequence depend on its earlier ones, which biased the mean by 0.5%).
    round_.first_sample = 0;
    round_.path.seed = round_seed(request_.path.seed, rounds_);
    round_.samples = static_cast<int>(batch_);
    return &round_;
}

void AdaptiveSampler::add_round(const Frame& frame) {
    render_ms_ += frame.render_ms;
    if (rounds_ == 0) {
        result_ = frame;  // depth, hits and the first round's statistics
        if (!frame.foreground.empty()) foreground_.assign(count_ * 3, 0.0);
    } else if (frame.lane_stats && result_.lane_stats) {
        result_.lane_stats->lane_evaluations += frame.lane_stats->lane_evaluations;
        result_.lane_stats->packet_evaluations += frame.lane_stats->packet_evaluations;
    }
    ++rounds_;
    started_ += batch_;
    for (size_t i = 0; i < count_; ++i) {
        AdaptivePixel& pixel = pixels_[i];
        if (pixel.take == 0) continue;
        const double take = double(pixel.take);
        if (rule_ == AdaptiveRule::Naive) pixel.round_weight = take;  // normalised at the end
        const double w = pixel.round_weight;
        for (int c = 0; c < 3; ++c) {
            const double mean = frame.linear[i * 3 + c];
            pixel.estimate[c] += w * mean;
            pixel.sum[c] += mean * take;
            albedo_[i * 3 + c] += w * frame.albedo[i * 3 + c];
            normal_[i * 3 + c] += w * frame.normal[i * 3 + c];
            if (!foreground_.empty()) foreground_[i * 3 + c] += w * frame.foreground[i * 3 + c];
        }
        alpha_[i] += w * frame.alpha[i];
        if (frame.variance[i * 3] >= 0.0f) {
            for (int c = 0; c < 3; ++c) {
                const double per_sample = double(frame.variance[i * 3 + c]) * take;
                pixel.variance_sum[c] += per_sample;
                pixel.last_variance[c] = per_sample;
            }
            ++pixel.variance_rounds;
        } else {
            for (double& v : pixel.last_variance) v = -1.0;
        }
        pixel.weight += w;
        pixel.weight_terms += w * w / take;
        pixel.samples += pixel.take;
        if (rule_ == AdaptiveRule::Naive) {
            // Stops on what its own samples show, those samples included in its average.
            const double own = relative_sample_variance(pixel);
            pixel.done =
                pixel.samples >= cap_ || own / double(pixel.samples) <= threshold_ * threshold_;
        }
    }
}

Frame AdaptiveSampler::frame(const Scene& scene) const {
    Frame result = result_;
    result.samples_per_pixel.assign(count_, 0.0f);
    result.variance.assign(count_ * 3, -1.0f);
    std::vector<double> errors(count_);
    AdaptiveReport report;
    report.threshold = static_cast<float>(threshold_);
    report.rounds = rounds_;
    report.cap = static_cast<int>(cap_);
    report.min_samples = static_cast<int>(min_samples_);
    report.min_spp = std::numeric_limits<float>::max();
    long converged = 0;
    double total = 0.0;
    for (size_t i = 0; i < count_; ++i) {
        const AdaptivePixel& pixel = pixels_[i];
        // Unfinished pixels (a frame shown before the last round) are scaled up to whole weight.
        const double norm =
            rule_ == AdaptiveRule::Naive || !finished_ ? std::max(pixel.weight, 1e-30) : 1.0;
        for (int c = 0; c < 3; ++c) {
            result.linear[i * 3 + c] = static_cast<float>(pixel.estimate[c] / norm);
            result.albedo[i * 3 + c] = static_cast<float>(albedo_[i * 3 + c] / norm);
            result.normal[i * 3 + c] = static_cast<float>(normal_[i * 3 + c] / norm);
            if (!foreground_.empty()) {
                result.foreground[i * 3 + c] = static_cast<float>(foreground_[i * 3 + c] / norm);
            }
            if (pixel.variance_rounds > 0) {
                // The unbiased rule's last round was decided before it was seen; the naive rule's
                // every round took part in its decisions alike.
                const double per_sample =
                    rule_ == AdaptiveRule::Unbiased && pixel.last_variance[c] >= 0.0
                        ? pixel.last_variance[c]
                        : pixel.variance_sum[c] / pixel.variance_rounds;
                const double terms = rule_ == AdaptiveRule::Naive
                                         ? 1.0 / double(pixel.samples)
                                         : pixel.weight_terms / (norm * norm);
                result.variance[i * 3 + c] = static_cast<float>(per_sample * terms);
            }
        }
        result.alpha[i] = static_cast<float>(alpha_[i] / norm);
        const float spp = static_cast<float>(pixel.samples);
        result.samples_per_pixel[i] = spp;
        report.min_spp = std::min(report.min_spp, spp);
        report.max_spp = std::max(report.max_spp, spp);
        total += spp;
        errors[i] = relative_error(&result.linear[i * 3], &result.variance[i * 3]);
        converged += errors[i] <= threshold_;
    }
    if (count_ > 0) {
        report.mean_spp = total / double(count_);
        report.share_converged = double(converged) / double(count_);
        double error_sum = 0.0;
        for (double error : errors) error_sum += error;
        report.mean_error = error_sum / double(count_);
        const size_t p95 = std::min(count_ - 1, static_cast<size_t>(0.95 * double(count_)));
        std::nth_element(errors.begin(), errors.begin() + static_cast<long>(p95), errors.end());
        report.error_p95 = errors[p95];
    } else {
        report.min_spp = 0.0f;
    }
    result.samples = static_cast<int>(report.max_spp);
    result.adaptive = report;
    result.image = display_image(scene, request_.params, result.linear, width_, height_);
    result.render_ms = render_ms_;
    return result;
}

Frame render_adaptive(Renderer& renderer, const FrameRequest& request, AdaptiveRule rule) {
    AdaptiveSampler sampler(request, rule);
    while (const FrameRequest* round = sampler.next_round()) {
        Frame frame = renderer.render(*round);
        if (frame.cancelled) return frame;
        sampler.add_round(frame);
        if (request.on_sample) {
            request.on_sample(static_cast<int>(sampler.samples_started()), request.samples);
        }
        if (request.enough && request.enough()) sampler.finish_next_round();
    }
    return sampler.frame(renderer.scene());
}

std::string adaptive_summary(const AdaptiveReport& report) {
    return fmt::format(
        "adaptive sampling to relative error {:g}: {:.1f}% of pixels at or below it (estimated "
        "error mean {:.4f}, 95th percentile {:.4f}); samples per pixel {:g} / {:.1f} / {:g} "
        "(min / mean / max) of {} in {} rounds, {:.0f}% fewer than fixed sampling",
        report.threshold, 100.0 * report.share_converged, report.mean_error, report.error_p95,
        report.min_spp, report.mean_spp, report.max_spp, report.cap, report.rounds,
        100.0 * report.saved());
}

}  // namespace fgr
