// SPDX-License-Identifier: Apache-2.0
// Alpha and layers (host/output/still_layers.hpp): every render mode, on DE and IFS scenes,
// gives a ball's analytic depth, normal and albedo, coverage 1 on it, 0 off it and the fraction of
// hitting samples at its edge; the plain shaded kernel is untouched by the switch; and the CLI's
// RGBA PNG and EXR hold the same coverage with the background removed.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "child_process.hpp"
#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "image/display.hpp"
#include "image/image_io.hpp"
#include "output/still_image.hpp"
#include "output/still_layers.hpp"
#include "render/renderer.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

constexpr int kLayersWidth = 64, kLayersHeight = 48;
const glm::vec3 kGrey{0.75f, 0.72f, 0.68f};  // the default albedo (fgr_shade.cl, IfsMap::colour)

// A ball of radius `radius` at the origin, seen by `view`: where each pixel's rays meet it.
struct BallInView {
    CameraBasis basis;
    double radius;

    // Distance along the ray through image point (px, py) to the ball; -1 where it misses.
    double distance(double px, double py) const {
        const glm::dvec3 d(primary_ray_direction(basis, kLayersWidth, kLayersHeight,
                                                 float(px - 0.5), float(py - 0.5)));
        const glm::dvec3 o = basis.eye;
        const double b = glm::dot(o, d), c = glm::dot(o, o) - radius * radius;
        const double discriminant = b * b - c;
        return discriminant < 0.0 ? -1.0 : -b - std::sqrt(discriminant);
    }
    // How far the ray through (px, py) passes from the ball's surface, in radians as seen from
    // the eye: > 0 outside, < 0 inside the silhouette.
    double angle_outside(double px, double py) const {
        const glm::dvec3 d(primary_ray_direction(basis, kLayersWidth, kLayersHeight,
                                                 float(px - 0.5), float(py - 0.5)));
        const glm::dvec3 to_centre = -basis.eye;
        const double centre_angle =
            std::acos(std::clamp(glm::dot(d, glm::normalize(to_centre)), -1.0, 1.0));
        return centre_angle - std::asin(radius / glm::length(to_centre));
    }
    // The ball's normal where the ray through (px, py) meets it (which it must).
    glm::dvec3 normal(double px, double py) const {
        const glm::dvec3 d(primary_ray_direction(basis, kLayersWidth, kLayersHeight,
                                                 float(px - 0.5), float(py - 0.5)));
        return glm::normalize(basis.eye + d * distance(px, py));
    }
};

// How far (radians) the ball's normal turns from the pixel's centre to its corners: how far a
// normal averaged over samples anywhere in the pixel may lie from the centre's.
double normal_spread(const BallInView& ball, int x, int y) {
    const glm::dvec3 centre = ball.normal(x + 0.5, y + 0.5);
    double spread = 0.0;
    for (const double dx : {0.0, 1.0}) {
        for (const double dy : {0.0, 1.0}) {
            spread = std::max(
                spread, std::acos(std::min(1.0, glm::dot(centre, ball.normal(x + dx, y + dy)))));
        }
    }
    return spread;
}

// The angle between a rendered (averaged) normal and the ball's at the pixel's centre.
double normal_angle(const BallInView& ball, int x, int y, glm::dvec3 rendered) {
    return std::acos(
        std::min(1.0, glm::dot(glm::normalize(rendered), ball.normal(x + 0.5, y + 0.5))));
}

enum class Coverage { Inside, Edge, Outside };

// Pixels at least two footprints inside the silhouette are covered by every sample; those two
// outside by none (the march's hit threshold dilates the surface by about a footprint).
Coverage classify(const BallInView& ball, int x, int y) {
    const double margin = 2.0 * double(pixel_angle(ball.basis, kLayersWidth));
    const double centre = ball.angle_outside(x + 0.5, y + 0.5);
    if (centre < -margin) return Coverage::Inside;
    if (centre > margin) return Coverage::Outside;
    return Coverage::Edge;
}

struct LayerCase {
    const char* name;
    RenderMode mode;
    bool ifs;
    int samples;
};

void PrintTo(const LayerCase& c, std::ostream* os) { *os << c.name; }

// Sierpinski maps at depth 0: the bounding ball of radius sqrt(3), traced exactly.
IfsScene ifs_ball() {
    IfsScene ifs;
    ifs.id = "ball-test";
    ifs.name = "BallInView test";
    const double s = 0.5;
    for (const glm::dvec3 corner : {glm::dvec3(1, 1, 1), glm::dvec3(1, -1, -1),
                                    glm::dvec3(-1, 1, -1), glm::dvec3(-1, -1, 1)}) {
        IfsMap map;
        map.linear = glm::dmat3(s);
        map.offset = corner * (1.0 - s);
        map.contraction = s;
        ifs.maps.push_back(map);
    }
    ifs.bounds = {glm::dvec3(0.0), std::sqrt(3.0)};
    ifs.default_depth = 0;
    ifs.max_depth = 4;
    ifs.cameras.push_back(
        {"default", CameraView{{0.0, -6.0, 0.0}, {0.0, 0.0, 0.0}, {0, 0, 1}, 60}});
    ifs.lights.push_back(Light{});
    return ifs;
}

class StillLayersTest : public test::DeviceSuite<::testing::TestWithParam<LayerCase>> {
protected:
    static Renderer renderer(const Scene& scene, RenderMode mode, bool aovs) {
        KernelSwitches switches{preferred_packet_width(device_->info), 0, false, false, mode};
        switches.aovs = aovs;
        return Renderer(*device_, *cache_, scene, switches);
    }
};

struct BallScene {
    Scene scene;
    FrameRequest request;
    BallInView ball;
};

BallScene ball_scene(bool ifs, int samples) {
    BallScene result;
    if (ifs) {
        result.scene = ifs_scene_to_scene(ifs_ball(), "ball-test.ifs.json");
    } else {
        result.scene = test::sphere_scene();
        result.scene.cameras.front().view.position = {0.0f, -6.0f, 0.0f};
    }
    const CameraView view = result.scene.cameras.front().view;
    result.request =
        FrameRequest{kLayersWidth, kLayersHeight, view, default_param_values(result.scene)};
    if (ifs) {
        set_param_from_text(result.scene, result.request.params, "ifs_depth=0");
    } else {
        set_param_from_text(result.scene, result.request.params, "radius=1.5");
    }
    result.request.samples = samples;
    result.ball = {camera_basis(view), ifs ? std::sqrt(3.0) : 1.5};
    return result;
}

// Every layer of every pixel against the ball: depth within the pixel's range of distances (the
// path mode's first sample lies anywhere in the pixel) and two footprints, the normal within the
// ball's turn over the pixel and 1 degree (4 for the brute mode's screen-space normals), the
// albedo the scene's, coverage 1 inside, 0 outside, and a fraction of the samples at the edge.
TEST_P(StillLayersTest, EveryLayerMatchesTheAnalyticBall) {
    const LayerCase& c = GetParam();
    const BallScene ball = ball_scene(c.ifs, c.samples);
    Renderer r = renderer(ball.scene, c.mode, true);
    const Frame frame = r.render(ball.request);
    const size_t pixels = size_t(kLayersWidth) * kLayersHeight;
    ASSERT_EQ(frame.alpha.size(), pixels);
    ASSERT_EQ(frame.foreground.size(), pixels * 3);
    ASSERT_EQ(frame.albedo.size(), pixels * 3);
    ASSERT_EQ(frame.normal.size(), pixels * 3);
    const double footprint = double(pixel_angle(ball.ball.basis, kLayersWidth));
    const double normal_error = glm::radians(c.mode == RenderMode::Brute ? 4.0 : 1.0);
    int inside = 0, outside = 0, fractional = 0;
    for (int y = 0; y < kLayersHeight; ++y) {
        for (int x = 0; x < kLayersWidth; ++x) {
            const size_t i = size_t(y) * kLayersWidth + x;
            const float alpha = frame.alpha[i];
            const glm::vec3 albedo(frame.albedo[i * 3], frame.albedo[i * 3 + 1],
                                   frame.albedo[i * 3 + 2]);
            const glm::vec3 normal(frame.normal[i * 3], frame.normal[i * 3 + 1],
                                   frame.normal[i * 3 + 2]);
            const glm::vec3 foreground(frame.foreground[i * 3], frame.foreground[i * 3 + 1],
                                       frame.foreground[i * 3 + 2]);
            // Coverage counts whole samples.
            const float hits = alpha * float(frame.samples);
            EXPECT_NEAR(hits, std::round(hits), 1e-3f) << x << "," << y;
            EXPECT_TRUE(alpha >= 0.0f && alpha <= 1.0f) << x << "," << y << ": " << alpha;
            fractional += alpha > 0.0f && alpha < 1.0f;
            switch (classify(ball.ball, x, y)) {
                case Coverage::Outside:
                    ++outside;
                    EXPECT_EQ(alpha, 0.0f) << x << "," << y;
                    EXPECT_EQ(frame.depth[i], -1.0f) << x << "," << y;
                    EXPECT_EQ(glm::length(albedo) + glm::length(normal) + glm::length(foreground),
                              0.0f)
                        << x << "," << y;
                    break;
                case Coverage::Inside: {
                    ++inside;
                    EXPECT_EQ(alpha, 1.0f) << x << "," << y;
                    double nearest = 1e9, farthest = 0.0;
                    for (const double dx : {0.0, 0.5, 1.0}) {
                        for (const double dy : {0.0, 0.5, 1.0}) {
                            const double t = ball.ball.distance(x + dx, y + dy);
                            nearest = std::min(nearest, t);
                            farthest = std::max(farthest, t);
                        }
                    }
                    const double slack = 2.0 * farthest * footprint;
                    EXPECT_GE(frame.depth[i], nearest - slack) << x << "," << y;
                    EXPECT_LE(frame.depth[i], farthest + slack) << x << "," << y;
                    EXPECT_LE(normal_angle(ball.ball, x, y, glm::dvec3(normal)),
                              normal_spread(ball.ball, x, y) + normal_error)
                        << x << "," << y;
                    for (int k = 0; k < 3; ++k) {
                        EXPECT_NEAR(albedo[k], kGrey[k], 1e-5f) << x << "," << y;
                        // Every sample hit: the foreground is the whole colour.
                        EXPECT_EQ(foreground[k], frame.linear[i * 3 + k]) << x << "," << y;
                    }
                    break;
                }
                case Coverage::Edge:
                    break;
            }
        }
    }
    EXPECT_GT(inside, 200);
    EXPECT_GT(outside, 200);
    // The brute mode's passes all sample the pixel's centre: covered or not.
    if (c.samples > 1 && c.mode != RenderMode::Brute) {
        EXPECT_GT(fractional, 20) << "anti-aliased edges have fractional coverage";
    } else {
        EXPECT_EQ(fractional, 0);
    }
}

// Coverage is the fraction of the samples that hit: the mean of the samples' own coverage, each
// rendered alone (1 where that sample's camera ray met the surface, else 0).
TEST_P(StillLayersTest, CoverageIsTheFractionOfSamplesThatHit) {
    const LayerCase& c = GetParam();
    if (c.mode == RenderMode::Brute) GTEST_SKIP() << "every pass samples the pixel's centre";
    const BallScene ball = ball_scene(c.ifs, c.samples);
    Renderer r = renderer(ball.scene, c.mode, true);
    const Frame all = r.render(ball.request);
    std::vector<float> sum(all.alpha.size(), 0.0f);
    for (int s = 0; s < c.samples; ++s) {
        FrameRequest one = ball.request;
        one.first_sample = s;
        one.samples = 1;
        const Frame single = r.render(one);
        for (size_t i = 0; i < sum.size(); ++i) {
            ASSERT_TRUE(single.alpha[i] == 0.0f || single.alpha[i] == 1.0f) << i;
            sum[i] += single.alpha[i];
        }
    }
    for (size_t i = 0; i < sum.size(); ++i) {
        EXPECT_NEAR(all.alpha[i], sum[i] / float(c.samples), 1e-6f) << i;
    }
}

// The switch adds planes and leaves the image alone: colour, depth and the 8-bit image are the
// same, bit for bit, as the plain kernel's, which writes no layers (path and brute keep their
// albedo and normal).
TEST_P(StillLayersTest, TheSwitchLeavesTheImageUnchanged) {
    const LayerCase& c = GetParam();
    const BallScene ball = ball_scene(c.ifs, c.samples);
    Renderer plain_renderer = renderer(ball.scene, c.mode, false);
    Renderer layered_renderer = renderer(ball.scene, c.mode, true);
    const Frame plain = plain_renderer.render(ball.request);
    const Frame layered = layered_renderer.render(ball.request);
    EXPECT_EQ(plain.linear, layered.linear);
    EXPECT_EQ(plain.depth, layered.depth);
    EXPECT_EQ(plain.image.rgb, layered.image.rgb);
    EXPECT_TRUE(plain.foreground.empty());
    EXPECT_EQ(plain.albedo.empty(), c.mode == RenderMode::Shaded);
}

INSTANTIATE_TEST_SUITE_P(Modes, StillLayersTest,
                         ::testing::Values(LayerCase{"ShadedDe", RenderMode::Shaded, false, 16},
                                           LayerCase{"ShadedDeOneSample", RenderMode::Shaded, false,
                                                     1},
                                           LayerCase{"PathDe", RenderMode::Path, false, 8},
                                           LayerCase{"BruteDe", RenderMode::Brute, false, 4},
                                           LayerCase{"ShadedIfs", RenderMode::Shaded, true, 16},
                                           LayerCase{"PathIfs", RenderMode::Path, true, 8}),
                         [](const ::testing::TestParamInfo<LayerCase>& param_info) {
                             return std::string(param_info.param.name);
                         });

// --- The files -----------------------------------------------------------------------------------

// A frame of four pixels: covered, half covered, uncovered, covered by a bright surface.
Frame four_pixels() {
    Frame frame;
    frame.image = {4, 1, std::vector<uint8_t>(12, 7)};
    frame.linear = {0.5f, 0.25f, 0.125f, 0.3f, 0.2f, 0.1f, 0.05f, 0.05f, 0.1f, 2.0f, 0.5f, 0.0f};
    frame.foreground = {0.5f, 0.25f, 0.125f, 0.2f, 0.1f, 0.05f, 0.0f, 0.0f, 0.0f, 2.0f, 0.5f, 0.0f};
    frame.alpha = {1.0f, 0.5f, 0.0f, 1.0f};
    frame.depth = {1.0f, 2.0f, -1.0f, 3.0f};
    frame.albedo.assign(12, 0.5f);
    frame.normal.assign(12, 0.0f);
    return frame;
}

// Straight alpha: the half-covered pixel's colour is its foreground over its coverage, the
// uncovered one is black and transparent; bands of rows give the rows of the whole.
TEST(StillLayers, RgbaRowsHoldTheStraightColourAndCoverage) {
    const Frame frame = four_pixels();
    std::vector<uint16_t> rgba(16);
    rgba16_linear_rows(frame, 1.0f, whole_frame(frame), rgba);
    const std::vector<uint16_t> expected{32768, 16384, 8192, 65535, 26214, 13107, 6554, 32768,
                                         0,     0,     0,    0,     65535, 32768, 0,    65535};
    EXPECT_EQ(rgba, expected);
    std::vector<uint8_t> rgba8(16);
    rgba8_rows(frame, DisplayTransform{1.0f, ToneMap::Clamp}, whole_frame(frame), rgba8);
    EXPECT_EQ(rgba8[0], encode_srgb(0.5f));
    EXPECT_EQ(rgba8[4], encode_srgb(0.4f));  // 0.2 / 0.5: the surface's own colour
    EXPECT_EQ(rgba8[7], 128);
    EXPECT_EQ(std::vector<uint8_t>(rgba8.begin() + 8, rgba8.begin() + 12),
              std::vector<uint8_t>(4, 0));
    const std::vector<ExrLayer> layers =
        exr_layers(frame, Aovs{false, false, true, true}, whole_frame(frame));
    ASSERT_EQ(layers.size(), 3u);
    EXPECT_EQ(layers[0].values, frame.foreground);  // premultiplied
    EXPECT_EQ(layers[1].values[2], std::numeric_limits<float>::infinity());
    EXPECT_EQ(layers[2].values, frame.alpha);
    Frame no_layers = frame;
    no_layers.alpha.clear();
    EXPECT_THROW(rgba8_rows(no_layers, {}, whole_frame(frame), rgba8), std::invalid_argument);
    EXPECT_THROW(rgba8_rows(frame, {}, RowBand{0, 2}, rgba8), std::invalid_argument);
}

// Path mode's sample counts and variance go to layers of their own, after the others and before
// alpha; a frame without them (another mode) is refused in one line.
TEST(StillLayers, SamplesAndVarianceLayers) {
    Frame frame = four_pixels();
    frame.samples_per_pixel = {4.0f, 16.0f, 64.0f, 8.0f};
    frame.variance.assign(12, 0.01f);
    Aovs aovs;
    aovs.samples = true;
    aovs.variance = true;
    aovs.alpha = true;
    const std::vector<ExrLayer> layers = exr_layers(frame, aovs, whole_frame(frame));
    ASSERT_EQ(layers.size(), 4u);
    EXPECT_EQ(layers[1].name, "samples");
    EXPECT_EQ(layers[1].values, frame.samples_per_pixel);
    EXPECT_EQ(layers[2].name, "variance");
    EXPECT_EQ(layers[2].values, frame.variance);
    EXPECT_EQ(layers[3].values, frame.alpha);
    EXPECT_EQ(parse_aovs("samples,variance").samples, true);
    frame.samples_per_pixel.clear();
    EXPECT_THROW(exr_layers(frame, aovs, whole_frame(frame)), std::invalid_argument);
}

// One named float channel of an EXR file, rows top first.
std::vector<float> exr_channel(const fs::path& file, const char* name) {
    Imf::InputFile input(file.c_str());
    const Imath::Box2i window = input.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    std::vector<float> values(size_t(width) * height);
    Imf::FrameBuffer buffer;
    buffer.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), window));
    input.setFrameBuffer(buffer);
    input.readPixels(window.min.y, window.max.y);
    return values;
}

// Through the CLI, a ball swapped into a scene (--kernel-source) and seen from a known place: the
// EXR's A is 1 on the ball, 0 off it and fractional at its edge, its depth the analytic one (+Inf
// where missed), its normal and albedo the ball's, its colour premultiplied (0 where A is 0); the
// PNG with --alpha has the same coverage in 8 and 16 bits, the EXR's colour over its coverage
// (straight), the plain image's colour where fully covered and black where not covered. The shaded
// mode's layers, once refused, are there.
TEST(StillLayersCli, ExrAndPngCarryCoverageAndTheBallsLayers) {
    test::TempDir dir("fgr_layers");
    const fs::path ball_source = dir.path() / "ball.cl";
    std::ofstream(ball_source) << "real scene_de(vec3 p, PARAMS) { (void)fgr_params; "
                                  "return v3_length(p) - 1.5f; }\n";
    const std::vector<std::string> args{"render",
                                        "mandelbulb",
                                        "--kernel-source",
                                        ball_source.string(),
                                        "--eye",
                                        "0,-6,0",
                                        "--target",
                                        "0,0,0",
                                        "--up",
                                        "0,0,1",
                                        "--fov",
                                        "60",
                                        "--width",
                                        std::to_string(kLayersWidth),
                                        "--height",
                                        std::to_string(kLayersHeight),
                                        "--spp",
                                        "8",
                                        "--set",
                                        "tone_map=clamp",
                                        "--set",
                                        "exposure=1"};
    const auto render = [&](const std::string& file, std::vector<std::string> extra) {
        std::vector<std::string> all = args;
        all.insert(all.end(), {"-o", (dir.path() / file).string()});
        all.insert(all.end(), extra.begin(), extra.end());
        const test::RunResult result = test::run_fgr(all, dir.path());
        EXPECT_EQ(result.exit_code, 0) << result;
        return dir.path() / file;
    };
    const fs::path exr = render("layers.exr", {"--aov", "albedo,normal,depth,alpha"});
    const fs::path plain_exr = render("plain.exr", {});
    const fs::path png = render("alpha.png", {"--alpha"});
    const fs::path png16 = render("alpha16.png", {"--alpha", "--bit-depth", "16"});
    const fs::path plain_png = render("plain.png", {});

    const std::vector<float> a = exr_channel(exr, "A"), depth = exr_channel(exr, "depth.Z");
    const std::vector<float> r = exr_channel(exr, "R"), plain_r = exr_channel(plain_exr, "R");
    const std::vector<float> nx = exr_channel(exr, "normal.X"), ny = exr_channel(exr, "normal.Y"),
                             nz = exr_channel(exr, "normal.Z");
    const std::vector<float> albedo_g = exr_channel(exr, "albedo.G");
    const PngSamples rgba = read_png_samples(png), rgba16 = read_png_samples(png16);
    const Image8 plain = read_png(plain_png);
    ASSERT_EQ(rgba.channels, 4);
    ASSERT_EQ(rgba.bit_depth, 8);
    ASSERT_EQ(rgba16.channels, 4);
    ASSERT_EQ(rgba16.bit_depth, 16);
    const BallInView ball{camera_basis(CameraView{{0, -6, 0}, {0, 0, 0}, {0, 0, 1}, 60}), 1.5};
    int inside = 0, outside = 0, fractional = 0;
    for (int y = 0; y < kLayersHeight; ++y) {
        for (int x = 0; x < kLayersWidth; ++x) {
            const size_t i = size_t(y) * kLayersWidth + x;
            EXPECT_EQ(rgba.samples[i * 4 + 3], std::lround(a[i] * 255.0f)) << x << "," << y;
            EXPECT_EQ(rgba16.samples[i * 4 + 3], std::lround(a[i] * 65535.0f)) << x << "," << y;
            fractional += a[i] > 0.0f && a[i] < 1.0f;
            if (a[i] > 0.0f) {
                // Straight in the PNG, premultiplied in the EXR: the PNG's colour is the EXR's
                // over its coverage (exposure 1, clamped; rounding to the file's steps).
                const float straight = std::min(r[i] / a[i], 1.0f);
                EXPECT_NEAR(rgba16.samples[i * 4], straight * 65535.0f, 1.5f) << x << "," << y;
                EXPECT_NEAR(rgba.samples[i * 4], encode_srgb(straight), 1.0f) << x << "," << y;
            }
            if (a[i] == 0.0f) {
                EXPECT_EQ(r[i], 0.0f);
                for (int k = 0; k < 3; ++k) EXPECT_EQ(rgba.samples[i * 4 + k], 0);
            }
            if (a[i] == 1.0f) {
                EXPECT_EQ(r[i], plain_r[i]);
                for (int k = 0; k < 3; ++k)
                    EXPECT_EQ(rgba.samples[i * 4 + k], plain.rgb[i * 3 + k]);
            }
            const Coverage coverage = classify(ball, x, y);
            if (coverage == Coverage::Outside) {
                ++outside;
                EXPECT_EQ(a[i], 0.0f) << x << "," << y;
                EXPECT_EQ(depth[i], std::numeric_limits<float>::infinity()) << x << "," << y;
            } else if (coverage == Coverage::Inside) {
                ++inside;
                EXPECT_EQ(a[i], 1.0f) << x << "," << y;
                const double t = ball.distance(x + 0.5, y + 0.5);  // sample 0: the centre
                EXPECT_NEAR(depth[i], t, 2.0 * t * double(pixel_angle(ball.basis, kLayersWidth)));
                EXPECT_LE(normal_angle(ball, x, y, glm::dvec3(nx[i], ny[i], nz[i])),
                          normal_spread(ball, x, y) + glm::radians(1.0))
                    << x << "," << y;
                EXPECT_NEAR(albedo_g[i], kGrey.g, 1e-5f);
            }
        }
    }
    EXPECT_GT(inside, 200);
    EXPECT_GT(outside, 200);
    EXPECT_GT(fractional, 20);
}

}  // namespace
}  // namespace fgr
