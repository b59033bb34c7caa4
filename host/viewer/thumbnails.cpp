// SPDX-License-Identifier: Apache-2.0
#include "viewer/thumbnails.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstring>
#include <string_view>

#include "device/kernel_assembly.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "util/content_hash.hpp"

namespace fgr::viewer {
namespace {

// Changes whenever the way thumbnails are rendered does, so old files are never shown.
constexpr std::string_view kThumbnailFormat = "fgr-thumbnail-1";

// The scene's program as the thumbnail renders it, the kernel library's files and the formula
// families it calls included: a newer fgr's kernels make new thumbnails. (A scene whose program
// cannot be assembled has no thumbnail to render; its source stands in.)
std::string program_source(const Scene& scene) {
    KernelSwitches switches;
    switches.effects = scene.effects;
    switches.mode = scene.default_mode;
    try {
        return assemble_program(scene, switches).source;
    } catch (const std::exception&) {
        return scene.source;
    }
}

}  // namespace

std::string thumbnail_key(const Scene& scene) {
    ContentHash hash;
    hash.add(kThumbnailFormat).add(program_source(scene));
    const std::vector<float> params = default_param_values(scene);
    hash.add({reinterpret_cast<const char*>(params.data()), params.size() * sizeof(float)});
    const CameraView& view = scene.cameras.front().view;
    for (int i = 0; i < 3; ++i) {
        hash.add_bytes_of(view.position[i]).add_bytes_of(view.target[i]).add_bytes_of(view.up[i]);
    }
    hash.add_bytes_of(view.fov_degrees)
        .add_bytes_of(scene.effects)
        .add_bytes_of(scene.default_mode);
    hash.add(fmt::format("{}x{}", kThumbnailWidth, kThumbnailHeight));
    return hash.hex();
}

std::filesystem::path default_thumbnail_directory() {
    const std::filesystem::path kernels = ProgramCache::default_directory();
    return kernels.empty() ? kernels : kernels / "thumbnails";
}

// --- On disk ---------------------------------------------------------------------------------

ThumbnailDiskCache::ThumbnailDiskCache(std::filesystem::path directory)
    : directory_(std::move(directory)) {}

std::filesystem::path ThumbnailDiskCache::file(const std::string& key) const {
    return directory_ / (key + ".png");
}

bool ThumbnailDiskCache::has(const std::string& key) const {
    std::error_code error;
    return !directory_.empty() && std::filesystem::is_regular_file(file(key), error);
}

std::optional<Image8> ThumbnailDiskCache::load(const std::string& key) const {
    if (directory_.empty()) return std::nullopt;
    std::error_code error;
    if (!std::filesystem::is_regular_file(file(key), error)) return std::nullopt;
    try {
        Image8 image = read_png(file(key));
        if (image.width != kThumbnailWidth || image.height != kThumbnailHeight) return std::nullopt;
        return image;
    } catch (const std::exception&) {
        return std::nullopt;  // a damaged file is rendered again and replaced
    }
}

std::string ThumbnailDiskCache::store(const std::string& key, const Image8& image) const {
    if (directory_.empty()) return "no cache directory";
    try {
        std::filesystem::create_directories(directory_);
        write_png(file(key), image);  // written beside, then renamed: never a partial file
    } catch (const std::exception& error) {
        return error.what();
    }
    return {};
}

// --- The worker ------------------------------------------------------------------------------

struct ThumbnailWorker::Device {
    ComputeDevice device;
    ProgramCache cache;
};

ThumbnailWorker::ThumbnailWorker(int device_index, int packet_width,
                                 std::filesystem::path directory)
    : device_index_(device_index), packet_width_(packet_width), disk_(std::move(directory)) {
    thread_ = std::thread([this] { run(); });
}

ThumbnailWorker::~ThumbnailWorker() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void ThumbnailWorker::request(std::shared_ptr<const Scene> scene, const std::string& key) {
    {
        std::lock_guard lock(mutex_);
        if (!requested_.insert(key).second) return;
        queue_.emplace_back(std::move(scene), key);
    }
    wake_.notify_all();
}

void ThumbnailWorker::set_paused(bool paused) {
    {
        std::lock_guard lock(mutex_);
        if (paused_ == paused) return;
        paused_ = paused;
    }
    wake_.notify_all();
}

std::vector<Thumbnail> ThumbnailWorker::take_finished() {
    std::lock_guard lock(mutex_);
    return std::exchange(finished_, {});
}

bool ThumbnailWorker::busy() const {
    std::lock_guard lock(mutex_);
    return working_ || !queue_.empty();
}

void ThumbnailWorker::run() {
    for (;;) {
        std::pair<std::shared_ptr<const Scene>, std::string> job;
        {
            std::unique_lock lock(mutex_);
            // Files already on disk are read even while paused: that costs the view nothing.
            wake_.wait(lock, [this] {
                return stopping_ ||
                       (!queue_.empty() && (!paused_ || disk_.has(queue_.front().second)));
            });
            if (stopping_) return;
            job = std::move(queue_.front());
            queue_.pop_front();
            working_ = true;
        }
        Thumbnail thumbnail = make(*job.first, job.second);
        std::lock_guard lock(mutex_);
        finished_.push_back(std::move(thumbnail));
        working_ = false;
    }
}

Thumbnail ThumbnailWorker::make(const Scene& scene, const std::string& key) {
    Thumbnail thumbnail{key, scene.id, {}, {}, false};
    if (std::optional<Image8> cached = disk_.load(key)) {
        thumbnail.image = std::move(*cached);
        thumbnail.from_disk = true;
        spdlog::info("thumbnail of '{}' read from {}", scene.id, disk_.file(key).string());
        return thumbnail;
    }
    try {
        thumbnail.image = render(scene);
    } catch (const std::exception& error) {
        thumbnail.error = fmt::format("thumbnail of '{}': {}", scene.id, error.what());
        spdlog::warn("{}", thumbnail.error);
        return thumbnail;
    }
    if (const std::string failed = disk_.store(key, thumbnail.image); !failed.empty()) {
        spdlog::debug("thumbnail of '{}' not cached: {}", scene.id, failed);
    }
    spdlog::info("thumbnail of '{}' rendered", scene.id);
    return thumbnail;
}

Image8 ThumbnailWorker::render(const Scene& scene) {
    if (!device_) {
        if (!device_error_.empty()) throw std::runtime_error(device_error_);
        try {
            ComputeDevice device = open_device(device_index_);
            device_ = std::make_unique<Device>(
                Device{std::move(device), ProgramCache(ProgramCache::default_directory())});
        } catch (const std::exception& error) {
            device_error_ = error.what();
            throw;
        }
    }
    const int packet_width =
        packet_width_ ? packet_width_ : preferred_packet_width(device_->device.info);
    // The switches the view starts a scene with (its effects, in its own mode: an inside-only
    // scene renders only in the brute-force one), so the kernel cached on disk serves both.
    Renderer renderer(
        device_->device, device_->cache, scene,
        KernelSwitches{packet_width, scene.effects, false, false, scene.default_mode});
    FrameRequest request;
    request.width = kThumbnailWidth;
    request.height = kThumbnailHeight;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    request.samples = 1;
    return std::move(renderer.render(request).image);
}

}  // namespace fgr::viewer
