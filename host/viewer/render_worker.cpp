// SPDX-License-Identifier: Apache-2.0
#include "viewer/render_worker.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "denoise/denoise.hpp"
#include "output/denoised_frame.hpp"
#include "output/still_image.hpp"
#include "render/sample_budget.hpp"
#include "scene/parameters.hpp"
#include "viewer/view_still.hpp"

namespace fgr::viewer {
namespace {

FrameRequest frame_request(const ViewState& state, int width, int height) {
    FrameRequest request;
    request.width = width;
    request.height = height;
    request.view = state.view;
    request.projection = state.projection;
    request.params = state.params;
    request.path = state.path;
    return request;
}

double samples_per_second(int width, int height, double render_ms) {
    return render_ms > 0.0 ? double(width) * double(height) * 1000.0 / render_ms : 0.0;
}

}  // namespace

int refine_pass_samples(const ViewState& state, int sample, int cap, double ms_per_pixel_sample,
                        double target_ms) {
    const bool regrouped =
        state.mode == RenderMode::Path && state.path.regroup && state.scene->ifs == nullptr;
    const int left = cap - sample;
    if (!regrouped || left <= 1 || !(ms_per_pixel_sample > 0.0) || !(target_ms > 0.0)) return 1;
    const double pass_ms = ms_per_pixel_sample * double(state.width) * double(state.height);
    const double fits = std::floor(target_ms / pass_ms);
    return static_cast<int>(std::clamp(fits, 1.0, double(std::min(left, kRegroupLaunchSamples))));
}

RenderWorker::RenderWorker(int device_index, int packet_width, QualitySettings quality)
    : device_(open_device(device_index)),
      packet_width_(packet_width ? packet_width : preferred_packet_width(device_.info)),
      cache_(ProgramCache::default_directory()),
      specialise_cache_(ProgramCache::default_directory()),
      precision_chooser_(device_.info,
                         [this](const std::string& warning) { post_message(warning); }),
      quality_(quality) {
    thread_ = std::thread([this] { run(); });
}

RenderWorker::~RenderWorker() { stop(); }

void RenderWorker::stop() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    if (specialiser_.joinable()) specialiser_.join();
}

void RenderWorker::set_specialise_gate(std::function<void()> gate) {
    std::lock_guard lock(mutex_);
    specialise_gate_ = std::move(gate);
}

void RenderWorker::submit(ViewState state) {
    {
        std::lock_guard lock(mutex_);
        if (state_ && state_->generation == state.generation &&
            state_->interactive == state.interactive) {
            return;
        }
        if (!state_ || state_->generation != state.generation) status_.idle = false;
        state_ = std::move(state);
    }
    wake_.notify_all();
}

void RenderWorker::set_quality(QualitySettings quality) {
    {
        std::lock_guard lock(mutex_);
        quality_.set_settings(quality);
        status_.idle = false;  // a higher cap means more samples to add
    }
    wake_.notify_all();
}

void RenderWorker::request_screenshot(ScreenshotRequest request) {
    {
        std::lock_guard lock(mutex_);
        screenshots_.push_back(std::move(request));
        status_.pending_screenshots = static_cast<int>(screenshots_.size());
    }
    wake_.notify_all();
}

void RenderWorker::request_reload(ReloadRequest request) {
    {
        std::lock_guard lock(mutex_);
        reloads_.push_back(std::move(request));
        status_.pending_reloads = static_cast<int>(reloads_.size());
    }
    wake_.notify_all();
}

std::vector<ReloadResult> RenderWorker::take_reloads() {
    std::lock_guard lock(mutex_);
    return std::exchange(reload_results_, {});
}

std::optional<DisplayFrame> RenderWorker::take_frame() {
    std::lock_guard lock(mutex_);
    return std::exchange(frame_, std::nullopt);
}

WorkerStatus RenderWorker::status() const {
    std::lock_guard lock(mutex_);
    return status_;
}

std::vector<std::string> RenderWorker::take_messages() {
    std::lock_guard lock(mutex_);
    return std::exchange(messages_, {});
}

void RenderWorker::post_message(std::string message) {
    std::lock_guard lock(mutex_);
    messages_.push_back(std::move(message));
}

void RenderWorker::publish(DisplayFrame frame, const Renderer& renderer) {
    frame.ifs_depth_reached = ifs_depth_reached_;
    frame.double_precision = renderer.switches().double_precision;
    frame.specialised = !renderer.switches().specialised.empty();
    std::lock_guard lock(mutex_);
    frame_ = std::move(frame);
}

void RenderWorker::mark_idle(uint64_t generation) {
    std::lock_guard lock(mutex_);
    if (state_ && state_->generation == generation && !state_->interactive) {
        status_.idle = true;
        status_.idle_generation = generation;
    }
}

std::optional<RenderWorker::Job> RenderWorker::next_job() {
    std::unique_lock lock(mutex_);
    // Work is a screenshot, a reload, or a state not yet fully refined; an interactive state
    // already previewed waits for the next change (or for the view to settle).
    wake_.wait(lock, [this] {
        return stopping_ || !screenshots_.empty() || !reloads_.empty() ||
               (state_ && !status_.idle &&
                !(state_->interactive && state_->generation == previewed_generation_));
    });
    Job job;
    if (!screenshots_.empty()) {
        job.screenshot = std::move(screenshots_.front());
        screenshots_.pop_front();
        return job;
    }
    if (!reloads_.empty()) {
        job.reload = std::move(reloads_.front());
        reloads_.pop_front();
        return job;
    }
    if (stopping_) return std::nullopt;
    job.view = *state_;
    return job;
}

void RenderWorker::run() {
    while (std::optional<Job> job = next_job()) {
        try {
            if (job->screenshot) {
                take_screenshot(*job->screenshot);
                std::lock_guard lock(mutex_);
                status_.pending_screenshots = static_cast<int>(screenshots_.size());
                continue;
            }
            if (job->reload) {
                reload(*job->reload);
                continue;
            }
            const ViewState& state = *job->view;
            Renderer* renderer = choose_renderer(state);
            if (renderer == nullptr) {
                mark_idle(state.generation);  // the build failed: nothing to refine
                continue;
            }
            render_pass(*specialised_or(*renderer, state), state);
        } catch (const std::exception& error) {
            // A render that fails (device out of memory, lost device) must not end the viewer:
            // report it and wait for the next change.
            spdlog::error("render failed: {}", error.what());
            post_message(fmt::format("render failed: {}", error.what()));
            if (job->view) mark_idle(job->view->generation);
        }
    }
}

Renderer* RenderWorker::build_renderer(const std::shared_ptr<const Scene>& scene, uint64_t effects,
                                       bool double_precision, RenderMode mode,
                                       std::pair<std::string, std::string>* failure) {
    const RendererKey key{scene.get(), effects, double_precision, mode};
    if (auto found = renderers_.find(key); found != renderers_.end()) {
        return found->second.renderer.get();
    }
    if (auto failed = failures_.find(key); failed != failures_.end()) {
        *failure = failed->second.message;
        return nullptr;
    }
    {
        std::lock_guard lock(mutex_);
        status_.compiling = true;
        status_.compiling_scene = scene->id;
        status_.compiling_double = double_precision;
    }
    std::unique_ptr<Renderer> renderer;
    try {
        renderer = std::make_unique<Renderer>(
            device_, cache_, *scene,
            with_precision(KernelSwitches{packet_width_, effects, false, false, mode},
                           double_precision));
        spdlog::info("kernel for '{}' ({} mode, effects: {}, {}) ready in {:.0f} ms", scene->id,
                     render_mode_name(mode), effect_names(effects),
                     double_precision ? "double" : "float", renderer->build_report().build_ms);
    } catch (const KernelBuildError& error) {
        *failure = {fmt::format("scene '{}': {}", scene->id, error.what()), error.build_log()};
    } catch (const cl::Error& error) {
        *failure = {fmt::format("scene '{}': {} failed: {}", scene->id, error.what(),
                                cl_error_name(error.err())),
                    ""};
    } catch (const std::invalid_argument& error) {  // a mode the scene cannot render in
        *failure = {error.what(), ""};
    }
    {
        std::lock_guard lock(mutex_);
        status_.compiling = false;
        status_.compiling_scene.clear();
        status_.compiling_double = false;
    }
    if (!renderer) {
        spdlog::error("{}", failure->first);
        if (!failure->second.empty()) fmt::print(stderr, "{}\n", failure->second);
        failures_[key] = {scene, *failure};
        return nullptr;
    }
    return (renderers_[key] = {scene, std::move(renderer)}).renderer.get();
}

Renderer* RenderWorker::choose_renderer(const ViewState& state) {
    if (state.generation == chosen_generation_) return renderer_for(state, chosen_double_);
    // The auto rule's DE at the camera comes from the float kernel, as in fgr render and fgr
    // bench, so all three decide alike.
    bool float_failed = false;
    const auto distance = [&] {
        Renderer* in_float = renderer_for(state, false);
        if (in_float == nullptr) {
            float_failed = true;
            return -1.0f;
        }
        probe_camera(*in_float, state);
        return probed_de_;
    };
    const bool in_double =
        precision_chooser_.in_double(state.precision, state.view, state.width, distance);
    if (float_failed) return nullptr;
    Renderer* renderer = renderer_for(state, in_double);
    if (renderer == nullptr) return nullptr;
    // The DE that sets the fly speed, probed in the precision that renders.
    probe_camera(*renderer, state);
    chosen_generation_ = state.generation;
    chosen_double_ = in_double;
    return renderer;
}

Renderer* RenderWorker::renderer_for(const ViewState& state, bool double_precision) {
    const RendererKey key{state.scene.get(), state.effects, double_precision, state.mode};
    const bool known = renderers_.count(key) || failures_.count(key);
    std::pair<std::string, std::string> failure;
    Renderer* renderer =
        build_renderer(state.scene, state.effects, double_precision, state.mode, &failure);
    std::lock_guard lock(mutex_);
    if (renderer == nullptr && !known) messages_.push_back(failure.first);
    std::tie(status_.error, status_.error_log) = failure;
    return renderer;
}

void RenderWorker::reload(const ReloadRequest& request) {
    std::pair<std::string, std::string> failure;
    // The float kernel decides: a deep view builds the double one when it first needs it.
    const bool ok = build_renderer(request.candidate, request.effects, false, RenderMode::Shaded,
                                   &failure) != nullptr;
    std::lock_guard lock(mutex_);
    reload_results_.push_back({request, ok, failure.first, failure.second});
    status_.pending_reloads = static_cast<int>(reloads_.size());
}

namespace {

std::string specialised_text(const std::vector<SpecialisedParam>& values) {
    std::string text;
    for (const SpecialisedParam& value : values) {
        text += fmt::format("{}{} = {}", text.empty() ? "" : ", ", value.id, value.value);
    }
    return text;
}

}  // namespace

void RenderWorker::collect_specialised() {
    std::unique_ptr<Renderer> built;
    {
        std::lock_guard lock(mutex_);
        if (!specialised_done_) return;
        specialised_done_ = false;
        built = std::move(specialised_built_);
        status_.specialising = false;
    }
    if (specialiser_.joinable()) specialiser_.join();
    const SpecialisedKey key = *std::exchange(specialising_, std::nullopt);
    if (!built) {
        specialise_failed_[key] = true;
        return;
    }
    std::shared_ptr<const Scene> scene;
    for (const auto& [renderer_key, cached] : renderers_) {
        if (cached.renderer.get() == key.first) scene = cached.scene;
    }
    specialised_[key] = {scene, std::move(built)};
    // Show it now: the view refines again from its first sample with the specialised kernel.
    accumulated_generation_ = UINT64_MAX;
}

Renderer* RenderWorker::specialised_or(Renderer& generic, const ViewState& state) {
    collect_specialised();
    std::vector<SpecialisedParam> values;
    try {
        values = specialisation_for(*state.scene, state.params);
    } catch (const std::invalid_argument&) {
        return &generic;  // a declaration naming no such parameter: the generic kernel serves
    }
    if (values.empty()) return &generic;
    const SpecialisedKey key{&generic, specialised_text(values)};
    if (auto found = specialised_.find(key); found != specialised_.end()) {
        return found->second.renderer.get();
    }
    if (specialise_failed_.count(key) || specialising_) return &generic;
    // One build at a time, on its own thread with its own program cache (the render thread's is
    // not shared); the generic kernel renders meanwhile, so a slider never waits for a compile.
    specialising_ = key;
    KernelSwitches switches = generic.switches();
    switches.specialised = values;
    std::function<void()> gate;
    {
        std::lock_guard lock(mutex_);
        status_.specialising = true;
        gate = specialise_gate_;
    }
    spdlog::info("building '{}' with {} compiled in", state.scene->id, key.second);
    specialiser_ = std::thread([this, scene = state.scene, switches, gate] {
        if (gate) gate();
        std::unique_ptr<Renderer> built;
        try {
            built = std::make_unique<Renderer>(device_, specialise_cache_, *scene, switches);
        } catch (const std::exception& error) {
            spdlog::warn(
                "the specialised kernel of '{}' did not build ({}): the generic one "
                "renders",
                scene->id, error.what());
        }
        {
            std::lock_guard lock(mutex_);
            specialised_built_ = std::move(built);
            specialised_done_ = true;
            status_.idle = false;  // render again, with the new kernel
            previewed_generation_ = UINT64_MAX;
        }
        wake_.notify_all();
    });
    return &generic;
}

void RenderWorker::render_pass(Renderer& renderer, const ViewState& state) {
    if (accumulated_generation_ != state.generation) {
        accumulated_generation_ = state.generation;
        accumulated_samples_ = 0;
    }
    RenderPass pass;
    {
        std::lock_guard lock(mutex_);
        pass = quality_.next_pass(state.interactive, accumulated_samples_,
                                  int64_t{state.width} * state.height,
                                  sample_budget(state.mode).standing_view);
    }
    switch (pass.kind) {
        case RenderPass::Kind::Preview:
            render_preview(renderer, state, pass.scale);
            break;
        case RenderPass::Kind::Refine:
            refine(renderer, state, pass.sample);
            break;
        case RenderPass::Kind::Idle:
            mark_idle(state.generation);
            break;
    }
}

void RenderWorker::render_preview(Renderer& renderer, const ViewState& state, float scale) {
    const int width = scaled_size(state.width, scale);
    const int height = scaled_size(state.height, scale);
    // Previews are short by design and never cancelled: while the view keeps changing, every
    // one of them would be.
    FrameRequest request = frame_request(state, width, height);
    request.path.noise_threshold = 0.0f;  // one sample: nothing to adapt
    request.start_hints = preview_start_hints(renderer, state, width, height);
    Frame frame = renderer.render(request);
    last_preview_ =
        LastPreview{state.scene, &renderer, state.params,
                    DepthView{state.view, state.projection, width, height, frame.depth}};
    {
        std::lock_guard lock(mutex_);
        quality_.record_frame(int64_t{width} * height, frame.render_ms);
        previewed_generation_ = state.generation;
    }
    ifs_depth_reached_ = frame.ifs_levels ? frame.ifs_levels->deepest : -1;
    publish({std::move(frame.image), scale, 1, frame.render_ms,
             samples_per_second(width, height, frame.render_ms),
             renderer.switches().double_precision, state.generation},
            renderer);
}

std::vector<float> RenderWorker::preview_start_hints(const Renderer& renderer,
                                                     const ViewState& state, int width,
                                                     int height) const {
    if (!last_preview_ || last_preview_->scene != state.scene ||
        last_preview_->renderer != &renderer || last_preview_->params != state.params) {
        return {};
    }
    return reproject_start_hints(last_preview_->depths, state.view, state.projection, width,
                                 height);
}

void RenderWorker::refine(Renderer& renderer, const ViewState& state, int sample) {
    if (state.mode == RenderMode::Path && state.path.noise_threshold > 0.0f) {
        refine_adaptive(renderer, state, sample);
        return;
    }
    FrameRequest request = frame_request(state, state.width, state.height);
    request.first_sample = sample;
    if (state.mode == RenderMode::Path) {
        int cap = sample_budget(state.mode).standing_view;
        std::lock_guard lock(mutex_);
        if (cap <= 0) cap = std::max(quality_.settings().sample_cap, 1);
        request.samples = refine_pass_samples(state, sample, cap, quality_.ms_per_pixel(),
                                              quality_.settings().target_ms);
    }
    request.cancel = [this, generation = state.generation] {
        std::lock_guard lock(mutex_);
        return stopping_ || (state_ && state_->generation != generation);
    };
    Frame frame = renderer.render(request);
    if (frame.cancelled) return;
    const int added = std::max(frame.samples, 1);
    {
        // The cost per pixel sample, as a preview's single sample measures it.
        std::lock_guard lock(mutex_);
        quality_.record_frame(int64_t{state.width} * state.height * added, frame.render_ms);
    }
    if (state.mode == RenderMode::Brute) {
        // The renderer carries the depth buffer from pass to pass: each frame is the whole image
        // so far, not one more sample to average.
        accumulated_samples_ = sample + 1;
        publish({std::move(frame.image), 1.0f, accumulated_samples_, frame.render_ms,
                 samples_per_second(state.width, state.height, frame.render_ms),
                 renderer.switches().double_precision, state.generation},
                renderer);
        return;
    }
    const bool denoising = state.denoise && state.mode == RenderMode::Path;
    if (denoising) accumulate_features(frame, sample == 0, added);
    // The accumulation holds the sum of the samples; the frame their mean.
    if (sample == 0) {
        ifs_depth_reached_ = frame.ifs_levels ? frame.ifs_levels->deepest : -1;
        accumulation_ = std::move(frame.linear);
        for (float& value : accumulation_) value *= static_cast<float>(added);
        accumulated_samples_ = added;
    } else {
        for (size_t i = 0; i < accumulation_.size(); ++i) {
            accumulation_[i] += frame.linear[i] * static_cast<float>(added);
        }
        accumulated_samples_ += added;
    }
    if (accumulated_samples_ == 1) {
        publish({std::move(frame.image), 1.0f, 1, frame.render_ms,
                 samples_per_second(state.width, state.height, frame.render_ms),
                 renderer.switches().double_precision, state.generation},
                renderer);
        return;
    }
    const float inverse = 1.0f / static_cast<float>(accumulated_samples_);
    Image8 image = denoising ? denoised_preview(state)
                             : display_image(*state.scene, state.params, accumulation_, state.width,
                                             state.height, inverse);
    publish({std::move(image), 1.0f, accumulated_samples_, frame.render_ms,
             samples_per_second(state.width, state.height, frame.render_ms / added),
             renderer.switches().double_precision, state.generation},
            renderer);
}

void RenderWorker::accumulate_features(const Frame& frame, bool first, int samples) {
    const float n = static_cast<float>(samples);
    const auto add = [first, n](std::vector<float>& sum, const std::vector<float>& means) {
        if (first || sum.size() != means.size()) sum.assign(means.size(), 0.0f);
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += means[i] * n;
    };
    // The frame's samples' squares summed: one sample's square, or for several (whose values
    // the frame does not keep) n m^2 + (n - 1) s^2 from their mean m and the per-sample variance
    // s^2 = n Var(m) that Frame::variance estimates without bias, so the sum stays right on
    // average.
    const bool several = samples > 1 && frame.variance.size() == frame.linear.size();
    std::vector<float> squares(frame.linear.size());
    for (size_t i = 0; i < squares.size(); ++i) {
        const float mean = frame.linear[i];
        const float spread = several ? std::max(frame.variance[i], 0.0f) * n : 0.0f;
        squares[i] = n * mean * mean + (n - 1.0f) * spread;
    }
    if (first || squares_.size() != squares.size()) squares_.assign(squares.size(), 0.0f);
    for (size_t i = 0; i < squares.size(); ++i) squares_[i] += squares[i];
    add(albedo_sum_, frame.albedo);
    add(normal_sum_, frame.normal);
    add(alpha_sum_, frame.alpha);
    if (first) first_depth_ = frame.depth;
}

Image8 RenderWorker::denoised_preview(const ViewState& state) {
    // Each sample is an independent estimate, so the variance of their mean is the samples'
    // variance over their count.
    const float n = static_cast<float>(accumulated_samples_);
    const size_t values = accumulation_.size();
    std::vector<float> mean(values), variance(values);
    for (size_t i = 0; i < values; ++i) {
        mean[i] = accumulation_[i] / n;
        const float spread = std::max(squares_[i] / n - mean[i] * mean[i], 0.0f);
        variance[i] = spread / (n - 1.0f);
    }
    const auto averaged = [n](const std::vector<float>& sum) {
        std::vector<float> out(sum.size());
        for (size_t i = 0; i < sum.size(); ++i) out[i] = sum[i] / n;
        return out;
    };
    const std::vector<float> albedo = averaged(albedo_sum_), normal = averaged(normal_sum_),
                             alpha = averaged(alpha_sum_);
    const size_t pixels = size_t(state.width) * size_t(state.height);
    const auto plane = [pixels](const std::vector<float>& sum, size_t per_pixel) {
        return sum.size() == pixels * per_pixel ? std::span<const float>(sum)
                                                : std::span<const float>();
    };
    try {
        const std::vector<float> denoised =
            denoise(DenoiseInput{state.width, state.height, mean, variance, plane(albedo, 3),
                                 plane(normal, 3), plane(first_depth_, 1), plane(alpha, 1)},
                    DenoiseSettings{DenoiseMethod::Atrous, 0});
        return display_image(*state.scene, state.params, denoised, state.width, state.height, 1.0f);
    } catch (const std::invalid_argument& error) {
        // Planes that do not match (a frame without them): the raw image, said once.
        spdlog::warn("denoising the preview: {}", error.what());
        return display_image(*state.scene, state.params, mean, state.width, state.height, 1.0f);
    }
}

void RenderWorker::refine_adaptive(Renderer& renderer, const ViewState& state, int sample) {
    int cap = sample_budget(state.mode).standing_view;
    if (cap <= 0) {
        std::lock_guard lock(mutex_);
        cap = std::max(quality_.settings().sample_cap, 1);
    }
    if (sample == 0 || !adaptive_) {
        FrameRequest request = frame_request(state, state.width, state.height);
        request.samples = cap;
        adaptive_.emplace(request);
    }
    const FrameRequest* planned = adaptive_->next_round();
    if (planned == nullptr) {
        accumulated_samples_ = cap;  // every pixel is done: the next pass is idle
        return;
    }
    FrameRequest round = *planned;
    round.cancel = [this, generation = state.generation] {
        std::lock_guard lock(mutex_);
        return stopping_ || (state_ && state_->generation != generation);
    };
    const Frame frame = renderer.render(round);
    if (frame.cancelled) {
        adaptive_.reset();  // a new view starts its rounds anew
        return;
    }
    {
        std::lock_guard lock(mutex_);
        quality_.record_frame(int64_t{state.width} * state.height * round.samples, frame.render_ms);
    }
    if (sample == 0) ifs_depth_reached_ = frame.ifs_levels ? frame.ifs_levels->deepest : -1;
    adaptive_->add_round(frame);
    accumulated_samples_ = static_cast<int>(std::min<long>(adaptive_->samples_started(), cap));
    Frame shown = adaptive_->frame(*state.scene);
    if (state.denoise && shown.variance.size() == shown.linear.size()) {
        // The rounds' combined estimate with its variance: the preview's fast filter over it.
        const size_t pixels = size_t(state.width) * size_t(state.height);
        const auto plane = [pixels](const std::vector<float>& values, size_t per_pixel) {
            return values.size() == pixels * per_pixel ? std::span<const float>(values)
                                                       : std::span<const float>();
        };
        const std::vector<float> denoised =
            denoise(DenoiseInput{state.width, state.height, shown.linear, shown.variance,
                                 plane(shown.albedo, 3), plane(shown.normal, 3),
                                 plane(shown.depth, 1), plane(shown.alpha, 1)},
                    DenoiseSettings{DenoiseMethod::Atrous, 0});
        shown.image =
            display_image(*state.scene, state.params, denoised, state.width, state.height, 1.0f);
    }
    double taken = 0.0;  // pixel samples this round
    for (float limit : round.sample_limits) taken += limit;
    publish({std::move(shown.image), 1.0f, accumulated_samples_, frame.render_ms,
             frame.render_ms > 0.0 ? taken * 1000.0 / frame.render_ms : 0.0,
             renderer.switches().double_precision, state.generation},
            renderer);
}

void RenderWorker::take_screenshot(const ScreenshotRequest& request) {
    const Scene& scene = *request.scene;
    const ViewFile& view = request.view;
    const auto not_taken = [this](const std::string& reason) {
        const std::string message = fmt::format("screenshot not taken: {}", reason);
        spdlog::error("{}", message);
        post_message(message);
    };
    constexpr const char* kNoKernel = "the kernel for this view did not build";
    spdlog::info("screenshot: rendering {}x{} at {} samples per pixel", view.width, view.height,
                 view.samples);
    try {
        // The still of the view as `fgr render` renders the view file: the same request and
        // settings, float or double chosen for the view alike, and the same file writer.
        const ViewStill still = still_of_view(scene, view, packet_width_);
        if (failures_.count({&scene, still.settings.effects, false, still.settings.mode})) {
            return not_taken(kNoKernel);  // the view's own build failed: no second try
        }
        Frame frame;
        if (view.path && view.path->denoise && view.samples >= 2) {
            // As `fgr render --denoise` renders it: two halves of the samples, then filtered.
            frame = render_with_variance(still.request, [&](const FrameRequest& half) {
                return render_still(scene, half, device_, cache_, still.settings);
            });
            denoise_frame(frame, still.output.display, DenoiseSettings{});
        } else {
            frame = render_still(scene, still.request, device_, cache_, still.settings);
        }
        write_still(request.file, frame, still.output);
        spdlog::info("screenshot: wrote {} ({}x{}, {} spp, {:.0f} ms)", request.file.string(),
                     view.width, view.height, still.request.samples, frame.render_ms);
    } catch (const KernelBuildError&) {
        return not_taken(kNoKernel);
    } catch (const std::exception& error) {
        return not_taken(error.what());
    }
    post_message(fmt::format("wrote {}", request.file.string()));
}

void RenderWorker::probe_camera(Renderer& renderer, const ViewState& state) {
    if (&renderer == probed_renderer_ && state.view.position == probed_position_ &&
        state.params == probed_params_) {
        return;
    }
    probed_renderer_ = &renderer;
    probed_position_ = state.view.position;
    probed_params_ = state.params;
    probed_de_ = surface_distance(renderer, state.view, state.params);
    std::lock_guard lock(mutex_);
    status_.de_at_camera = probed_de_;
}

}  // namespace fgr::viewer
