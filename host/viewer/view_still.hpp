// SPDX-License-Identifier: Apache-2.0
#pragma once
// The viewer's view as a view file (view_file/view_file.hpp), and the still a view file renders
// to. Ctrl+S saves the view; F12 renders the still of the view it would save, through the
// functions `fgr render VIEW.fgrview.json` renders with (render_still, write_still) and with the
// same settings, so that a view saved in the viewer renders on the command line to the bytes of
// the viewer's own screenshot. Private to fgr_viewer.

#include <filesystem>
#include <set>
#include <string>

#include "image/image_io.hpp"
#include "output/still_image.hpp"
#include "render/environment.hpp"
#include "view_file/view_file.hpp"
#include "viewer/render_worker.hpp"

namespace fgr::viewer {

// How wide the thumbnail beside a saved view is (narrower windows keep their width).
constexpr int kViewThumbnailWidth = 160;
// What a saved view's thumbnail is named after: NAME.fgrview.json's is NAME.fgrview.png.
constexpr const char* kViewThumbnailSuffix = ".fgrview.png";

// The view of `state` (its scene, size, camera, projection, parameters, effects, mode, precision
// and path settings), lit by `environment` in the path mode, its still `samples` deep (the sample
// cap). The projection keeps only the settings of its kind, as `fgr render` reads them.
ViewFile view_of_state(const ViewState& state, const EnvironmentChoice& environment, int samples);

// What `fgr render VIEW` renders `view` of `scene` with: the request (size, camera, parameters,
// projection, prepass, samples, the path settings with the environment prepared), the still's
// settings (`packet_width` rays per work-item, 0: the device's preference) and how it is written,
// carrying the view as its text (image/embedded_view.hpp).
struct ViewStill {
    FrameRequest request;
    StillSettings settings;
    StillOutput output;
};
// Throws UsageError or std::invalid_argument for a view the scene cannot take (an unknown
// parameter, effect or mode), std::runtime_error for an environment file that cannot be read.
ViewStill still_of_view(const Scene& scene, const ViewFile& view, int packet_width);

// `image` shrunk to `width` pixels wide, its height in proportion (at least 1), each pixel the
// mean of those it covers; an image no wider is returned as it is.
Image8 shrunk_image(const Image8& image, int width);

// `directory`/STEM + `suffix`, or STEM-2, STEM-3... when that file exists or is in `taken` (two
// files asked for within a second, the first perhaps not written yet, must not collide).
std::filesystem::path unused_file(const std::filesystem::path& directory, const std::string& stem,
                                  const std::string& suffix,
                                  const std::set<std::filesystem::path>& taken);

// The thumbnail beside the view file `view_file` (NAME.fgrview.json: NAME.fgrview.png).
std::filesystem::path view_thumbnail_file(const std::filesystem::path& view_file);

}  // namespace fgr::viewer
