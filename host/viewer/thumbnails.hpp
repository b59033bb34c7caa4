// SPDX-License-Identifier: Apache-2.0
#pragma once
// The formula browser's thumbnails: each scene's default view rendered small and at low quality,
// kept in memory for the session and on disk (PNG files under the kernel cache's directory,
// "thumbnails/<key>.png") so the next start shows them without rendering. A thumbnail's key hashes
// everything that decides its image: the scene's source, parameter defaults, default camera and
// effects, and the thumbnail's size; an edited scene gets a new one.
//
// ThumbnailWorker renders them one at a time on a thread and an OpenCL context of its own, so the
// render worker's view never waits behind a thumbnail's kernel build; the viewer pauses it while
// the view is changing or refining, so thumbnails take only the time the view leaves idle.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "image/image_io.hpp"
#include "scene/scene.hpp"

namespace fgr::viewer {

constexpr int kThumbnailWidth = 128;
constexpr int kThumbnailHeight = 96;

// 16 hex digits: a 64-bit FNV-1a hash of what decides the thumbnail's image: the scene's program as
// assembled (the kernel library and the formula families it calls with it), the parameters'
// defaults, the default camera, the effects and the render mode.
std::string thumbnail_key(const Scene& scene);

// The thumbnails' folder: "thumbnails" in ProgramCache::default_directory() (FGR_CACHE_DIR ...);
// empty when there is no cache directory.
std::filesystem::path default_thumbnail_directory();

// Thumbnails on disk. Reading a missing or unreadable file gives nothing; a failed write is
// returned as its reason (a cache only saves time).
class ThumbnailDiskCache {
public:
    explicit ThumbnailDiskCache(std::filesystem::path directory);
    bool has(const std::string& key) const;
    std::optional<Image8> load(const std::string& key) const;
    std::string store(const std::string& key, const Image8& image) const;
    std::filesystem::path file(const std::string& key) const;

private:
    std::filesystem::path directory_;
};

struct Thumbnail {
    std::string key;
    std::string scene_id;
    Image8 image;       // kThumbnailWidth x kThumbnailHeight, empty when it failed
    std::string error;  // one line, when it failed
    bool from_disk = false;
};

class ThumbnailWorker {
public:
    // Starts the thread; it opens OpenCL device `device_index` itself.
    ThumbnailWorker(int device_index, int packet_width, std::filesystem::path directory);
    ~ThumbnailWorker();
    ThumbnailWorker(const ThumbnailWorker&) = delete;
    ThumbnailWorker& operator=(const ThumbnailWorker&) = delete;

    // Queues the scene's thumbnail (`key`: its thumbnail_key) unless it was asked for already.
    void request(std::shared_ptr<const Scene> scene, const std::string& key);
    // While paused, no new thumbnail starts (one being rendered finishes).
    void set_paused(bool paused);
    // Thumbnails finished since the last call.
    std::vector<Thumbnail> take_finished();
    // Whether a thumbnail is queued or being made.
    bool busy() const;

private:
    void run();
    Thumbnail make(const Scene& scene, const std::string& key);
    Image8 render(const Scene& scene);

    int device_index_;
    int packet_width_;
    ThumbnailDiskCache disk_;
    struct Device;
    std::unique_ptr<Device> device_;  // opened on the thread, on first need
    std::string device_error_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::pair<std::shared_ptr<const Scene>, std::string>> queue_;  // scene, key
    std::set<std::string> requested_;
    std::vector<Thumbnail> finished_;
    bool paused_ = false;
    bool working_ = false;
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace fgr::viewer
