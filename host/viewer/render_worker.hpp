// SPDX-License-Identifier: Apache-2.0
#pragma once
// The viewer's render thread. The window thread posts the state to show (latest wins) and takes
// finished frames; it never waits on OpenCL. The worker builds kernels (keeping the last image on
// screen meanwhile), renders previews at a reduced resolution while the view changes, refines the
// still view sample by sample (the path tracer's for as long as the view stands still), renders
// screenshots as `fgr render` renders their view, and reports the distance
// estimate at the camera for the fly speed. It picks float or double lanes per view (see
// precision.hpp), building the double kernel the first time a deep view needs it.

#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "image/image_io.hpp"
#include "render/adaptive_sampling.hpp"
#include "render/path_settings.hpp"
#include "render/precision.hpp"
#include "render/prepass/reprojection.hpp"
#include "render/renderer.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"
#include "view_file/view_file.hpp"
#include "viewer/adaptive_quality.hpp"

namespace fgr::viewer {

// Everything that decides the image. `generation` changes whenever anything else but
// `interactive` does, so the worker knows when to restart refinement.
struct ViewState {
    std::shared_ptr<const Scene> scene;
    uint64_t effects = 0;
    CameraView view;
    Projection projection;
    std::vector<float> params;
    int width = 1;  // full resolution
    int height = 1;
    Precision precision = Precision::Auto;
    RenderMode mode = RenderMode::Shaded;
    PathSettings path;         // mode Path: bounces, strategies, the environment (null: the sky)
    bool interactive = false;  // the view is changing: preview frames, no refinement
    // Mode Path: the accumulating image is shown denoised (denoise/denoise.hpp, the a-trous
    // filter), guided by the samples' variance and the first hit's albedo, normal and depth.
    bool denoise = false;
    uint64_t generation = 0;
    bool operator==(const ViewState&) const = default;
};

struct DisplayFrame {
    Image8 image;                   // tone-mapped sRGB at the rendered size
    float scale = 1.0f;             // rendered size / full size
    int samples = 1;                // samples per pixel averaged into it
    double render_ms = 0;           // the pass that produced it
    double samples_per_second = 0;  // pixel samples per second of that pass
    bool double_precision = false;  // rendered with double lanes
    uint64_t generation = 0;
    int ifs_depth_reached = -1;  // IFS scenes: the deepest level a pixel hit (-1: none or not IFS)
    // Rendered by a kernel with the scene's specialisable parameters compiled in (KernelSwitches::
    // specialised); the generic kernel renders until that one is built.
    bool specialised = false;
};

struct WorkerStatus {
    bool compiling = false;
    std::string compiling_scene;    // id of the scene being built
    bool compiling_double = false;  // ... its double-precision kernel
    std::string error;              // build failure of the shown (scene, effects), one line
    std::string error_log;          // the compiler's output for it
    float de_at_camera = -1.0f;     // < 0 until known
    bool idle = false;              // the posted state is fully refined (or failed to build)
    uint64_t idle_generation = 0;   // ... for this generation
    int pending_screenshots = 0;
    int pending_reloads = 0;
    bool specialising = false;  // a kernel with the parameters compiled in is building meanwhile
};

// A screenshot is the still of a view file (view_still.hpp), rendered and written as `fgr render`
// renders that file.
struct ScreenshotRequest {
    std::shared_ptr<const Scene> scene;  // the version shown when it was asked for
    ViewFile view;                       // everything that decides the image, its size too
    std::filesystem::path file;          // which carries the view (image/embedded_view.hpp)
};

// A new version of a scene (a rebuilt plugin, an edited .cl file) to try before it replaces the
// running one: its kernel must build first, so a broken update never takes a working scene away.
struct ReloadRequest {
    std::shared_ptr<const Scene> candidate;
    std::shared_ptr<const Scene> replaces;  // the version running now
    uint64_t effects = 0;                   // the effects it will be shown with
};

struct ReloadResult {
    ReloadRequest request;
    bool ok = false;
    std::string error;      // one line, when !ok
    std::string error_log;  // the compiler's output, when it has one
};

// Samples a refine pass adds from sample `sample` on: one, or with the path tracer's regrouped
// lanes (whose launch of several samples keeps its lanes fuller than one of a sample) as many as
// the cost per pixel sample measured so far fits in the viewer's target frame time, at most a
// regrouped launch's and what the cap leaves.
int refine_pass_samples(const ViewState& state, int sample, int cap, double ms_per_pixel_sample,
                        double target_ms);

class RenderWorker {
public:
    // Opens the OpenCL device on the calling thread (throws std::runtime_error when there is
    // none), then starts the render thread.
    RenderWorker(int device_index, int packet_width, QualitySettings quality);
    ~RenderWorker();
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    void submit(ViewState state);
    void set_quality(QualitySettings quality);
    void request_screenshot(ScreenshotRequest request);
    void request_reload(ReloadRequest request);
    // Reloads finished since the last call, in the order requested.
    std::vector<ReloadResult> take_reloads();

    // The newest frame finished since the last call, if any.
    std::optional<DisplayFrame> take_frame();
    WorkerStatus status() const;
    // One-line messages for the panel's log (screenshots written, build failures), oldest first.
    std::vector<std::string> take_messages();
    const DeviceInfo& device_info() const { return device_.info; }

    // Finishes pending screenshots, abandons refinement, and stops the thread.
    void stop();

    // Called on the thread that builds a specialised kernel, before it builds: a test holds it
    // there to see what the viewer shows meanwhile. Set before the first submit.
    void set_specialise_gate(std::function<void()> gate);

private:
    struct RendererKey {
        const Scene* scene;
        uint64_t effects;
        bool double_precision;
        RenderMode mode;
        auto operator<=>(const RendererKey&) const = default;
    };
    struct CachedRenderer {
        std::shared_ptr<const Scene> scene;  // kept alive for the renderer, which refers to it
        std::unique_ptr<Renderer> renderer;
    };
    struct Job {
        std::optional<ScreenshotRequest> screenshot;
        std::optional<ReloadRequest> reload;
        std::optional<ViewState> view;
    };

    void run();
    // The next thing to do, or nothing when the thread should stop; waits while idle.
    std::optional<Job> next_job();
    // The renderer for the state's scene, effects and precision (decided once per generation by
    // the library's auto rule, so refinement never mixes float and double samples), the DE at the
    // camera probed with it; null when the build failed (the status then carries the error).
    Renderer* choose_renderer(const ViewState& state);
    // The renderer for the state's scene and effects in the given precision, building it when
    // needed; null when the build failed (the status then carries the error).
    Renderer* renderer_for(const ViewState& state, bool double_precision);
    // Builds (or finds) the renderer; on failure returns null and fills `failure`.
    Renderer* build_renderer(const std::shared_ptr<const Scene>& scene, uint64_t effects,
                             bool double_precision, RenderMode mode,
                             std::pair<std::string, std::string>* failure);
    void reload(const ReloadRequest& request);
    // The renderer with the state's specialisable parameters compiled in when it is built, else
    // `generic`, whose kernel reads every parameter (and the specialised one's build is started on
    // its own thread, so no frame waits for the compiler).
    Renderer* specialised_or(Renderer& generic, const ViewState& state);
    // Takes over a specialised renderer whose build has finished (render thread).
    void collect_specialised();
    void render_pass(Renderer& renderer, const ViewState& state);
    void render_preview(Renderer& renderer, const ViewState& state, float scale);
    // Start hints for a preview of `state` at width x height from the last preview's depths
    // (empty when the renderer or the parameters changed since: the surface may have moved).
    std::vector<float> preview_start_hints(const Renderer& renderer, const ViewState& state,
                                           int width, int height) const;
    void refine(Renderer& renderer, const ViewState& state, int sample);
    // The denoised preview's sums, added from one more sample (`first`: sample 0, which starts
    // them), and the image of the samples so far, denoised.
    // Adds a refine frame of `samples` samples to the denoised preview's sums.
    void accumulate_features(const Frame& frame, bool first, int samples);
    Image8 denoised_preview(const ViewState& state);
    // Path mode with a noise threshold: one round of adaptive sampling a pass (sample 0 starts
    // them), up to the standing view's sample cap.
    void refine_adaptive(Renderer& renderer, const ViewState& state, int sample);
    void take_screenshot(const ScreenshotRequest& request);
    void probe_camera(Renderer& renderer, const ViewState& state);
    void publish(DisplayFrame frame, const Renderer& renderer);
    void mark_idle(uint64_t generation);
    void post_message(std::string message);

    ComputeDevice device_;
    int packet_width_;
    ProgramCache cache_;
    std::map<RendererKey, CachedRenderer> renderers_;  // render thread only
    // Keys are scene addresses: each entry keeps its scene alive so no new scene can reuse the
    // address while the entry exists.
    struct Failure {
        std::shared_ptr<const Scene> scene;
        std::pair<std::string, std::string> message;  // summary, log
    };
    std::map<RendererKey, Failure> failures_;

    // Specialised renderers, by the generic renderer they stand in for (which lives as long as the
    // worker) and the values compiled in; render thread only. A failed build is not retried.
    using SpecialisedKey = std::pair<const Renderer*, std::string>;
    std::map<SpecialisedKey, CachedRenderer> specialised_;
    std::map<SpecialisedKey, bool> specialise_failed_;
    std::optional<SpecialisedKey> specialising_;  // the build in flight
    std::thread specialiser_;                     // ... its thread, which has its own cache
    ProgramCache specialise_cache_;
    // Handed over under mutex_ when the build ends: the renderer, or null when it failed.
    bool specialised_done_ = false;
    std::unique_ptr<Renderer> specialised_built_;
    std::function<void()> specialise_gate_;

    // Refinement of the current generation (render thread only).
    uint64_t accumulated_generation_ = UINT64_MAX;
    int accumulated_samples_ = 0;
    int ifs_depth_reached_ = -1;       // of the last frame that reported it (sample 0 or a preview)
    std::vector<float> accumulation_;  // sum of linear RGB over the samples
    // For the denoised preview: sums of the squares of linear RGB, of albedo, normal and alpha
    // over the samples, and sample 0's depth (empty unless the state denoises).
    std::vector<float> squares_, albedo_sum_, normal_sum_, alpha_sum_, first_depth_;
    std::optional<AdaptiveSampler> adaptive_;  // the rounds so far, under a noise threshold
    // The last preview's depths and what they were rendered with: the next preview starts its
    // rays from them, reprojected (render/prepass/reprojection.hpp), when only the camera moved.
    struct LastPreview {
        std::shared_ptr<const Scene> scene;  // held: no reloaded scene can take its address
        const Renderer* renderer = nullptr;
        std::vector<float> params;
        DepthView depths;
    };
    std::optional<LastPreview> last_preview_;
    const Renderer* probed_renderer_ = nullptr;  // renderers live as long as the worker
    glm::dvec3 probed_position_{NAN};
    std::vector<float> probed_params_;
    float probed_de_ = -1.0f;
    uint64_t chosen_generation_ = UINT64_MAX;  // the generation whose precision is decided
    bool chosen_double_ = false;
    PrecisionChooser precision_chooser_;  // posts once when auto wants double the device lacks

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<ViewState> state_;
    QualityController quality_;
    std::deque<ScreenshotRequest> screenshots_;
    std::deque<ReloadRequest> reloads_;
    std::vector<ReloadResult> reload_results_;
    std::optional<DisplayFrame> frame_;
    WorkerStatus status_;
    uint64_t previewed_generation_ = UINT64_MAX;  // the last interactive state previewed
    std::vector<std::string> messages_;
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace fgr::viewer
