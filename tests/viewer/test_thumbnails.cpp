// SPDX-License-Identifier: Apache-2.0
// The formula browser's thumbnail cache (viewer/thumbnails.hpp): the key follows everything
// that decides a thumbnail's image, and thumbnails on disk come back as they were stored, in the
// kernel cache's folder.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "child_process.hpp"
#include "device/program_cache.hpp"
#include "scene/formulas/formulas.hpp"
#include "viewer/thumbnails.hpp"

namespace fgr::viewer {
namespace {

namespace fs = std::filesystem;

Scene bulb_box() {
    const fs::path file = fs::path(FGR_TEST_FORMULA_DIR) / "bulb-box.formula.json";
    return formula_scene_to_scene(read_formula_file(file), file);
}

TEST(ThumbnailKey, FollowsTheSourceTheParametersTheCameraAndTheEffects) {
    const Scene scene = bulb_box();
    const std::string key = thumbnail_key(scene);
    EXPECT_EQ(key.size(), 16u);
    EXPECT_EQ(thumbnail_key(bulb_box()), key) << "the same scene, the same key";

    Scene other_source = scene;
    other_source.source += "\n";
    Scene other_default = scene;
    other_default.params[0].default_value[0] += 0.5f;
    Scene other_camera = scene;
    other_camera.cameras[0].view.position.x += 0.25;
    Scene other_fov = scene;
    other_fov.cameras[0].view.fov_degrees += 1.0f;
    Scene other_effects = scene;
    other_effects.effects ^= 1u;
    for (const Scene* changed :
         {&other_source, &other_default, &other_camera, &other_fov, &other_effects}) {
        EXPECT_NE(thumbnail_key(*changed), key);
    }
    Scene renamed = scene;
    renamed.name = "another name";
    EXPECT_EQ(thumbnail_key(renamed), key) << "the name does not change the image";
}

Image8 gradient() {
    Image8 image;
    image.width = kThumbnailWidth;
    image.height = kThumbnailHeight;
    image.rgb.resize(size_t(image.width) * size_t(image.height) * 3);
    for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<uint8_t>(i * 7);
    return image;
}

TEST(ThumbnailDiskCache, GivesBackWhatWasStoredAndNothingForMissingOrBadFiles) {
    const test::TempDir dir("fgr_thumbnail_test");
    const ThumbnailDiskCache cache(dir.path() / "thumbnails");
    EXPECT_FALSE(cache.has("0123456789abcdef"));
    EXPECT_FALSE(cache.load("0123456789abcdef"));
    EXPECT_EQ(cache.store("0123456789abcdef", gradient()), "");
    EXPECT_TRUE(cache.has("0123456789abcdef"));
    const std::optional<Image8> loaded = cache.load("0123456789abcdef");
    ASSERT_TRUE(loaded);
    EXPECT_EQ(loaded->rgb, gradient().rgb);

    std::ofstream(cache.file("fedcba9876543210")) << "not a PNG";
    EXPECT_FALSE(cache.load("fedcba9876543210")) << "a damaged file is made again";
    Image8 small = gradient();
    small.width = 4;
    small.height = 2;
    small.rgb.resize(4 * 2 * 3);
    EXPECT_EQ(cache.store("00000000000000aa", small), "");
    EXPECT_FALSE(cache.load("00000000000000aa")) << "a thumbnail of another size is not one";

    const ThumbnailDiskCache none{fs::path()};
    EXPECT_NE(none.store("0123456789abcdef", gradient()), "");
    EXPECT_FALSE(none.load("0123456789abcdef"));
}

TEST(ThumbnailDiskCache, LivesInTheKernelCachesFolder) {
    EXPECT_EQ(default_thumbnail_directory(), ProgramCache::default_directory() / "thumbnails");
}

}  // namespace
}  // namespace fgr::viewer
