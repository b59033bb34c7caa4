// SPDX-License-Identifier: Apache-2.0
// Environments: the kernel's lookup and importance sampling (fgr_environment.cl), run through test
// kernels at every packet width and precision and judged against host truths (χ² of the sampled
// directions against the kernel's own pdf integrated over bins, the pdf's integral, the Monte
// Carlo estimate of the map's integral, texels known by construction); the generated maps (the
// Preetham sky and sun against published values and their symmetries, the studio); and the
// tables' validation.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "kernel_test_program.hpp"
#include "render/environment.hpp"
#include "test_math.hpp"

namespace fgr {
namespace {

using test::kPi;
using test::upper_gamma_q;

// One packet per work-item; inputs and outputs are planes of floats, lane i of packet p at
// p * FGR_WIDTH + i.
constexpr const char* kEnvironmentTestKernels = R"CL(
#if FGR_WIDTH == 1
#define t_load(i, p) convert_real((p)[i])
#define t_store(v, i, p) ((p)[i] = convert_float_lanes(v))
#else
#define t_load(i, p) convert_real(FGR_PASTE(vload, FGR_WIDTH)((i), (p)))
#define t_store(v, i, p) FGR_PASTE(vstore, FGR_WIDTH)(convert_float_lanes(v), (i), (p))
#endif

/* out: x, y, z, pdf, r, g, b planes of the directions drawn from (u1, u2) and their radiance. */
__kernel void env_test_sample(__global const float* u1, __global const float* u2,
                              __global float* out, int plane, int packets, ENVIRONMENT) {
    const int p = get_global_id(0);
    if (p >= packets) return;
    real pdf;
    vec3 c;
    vec3 d = environment_sample_radiance(t_load(p, u1), t_load(p, u2), FGR_TRUE,
                                         ENVIRONMENT_PASS, &pdf, &c);
    t_store(d.x, p, out);
    t_store(d.y, p, out + plane);
    t_store(d.z, p, out + 2 * plane);
    t_store(pdf, p, out + 3 * plane);
    t_store(c.x, p, out + 4 * plane);
    t_store(c.y, p, out + 5 * plane);
    t_store(c.z, p, out + 6 * plane);
}

/* dirs: x, y, z planes; out: r, g, b, pdf planes. */
__kernel void env_test_evaluate(__global const float* dirs, __global float* out, int plane,
                                int packets, ENVIRONMENT) {
    const int p = get_global_id(0);
    if (p >= packets) return;
    vec3 d = v3(t_load(p, dirs), t_load(p, dirs + plane), t_load(p, dirs + 2 * plane));
    vec3 c = environment_radiance(d, FGR_TRUE, ENVIRONMENT_PASS);
    t_store(c.x, p, out);
    t_store(c.y, p, out + plane);
    t_store(c.z, p, out + 2 * plane);
    t_store(environment_pdf(d, FGR_TRUE, ENVIRONMENT_PASS), p, out + 3 * plane);
}
)CL";

struct Variant {
    int width;
    bool double_precision;
};

std::string label(Variant v) {
    return fmt::format("{}{}", v.double_precision ? "double" : "float", v.width);
}

double luminance(glm::dvec3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

struct Sampled {
    std::vector<glm::dvec3> directions;
    std::vector<double> pdf;
    std::vector<glm::dvec3> radiance;
};
struct Evaluated {
    std::vector<glm::dvec3> radiance;
    std::vector<double> pdf;
};

class EnvironmentTest : public test::DeviceSuite<> {
protected:
    static std::vector<Variant> variants() {
        std::vector<Variant> list;
        for (bool double_precision : {false, true}) {
            if (double_precision && !device_->info.has_fp64) continue;
            for (int width : {1, 4, 8, 16}) {
                // Double lanes need at least 4 rays per work-item (precision.hpp).
                if (double_precision && width == 1) continue;
                list.push_back({width, double_precision});
            }
        }
        return list;
    }

    static cl::Program program(Variant v) {
        return test::build_library_test_program(*device_, *cache_, kEnvironmentTestKernels, v.width,
                                                v.double_precision);
    }

    // Runs `name` over `count` lanes (padded to whole packets) with the planes in `inputs`,
    // returning `out_planes` planes of `count` floats.
    static std::vector<std::vector<float>> run(Variant v, const char* name,
                                               const std::vector<std::vector<float>>& inputs,
                                               int out_planes, const EnvironmentTables& tables,
                                               const EnvironmentInfo& info, size_t count) {
        const size_t packets = (count + size_t(v.width) - 1) / size_t(v.width);
        const size_t plane = packets * size_t(v.width);
        cl::Program built = program(v);
        cl::Kernel kernel(built, name);
        std::vector<cl::Buffer> buffers;
        std::vector<float> env_data = tables.data;
        cl::Buffer env(device_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                       env_data.size() * sizeof(float), env_data.data());
        int arg = 0;
        if (inputs.size() == 3) {
            // One buffer of three planes (directions).
            std::vector<float> joined(3 * plane, 0.0f);
            for (size_t c = 0; c < 3; ++c) {
                std::copy(inputs[c].begin(), inputs[c].end(), joined.begin() + c * plane);
            }
            buffers.emplace_back(device_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                 joined.size() * sizeof(float), joined.data());
            kernel.setArg(arg++, buffers.back());
        } else {
            for (const std::vector<float>& input : inputs) {
                std::vector<float> padded(plane, 0.0f);
                std::copy(input.begin(), input.end(), padded.begin());
                buffers.emplace_back(device_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                     padded.size() * sizeof(float), padded.data());
                kernel.setArg(arg++, buffers.back());
            }
        }
        cl::Buffer out(device_->context, CL_MEM_WRITE_ONLY,
                       size_t(out_planes) * plane * sizeof(float));
        kernel.setArg(arg++, out);
        kernel.setArg(arg++, cl_int(plane));
        kernel.setArg(arg++, cl_int(packets));
        kernel.setArg(arg++, env);
        kernel.setArg(arg++, info);
        device_->queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(packets),
                                            cl::NDRange(1));
        std::vector<float> all(size_t(out_planes) * plane);
        device_->queue.enqueueReadBuffer(out, CL_TRUE, 0, all.size() * sizeof(float), all.data());
        std::vector<std::vector<float>> planes;
        for (int c = 0; c < out_planes; ++c) {
            planes.emplace_back(all.begin() + c * plane, all.begin() + c * plane + count);
        }
        return planes;
    }

    static Sampled sample(Variant v, const EnvironmentTables& tables, const EnvironmentInfo& info,
                          const std::vector<float>& u1, const std::vector<float>& u2) {
        const auto planes = run(v, "env_test_sample", {u1, u2}, 7, tables, info, u1.size());
        Sampled result;
        for (size_t i = 0; i < u1.size(); ++i) {
            result.directions.emplace_back(planes[0][i], planes[1][i], planes[2][i]);
            result.pdf.push_back(planes[3][i]);
            result.radiance.emplace_back(planes[4][i], planes[5][i], planes[6][i]);
        }
        return result;
    }

    static Evaluated evaluate(Variant v, const EnvironmentTables& tables,
                              const EnvironmentInfo& info,
                              const std::vector<glm::dvec3>& directions) {
        std::vector<std::vector<float>> xyz(3);
        for (const glm::dvec3& d : directions) {
            for (int c = 0; c < 3; ++c) xyz[size_t(c)].push_back(float(d[c]));
        }
        const auto planes = run(v, "env_test_evaluate", xyz, 4, tables, info, directions.size());
        Evaluated result;
        for (size_t i = 0; i < directions.size(); ++i) {
            result.radiance.emplace_back(planes[0][i], planes[1][i], planes[2][i]);
            result.pdf.push_back(planes[3][i]);
        }
        return result;
    }
};

std::vector<float> uniforms(std::mt19937& random, size_t count) {
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> values(count);
    for (float& value : values) value = uniform(random);
    return values;
}

// A map with a gradient (brighter towards the top and along u), a few black texels, and a small
// spot 500 times brighter than its surroundings.
HdrImage spot_and_gradient(int width, int height) {
    HdrImage map;
    map.width = width;
    map.height = height;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float g =
                0.1f + 1.5f * float(height - y) / float(height) + 0.5f * float(x) / float(width);
            glm::vec3 c(g, 0.8f * g, 0.6f * g + 0.05f);
            if (x == 3 && y == height - 2) c = glm::vec3(0.0f);
            if (y == 1 && x >= width / 2 && x < width / 2 + 3) c = glm::vec3(0.0f);
            if (x == width / 3 && y == height / 3) c = glm::vec3(600.0f, 500.0f, 300.0f);
            map.rgb.insert(map.rgb.end(), {c.r, c.g, c.b});
        }
    }
    return map;
}

glm::dvec3 texel(const HdrImage& map, int x, int y) {
    const size_t i = map.pixel_index(x, y);
    return {map.rgb[i], map.rgb[i + 1], map.rgb[i + 2]};
}

// ---- Sampling ----

// χ² (Mitsuba 3's chi2 test, in its structure): directions drawn by the kernel are counted in
// bins, 2 x 2 per texel (split evenly in theta and phi, so unequal in solid angle: a sampler
// uniform in theta rather than in solid angle inside a texel fails), aligned with the rotated
// texels; each bin's expected count is N times the kernel's pdf integrated over it (2 x 2
// midpoint points, exact for the piecewise-constant pdf, times the bins' exact solid angles).
// Bins expecting fewer than 5 are pooled. Significance 0.01, Bonferroni-corrected over the
// variants and rotations tested.
TEST_F(EnvironmentTest, SampledDirectionsFollowThePdf) {
    const HdrImage map = spot_and_gradient(32, 16);
    const EnvironmentTables tables = environment_tables(map);
    const std::vector<double> rotations = {0.0, 73.5};
    const std::vector<Variant> tested = variants();
    const double alpha = 0.01 / double(tested.size() * rotations.size());
    constexpr size_t kSamples = 120000;
    constexpr int kSub = 2;     // bins per texel, each way
    constexpr int kPoints = 2;  // quadrature points per bin, each way
    const int bins_u = map.width * kSub, bins_v = map.height * kSub;
    for (const Variant v : tested) {
        for (const double rotation : rotations) {
            SCOPED_TRACE(fmt::format("{} rotation {}", label(v), rotation));
            const EnvironmentInfo info = environment_info(tables, rotation);
            // Expected probabilities from the kernel's pdf.
            std::vector<glm::dvec3> points;
            std::vector<double> point_weight;
            std::vector<size_t> point_bin;
            for (int by = 0; by < bins_v; ++by) {
                for (int bx = 0; bx < bins_u; ++bx) {
                    for (int j = 0; j < kPoints; ++j) {
                        const double v0 = (by + double(j) / kPoints) / bins_v;
                        const double v1 = (by + double(j + 1) / kPoints) / bins_v;
                        const double solid_angle = 2.0 * kPi / (bins_u * kPoints) *
                                                   (std::cos(kPi * v0) - std::cos(kPi * v1));
                        for (int i = 0; i < kPoints; ++i) {
                            const double u = (bx + (i + 0.5) / kPoints) / bins_u;
                            const double vm = 0.5 * (v0 + v1);
                            points.push_back(rotate_environment_direction(
                                environment_direction(u, vm), rotation));
                            point_weight.push_back(solid_angle);
                            point_bin.push_back(size_t(by * bins_u + bx));
                        }
                    }
                }
            }
            const Evaluated at_points = evaluate(v, tables, info, points);
            std::vector<double> expected(size_t(bins_u * bins_v), 0.0);
            double integral = 0.0;
            for (size_t i = 0; i < points.size(); ++i) {
                expected[point_bin[i]] += at_points.pdf[i] * point_weight[i];
                integral += at_points.pdf[i] * point_weight[i];
            }
            EXPECT_NEAR(integral, 1.0, 1e-4);
            for (double& e : expected) e *= double(kSamples);

            std::mt19937 random(1234u + unsigned(v.width) * 7u + (v.double_precision ? 1u : 0u));
            const std::vector<float> u1 = uniforms(random, kSamples);
            const std::vector<float> u2 = uniforms(random, kSamples);
            const Sampled drawn = sample(v, tables, info, u1, u2);
            std::vector<double> observed(expected.size(), 0.0);
            size_t bad = 0;
            for (size_t i = 0; i < kSamples; ++i) {
                const glm::dvec3 d = drawn.directions[i];
                if (!std::isfinite(drawn.pdf[i]) || !(drawn.pdf[i] > 0.0) ||
                    std::abs(glm::length(d) - 1.0) > 1e-4) {
                    ++bad;
                    continue;
                }
                const glm::dvec2 uv =
                    environment_coordinates(rotate_environment_direction(d, -rotation));
                const int bx = std::clamp(int(uv.x * bins_u), 0, bins_u - 1);
                const int by = std::clamp(int(uv.y * bins_v), 0, bins_v - 1);
                observed[size_t(by * bins_u + bx)] += 1.0;
            }
            ASSERT_EQ(bad, 0u) << "samples with a non-unit direction or a pdf not > 0";

            // Pool the bins that expect fewer than 5; none may see samples it expects none of.
            double chi2 = 0.0, pooled_expected = 0.0, pooled_observed = 0.0;
            int cells = 0;
            for (size_t b = 0; b < expected.size(); ++b) {
                if (expected[b] == 0.0) {
                    ASSERT_EQ(observed[b], 0.0) << "samples in bin " << b << " of pdf 0";
                } else if (expected[b] < 5.0) {
                    pooled_expected += expected[b];
                    pooled_observed += observed[b];
                } else {
                    chi2 += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
                    ++cells;
                }
            }
            if (pooled_expected > 0.0) {
                chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                        pooled_expected;
                ++cells;
            }
            const double p_value = upper_gamma_q(0.5 * (cells - 1), 0.5 * chi2);
            EXPECT_GT(p_value, alpha) << "chi2 " << chi2 << " over " << cells << " cells";
        }
    }
}

// The pdf and radiance environment_sample_radiance reports for each direction are
// environment_pdf's and environment_radiance's there.
TEST_F(EnvironmentTest, SampleReportsThePdfOfItsDirection) {
    const HdrImage map = spot_and_gradient(24, 12);
    const EnvironmentTables tables = environment_tables(map);
    const EnvironmentInfo info = environment_info(tables, 200.0, 1.5f);
    for (const Variant v : variants()) {
        SCOPED_TRACE(label(v));
        std::mt19937 random(99u);
        const std::vector<float> u1 = uniforms(random, 4000), u2 = uniforms(random, 4000);
        const Sampled drawn = sample(v, tables, info, u1, u2);
        const Evaluated at = evaluate(v, tables, info, drawn.directions);
        size_t differing = 0;
        for (size_t i = 0; i < drawn.pdf.size(); ++i) {
            // A float direction within rounding of a texel edge may land in the neighbour.
            if (std::abs(at.pdf[i] - drawn.pdf[i]) > 1e-4 * drawn.pdf[i] ||
                glm::length(at.radiance[i] - drawn.radiance[i]) >
                    1e-6 * glm::length(drawn.radiance[i])) {
                ++differing;
            }
        }
        EXPECT_LE(differing, 4u);
    }
}

// E[radiance(d) / pdf(d)] over the kernel's samples is the integral of the radiance over the
// sphere (the texels times their solid angles, times the intensity), within 4 standard errors
// estimated from the same samples (per channel; 4 rather than 3 because 24 such comparisons
// run, so one 3-sigma excursion in them would not be unusual).
TEST_F(EnvironmentTest, EstimatorIsUnbiased) {
    const HdrImage map = spot_and_gradient(32, 16);
    const EnvironmentTables tables = environment_tables(map);
    constexpr float kIntensity = 2.5f;
    const EnvironmentInfo info = environment_info(tables, 120.0, kIntensity);
    glm::dvec3 truth(0.0);
    for (int y = 0; y < map.height; ++y) {
        for (int x = 0; x < map.width; ++x) {
            truth += texel(map, x, y) * environment_texel_solid_angle(y, map.width, map.height) *
                     double(kIntensity);
        }
    }
    EXPECT_NEAR(tables.luminance_integral * kIntensity, luminance(truth), 1e-9 * luminance(truth));
    constexpr size_t kSamples = 40000;
    for (const Variant v : variants()) {
        SCOPED_TRACE(label(v));
        std::mt19937 random(4242u + unsigned(v.width));
        const std::vector<float> u1 = uniforms(random, kSamples), u2 = uniforms(random, kSamples);
        const Sampled drawn = sample(v, tables, info, u1, u2);
        const Evaluated at = evaluate(v, tables, info, drawn.directions);
        glm::dvec3 sum(0.0), sum2(0.0);
        for (size_t i = 0; i < kSamples; ++i) {
            const glm::dvec3 f = at.radiance[i] / drawn.pdf[i];
            sum += f;
            sum2 += f * f;
        }
        const glm::dvec3 mean = sum / double(kSamples);
        const glm::dvec3 variance = (sum2 / double(kSamples) - mean * mean);
        for (int c = 0; c < 3; ++c) {
            const double standard_error = std::sqrt(variance[c] / double(kSamples - 1));
            EXPECT_LE(std::abs(mean[c] - truth[c]), 4.0 * standard_error)
                << "channel " << c << ": mean " << mean[c] << ", integral " << truth[c];
        }
    }
}

// Over a map whose luminance is the same everywhere (its colour varying), luminance / pdf is the
// same for every sample: 4 pi times that luminance (importance sampling is exact there).
TEST_F(EnvironmentTest, ConstantLuminanceIsSampledExactly) {
    HdrImage map;
    map.width = 20;
    map.height = 10;
    std::mt19937 colours(7u);
    std::uniform_real_distribution<float> uniform(0.05f, 1.0f);
    constexpr double kLuminance = 0.7;
    for (int i = 0; i < map.width * map.height; ++i) {
        const glm::dvec3 c(uniform(colours), uniform(colours), uniform(colours));
        const glm::dvec3 scaled = c * (kLuminance / luminance(c));
        map.rgb.insert(map.rgb.end(), {float(scaled.x), float(scaled.y), float(scaled.z)});
    }
    const EnvironmentTables tables = environment_tables(map);
    const EnvironmentInfo info = environment_info(tables, 45.0);
    for (const Variant v : variants()) {
        SCOPED_TRACE(label(v));
        std::mt19937 random(5u);
        const std::vector<float> u1 = uniforms(random, 3000), u2 = uniforms(random, 3000);
        const Sampled drawn = sample(v, tables, info, u1, u2);
        const Evaluated at = evaluate(v, tables, info, drawn.directions);
        size_t off = 0;
        for (size_t i = 0; i < drawn.pdf.size(); ++i) {
            const double ratio = luminance(at.radiance[i]) / drawn.pdf[i];
            // Float texels and CDF steps: ~1e-6 relative; a lookup that lands in a neighbour
            // texel still has the same luminance.
            if (std::abs(ratio - 4.0 * kPi * kLuminance) > 1e-4 * 4.0 * kPi * kLuminance) ++off;
        }
        EXPECT_EQ(off, 0u);
    }
}

// A black map is sampled uniformly over the sphere (pdf 1 / 4 pi everywhere), without NaN.
TEST_F(EnvironmentTest, BlackMapIsSampledUniformly) {
    HdrImage map;
    map.width = 16;
    map.height = 8;
    map.rgb.assign(16 * 8 * 3, 0.0f);
    const EnvironmentTables tables = environment_tables(map);
    EXPECT_EQ(tables.luminance_integral, 0.0);
    const EnvironmentInfo info = environment_info(tables);
    for (const Variant v : variants()) {
        SCOPED_TRACE(label(v));
        std::mt19937 random(11u);
        const std::vector<float> u1 = uniforms(random, 2000), u2 = uniforms(random, 2000);
        const Sampled drawn = sample(v, tables, info, u1, u2);
        const Evaluated at = evaluate(v, tables, info, drawn.directions);
        double mean_z = 0.0;
        for (size_t i = 0; i < drawn.pdf.size(); ++i) {
            ASSERT_NEAR(drawn.pdf[i], 1.0 / (4.0 * kPi), 1e-5);
            ASSERT_NEAR(at.pdf[i], 1.0 / (4.0 * kPi), 1e-5);
            ASSERT_EQ(at.radiance[i], glm::dvec3(0.0));
            ASSERT_NEAR(glm::length(drawn.directions[i]), 1.0, 1e-4);
            mean_z += drawn.directions[i].z / double(drawn.pdf.size());
        }
        // Uniform on the sphere: z uniform in [-1, 1], standard error sqrt(1/3 / 2000) = 0.013.
        EXPECT_NEAR(mean_z, 0.0, 4.0 * 0.013);
    }
}

// One texel, and a map spanning 60 orders of magnitude with black texels between, sample
// without NaN or Inf, also at u = 0, u just below 1, u = 1 and NaN u.
TEST_F(EnvironmentTest, ExtremeMapsSampleWithoutNaN) {
    HdrImage one;
    one.width = 1;
    one.height = 1;
    one.rgb = {2.0f, 3.0f, 4.0f};
    HdrImage wide;
    wide.width = 64;
    wide.height = 32;
    std::mt19937 values(3u);
    std::uniform_real_distribution<float> exponent(-30.0f, 30.0f);
    for (int i = 0; i < 64 * 32; ++i) {
        const float value = i % 5 == 0 ? 0.0f : std::pow(10.0f, exponent(values));
        wide.rgb.insert(wide.rgb.end(), {value, value * 0.5f, value});
    }
    const float below_one = std::nextafter(1.0f, 0.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const HdrImage* map : {&one, &wide}) {
        const EnvironmentTables tables = environment_tables(*map);
        const EnvironmentInfo info = environment_info(tables, 10.0, 1.0f);
        for (const Variant v : variants()) {
            SCOPED_TRACE(fmt::format("{}x{} {}", map->width, map->height, label(v)));
            std::mt19937 random(17u);
            std::vector<float> u1 = uniforms(random, 1000), u2 = uniforms(random, 1000);
            for (float edge : {0.0f, below_one, 1.0f, nan}) {
                for (float other : {0.0f, 0.5f, below_one, 1.0f, nan}) {
                    u1.push_back(edge);
                    u2.push_back(other);
                    u1.push_back(other);
                    u2.push_back(edge);
                }
            }
            const Sampled drawn = sample(v, tables, info, u1, u2);
            const Evaluated at = evaluate(v, tables, info, drawn.directions);
            for (size_t i = 0; i < drawn.pdf.size(); ++i) {
                ASSERT_TRUE(std::isfinite(drawn.pdf[i]) && drawn.pdf[i] > 0.0)
                    << "u = (" << u1[i] << ", " << u2[i] << "): pdf " << drawn.pdf[i];
                ASSERT_NEAR(glm::length(drawn.directions[i]), 1.0, 1e-4) << i;
                for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(at.radiance[i][c])) << i;
                ASSERT_TRUE(std::isfinite(at.pdf[i])) << i;
            }
            if (map == &one) {
                for (size_t i = 0; i < drawn.pdf.size(); ++i) {
                    ASSERT_NEAR(drawn.pdf[i], 1.0 / (4.0 * kPi), 1e-5);
                    ASSERT_EQ(at.radiance[i], glm::dvec3(2.0, 3.0, 4.0));
                }
            }
        }
    }
}

// ---- Lookup ----

// An 8 x 4 map whose texels name themselves (R = column, G = row): directions whose texel is
// known from the convention (row 0 looks up, phi = 0 along -x and 90 degrees along +y) return
// it; a rotation of 90 degrees moves what is seen by two columns; intensity scales.
TEST_F(EnvironmentTest, LookupReturnsTheTexelADirectionFallsIn) {
    HdrImage map;
    map.width = 8;
    map.height = 4;
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x) map.rgb.insert(map.rgb.end(), {float(x), float(y), 1.0f});
    }
    const EnvironmentTables tables = environment_tables(map);
    struct Known {
        glm::dvec3 direction;
        int column;  // -1: any (a pole)
        int row;
    };
    // Rows are 45 degrees of theta, columns 45 degrees of phi.
    const std::vector<Known> known = {
        {{0.0, 0.0, 1.0}, -1, 0},      // straight up
        {{0.0, 0.0, -1.0}, -1, 3},     // straight down
        {{0.01, 0.0, 1.0}, -1, 0},     // near the pole
        {{-1.0, 0.01, 0.2}, 0, 1},     // just past phi = 0 (-x), a little above the horizon
        {{-1.0, -0.01, 0.2}, 7, 1},    // just before the seam
        {{-1.0, 0.0, -0.2}, 0, 2},     // on the seam, a little below the horizon
        {{-0.01, 1.0, -0.2}, 1, 2},    // just before phi = 90 (+y)
        {{0.01, 1.0, 1.5}, 2, 0},      // just past +y, 34 degrees from the zenith
        {{1.0, 0.01, 0.5}, 3, 1},      // just before phi = 180 (+x)
        {{1.0, -0.01, -2.0}, 4, 3},    // just past +x, far below the horizon
        {{0.05, -1.0, -0.9}, 5, 2},    // just before phi = 270 (-y)
        {{-0.3, -1.0, 0.0001}, 6, 1},  // between -y and -x, on the horizon's upper side
    };
    for (const Variant v : variants()) {
        SCOPED_TRACE(label(v));
        for (double rotation : {0.0, 90.0}) {
            const float intensity = rotation == 0.0 ? 1.0f : 3.0f;
            const EnvironmentInfo info = environment_info(tables, rotation, intensity);
            std::vector<glm::dvec3> directions;
            for (const Known& k : known) directions.push_back(glm::normalize(k.direction));
            const Evaluated at = evaluate(v, tables, info, directions);
            for (size_t i = 0; i < known.size(); ++i) {
                const glm::dvec3 c = at.radiance[i] / double(intensity);
                // A rotation of 90 degrees shows at phi what the map has at phi - 90: two
                // columns back.
                const int shift = rotation == 0.0 ? 0 : 2;
                EXPECT_EQ(c.y, known[i].row) << "direction " << i << " rotation " << rotation;
                if (known[i].column >= 0) {
                    EXPECT_EQ(c.x, (known[i].column - shift + 8) % 8)
                        << "direction " << i << " rotation " << rotation;
                }
                EXPECT_EQ(c.z, 1.0);
            }
        }
    }
}

// ---- Tables ----

// What --environment takes and environment_argument writes read back to the same choice, floats
// to the bit; a file named like a kind is written so that it stays a file.
TEST(EnvironmentArgument, ReadsBackToTheSameChoice) {
    for (const char* text : {"sky", "studio", "uniform", "uniform:0.5", "uniform:0.1,0.2,0.3",
                             "uniform:0.33333334,1e-07,3", "/maps/hall.hdr", "maps/hall.exr"}) {
        const EnvironmentChoice choice = parse_environment(text);
        EXPECT_EQ(environment_argument(choice), text);
        const EnvironmentChoice back = parse_environment(environment_argument(choice));
        EXPECT_EQ(back.kind, choice.kind) << text;
        EXPECT_EQ(back.radiance, choice.radiance) << text;
        EXPECT_EQ(back.file, choice.file) << text;
    }
    EnvironmentChoice grey;
    grey.kind = EnvironmentKind::Uniform;
    grey.radiance = glm::vec3(1.0f / 3.0f);
    EXPECT_EQ(parse_environment(environment_argument(grey)).radiance, grey.radiance);
    EnvironmentChoice named_sky;
    named_sky.kind = EnvironmentKind::File;
    named_sky.file = "sky";
    EXPECT_EQ(environment_argument(named_sky), "./sky");
    EXPECT_EQ(parse_environment(environment_argument(named_sky)).kind, EnvironmentKind::File);
}

TEST(EnvironmentTables, RejectBadMapsInOneLine) {
    const auto message = [](const HdrImage& map) {
        try {
            environment_tables(map, "sky.hdr");
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    HdrImage good = uniform_environment(glm::vec3(1.0f));
    HdrImage nan = good, negative = good, infinite = good, empty, short_of_values = good;
    nan.rgb[5] = std::numeric_limits<float>::quiet_NaN();
    negative.rgb[3 * 9 + 1] = -0.5f;
    infinite.rgb[0] = std::numeric_limits<float>::infinity();
    short_of_values.rgb.pop_back();
    EXPECT_EQ(message(good), "accepted");
    EXPECT_EQ(message(nan),
              "sky.hdr: pixel (1, 0) has a B value nan (values must be finite and non-negative)");
    EXPECT_EQ(message(negative),
              "sky.hdr: pixel (1, 1) has the G value -0.5 (values must be "
              "finite and non-negative)");
    EXPECT_EQ(message(infinite),
              "sky.hdr: pixel (0, 0) has the R value inf (values must be "
              "finite and non-negative)");
    EXPECT_EQ(message(empty), "sky.hdr: empty (0 x 0 pixels)");
    EXPECT_EQ(message(short_of_values), "sky.hdr: holds 95 values, 8 x 4 pixels need 96");
    EXPECT_THROW(environment_info(environment_tables(good), 0.0, -1.0f), std::invalid_argument);
    EXPECT_THROW(environment_info(environment_tables(good), std::nan(""), 1.0f),
                 std::invalid_argument);
    EXPECT_THROW(uniform_environment(glm::vec3(1.0f, -1.0f, 1.0f)), std::invalid_argument);
}

// The tables' layout (kernels/shared/fgr_layout_environment.h): each texel's colour and the
// probability stored beside it, proportional to luminance times solid angle (0 for black texels);
// and that probability is exactly what the rows' and columns' alias tables realise (worked out
// here from the stored entries), so the kernel's pdf is its sampling's density.
TEST(EnvironmentTables, AliasTablesRealiseTheStoredProbabilities) {
    for (const auto& [width, height] : {std::pair{16, 8}, std::pair{37, 5}, std::pair{1, 1}}) {
        SCOPED_TRACE(fmt::format("{} x {}", width, height));
        const HdrImage map = spot_and_gradient(width, height);
        const EnvironmentTables tables = environment_tables(map);
        const size_t w = size_t(width), h = size_t(height);
        ASSERT_EQ(tables.data.size(),
                  FGR_ENV_TEXEL_FLOATS * w * h + FGR_ENV_ALIAS_FLOATS * (h + w * h));
        const auto realised = [&](int offset, size_t n) {
            std::vector<double> p(n, 0.0);
            for (size_t k = 0; k < n; ++k) {
                const float* entry = tables.data.data() + offset + FGR_ENV_ALIAS_FLOATS * k;
                const double threshold = entry[FGR_ENV_ALIAS_THRESHOLD];
                int alias = 0;
                std::memcpy(&alias, entry + FGR_ENV_ALIAS_INDEX, sizeof(int));
                EXPECT_TRUE(threshold >= 0.0 && threshold <= 1.0) << k;
                EXPECT_TRUE(alias >= 0 && size_t(alias) < n) << k;
                if (alias < 0 || size_t(alias) >= n) continue;
                p[k] += threshold / double(n);
                p[size_t(alias)] += (1.0 - threshold) / double(n);
            }
            return p;
        };
        const std::vector<double> rows = realised(tables.rows_offset, h);
        double sum = 0.0;
        for (size_t y = 0; y < h; ++y) {
            const std::vector<double> columns =
                realised(tables.columns_offset + int(FGR_ENV_ALIAS_FLOATS * y * w), w);
            for (size_t x = 0; x < w; ++x) {
                const float* stored = tables.data.data() + FGR_ENV_TEXEL_FLOATS * (y * w + x);
                const glm::dvec3 colour = texel(map, int(x), int(y));
                EXPECT_EQ(glm::dvec3(stored[0], stored[1], stored[2]), colour);
                const double p = stored[FGR_ENV_TEXEL_PROBABILITY];
                EXPECT_NEAR(p, rows[y] * columns[x], 1e-6 * p) << x << ", " << y;
                const double expected = luminance(colour) *
                                        environment_texel_solid_angle(int(y), width, height) /
                                        tables.luminance_integral;
                EXPECT_NEAR(p, expected, 1e-12 + 1e-5 * expected) << x << ", " << y;
                if (expected == 0.0) {
                    EXPECT_EQ(p, 0.0) << x << ", " << y;
                }
                sum += p;
            }
        }
        EXPECT_NEAR(sum, 1.0, 1e-5);
    }
}

// ---- Directions ----

TEST(EnvironmentDirections, FollowTheDocumentedConvention) {
    const auto near = [](glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-12; };
    EXPECT_TRUE(near(environment_direction(0.3, 0.0), {0.0, 0.0, 1.0}));
    EXPECT_TRUE(near(environment_direction(0.0, 0.5), {-1.0, 0.0, 0.0}));
    EXPECT_TRUE(near(environment_direction(0.25, 0.5), {0.0, 1.0, 0.0}));
    EXPECT_TRUE(near(environment_direction(0.5, 0.5), {1.0, 0.0, 0.0}));
    EXPECT_TRUE(near(environment_direction(0.75, 1.0), {0.0, 0.0, -1.0}));
    const glm::dvec2 uv = environment_coordinates(environment_direction(0.8, 0.3));
    EXPECT_NEAR(uv.x, 0.8, 1e-12);
    EXPECT_NEAR(uv.y, 0.3, 1e-12);
    // Rotating by R adds R degrees to the azimuth.
    const glm::dvec3 turned = rotate_environment_direction(environment_direction(0.1, 0.4), 36.0);
    EXPECT_TRUE(near(turned, environment_direction(0.2, 0.4)));
    // Row solid angles add up to the sphere.
    double sum = 0.0;
    for (int row = 0; row < 7; ++row) sum += 5 * environment_texel_solid_angle(row, 5, 7);
    EXPECT_NEAR(sum, 4.0 * kPi, 1e-12);
}

// ---- The Preetham sky and sun ----

// Zenith luminance and chromaticity against values from the formulas printed in Preetham,
// Shirley, Smits 1999, Appendix A.2 (zenith luminance in kcd/m^2, chromaticity matrices),
// evaluated independently (Python, double) for these turbidities and sun angles:
//   T = 2,  theta_s = 30 deg:  Y_z = 5.8867 kcd/m^2, x_z = 0.25142, y_z = 0.25592
//   T = 3,  theta_s = 55 deg:  Y_z = 5.8035 kcd/m^2, x_z = 0.24410, y_z = 0.25082
//   T = 6,  theta_s = 70 deg:  Y_z = 6.5797 kcd/m^2, x_z = 0.27145, y_z = 0.28981
// (No published table of the model's outputs was found to compare with; the values are the
// paper's formulas, not fgr's code.) Luminance sits within the range published for clear skies
// ("average clear sky 7 kcd/m^2"; Wikipedia, Orders of magnitude (luminance)), and the zenith
// is bluer than white (x, y below D65's 0.3127, 0.3290).
TEST(PreethamSky, ZenithMatchesThePaper) {
    struct Case {
        float turbidity, sun_zenith_degrees;
        double luminance, x, y;
    };
    for (const Case& c :
         {Case{2.0f, 30.0f, 5.8867, 0.25142, 0.25592}, Case{3.0f, 55.0f, 5.8035, 0.24410, 0.25082},
          Case{6.0f, 70.0f, 6.5797, 0.27145, 0.28981}}) {
        SkySettings sky;
        sky.turbidity = c.turbidity;
        sky.sun_elevation_degrees = 90.0f - c.sun_zenith_degrees;
        const glm::dvec3 zenith = preetham_sky_xyY(sky, {0.0, 0.0, 1.0});
        EXPECT_NEAR(zenith.z / 1000.0, c.luminance, 5e-4 * c.luminance) << c.turbidity;
        EXPECT_NEAR(zenith.x, c.x, 5e-5) << c.turbidity;
        EXPECT_NEAR(zenith.y, c.y, 5e-5) << c.turbidity;
        EXPECT_LT(zenith.x, 0.3127);
        EXPECT_LT(zenith.y, 0.3290);
        // The map's top row holds the zenith's neighbourhood: within a few percent of it.
        const HdrImage map = preetham_sky(sky, 256);
        const glm::dvec3 top = texel(map, 17, 0);
        EXPECT_NEAR(luminance(top) * kDaylightUnit, zenith.z, 0.03 * zenith.z);
    }
}

TEST(PreethamSky, BrighterTowardsTheSunThanOpposite) {
    for (float elevation : {10.0f, 35.0f, 60.0f}) {
        SkySettings sky;
        sky.sun_elevation_degrees = elevation;
        const double toward = sky.sun_azimuth_degrees / 360.0;
        for (double altitude_degrees : {5.0, 20.0, 45.0}) {
            const double v = (90.0 - altitude_degrees) / 180.0;
            const double near =
                luminance(glm::dvec3(preetham_sky_radiance(sky, environment_direction(toward, v))));
            const double far = luminance(
                glm::dvec3(preetham_sky_radiance(sky, environment_direction(toward + 0.5, v))));
            EXPECT_GT(near, 1.2 * far) << elevation << " " << altitude_degrees;
        }
    }
}

TEST(PreethamSky, SymmetricAboutTheSunsVerticalPlane) {
    SkySettings sky;
    sky.sun_azimuth_degrees = 123.0f;
    sky.turbidity = 4.0f;
    const double sun_u = 123.0 / 360.0;
    for (double offset : {0.01, 0.1, 0.3, 0.45}) {
        for (double v : {0.05, 0.3, 0.49}) {
            const glm::dvec3 left(
                preetham_sky_radiance(sky, environment_direction(sun_u - offset, v)));
            const glm::dvec3 right(
                preetham_sky_radiance(sky, environment_direction(sun_u + offset, v)));
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(left[c], right[c], 1e-5 * right[c] + 1e-9);
        }
    }
}

// Across the seam: with the sun just past the seam (its glow spans it), the map equals the map
// of a sun turned by half a turn, shifted by half the columns, at every texel: the seam is no
// different from any other column boundary.
TEST(PreethamSky, ContinuousAcrossTheSeam) {
    SkySettings sky;
    sky.sun_azimuth_degrees = 3.0f;
    sky.sun_elevation_degrees = 20.0f;
    const HdrImage map = preetham_sky(sky, 128);
    sky.sun_azimuth_degrees = 183.0f;
    const HdrImage turned = preetham_sky(sky, 128);
    for (int y = 0; y < map.height; ++y) {
        for (int x = 0; x < map.width; ++x) {
            const glm::dvec3 a = texel(map, x, y);
            const glm::dvec3 b = texel(turned, (x + map.width / 2) % map.width, y);
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(a[c], b[c], 1e-4 * std::max(a[c], 1e-3)) << x << ", " << y;
            }
        }
    }
}

// The ground below the horizon is one grey: albedo / pi times the horizontal irradiance of the
// sky (integrated here over the map's upper rows) and the sun.
TEST(PreethamSky, GroundReflectsTheSkyAndSun) {
    SkySettings sky;
    sky.ground_albedo = 0.4f;
    const HdrImage map = preetham_sky(sky, 512);
    glm::dvec3 irradiance(0.0);
    for (int y = 0; y < map.height / 2; ++y) {
        const double cos_theta = std::cos(kPi * (y + 0.5) / map.height);
        for (int x = 0; x < map.width; ++x) {
            irradiance += texel(map, x, y) * cos_theta *
                          environment_texel_solid_angle(y, map.width, map.height);
        }
    }
    const SunDisc sun = preetham_sun(sky);
    const double sun_solid_angle = 2.0 * kPi * (1.0 - std::cos(sun.angular_radius_radians));
    irradiance += glm::dvec3(sun.radiance) * sun_solid_angle * double(sun.direction.z);
    const glm::dvec3 expected = irradiance * (0.4 / kPi);
    for (int y = map.height / 2; y < map.height; y += 7) {
        const glm::dvec3 ground = texel(map, (y * 13) % map.width, y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(ground[c], expected[c], 0.01 * expected[c]);
    }
    // The scale: a white Lambertian floor under the default sky and sun reads about 1 (well
    // exposed at exposure 1; see kDaylightUnit), i.e. 40 to 120 klx, bright daylight.
    EXPECT_GT(luminance(irradiance) / kPi, 0.6);
    EXPECT_LT(luminance(irradiance) / kPi, 1.9);
}

// The sun's disc: its true size, its direction from elevation and azimuth, its luminance against
// published values (solar disc 1.6 Gcd/m^2 at noon, 0.6 Mcd/m^2 at the horizon; Wikipedia,
// Orders of magnitude (luminance)), and dimmer and redder as it sets or as haze rises.
TEST(PreethamSun, DimsAsItSetsAndAsHazeRises) {
    SkySettings sky;
    sky.sun_elevation_degrees = 30.0f;
    sky.sun_azimuth_degrees = 90.0f;
    const SunDisc disc = preetham_sun(sky);
    EXPECT_NEAR(disc.angular_radius_radians, 0.2667 * kPi / 180.0, 1e-7);
    EXPECT_NEAR(disc.direction.x, 0.0, 1e-6);
    EXPECT_NEAR(disc.direction.y, std::cos(kPi / 6.0), 1e-6);
    EXPECT_NEAR(disc.direction.z, 0.5, 1e-6);

    sky.turbidity = 2.0f;
    sky.sun_elevation_degrees = 90.0f;
    const double noon = luminance(glm::dvec3(preetham_sun(sky).radiance)) * kDaylightUnit;
    EXPECT_GT(noon, 1.6e9 / 1.5);
    EXPECT_LT(noon, 1.6e9 * 1.5);

    double previous = 1e300, previous_red = 0.0;
    for (float elevation : {90.0f, 60.0f, 35.0f, 15.0f, 5.0f, 1.0f, 0.0f}) {
        sky.sun_elevation_degrees = elevation;
        const glm::dvec3 radiance(preetham_sun(sky).radiance);
        const double value = luminance(radiance);
        EXPECT_LT(value, previous) << elevation;
        // Red over green: blue leaves the gamut (and is clamped to 0) near the horizon.
        EXPECT_GT(radiance.r / radiance.g, previous_red) << elevation;
        previous = value;
        previous_red = radiance.r / radiance.g;
    }
    // At the horizon: within an order of magnitude of the published 0.6 Mcd/m^2 (the value
    // depends strongly on the air's state there).
    EXPECT_GT(previous * kDaylightUnit, 0.6e6 / 10.0);
    EXPECT_LT(previous * kDaylightUnit, 0.6e6 * 10.0);

    sky.sun_elevation_degrees = 35.0f;
    previous = 1e300;
    for (float turbidity : {1.7f, 2.0f, 3.0f, 5.0f, 8.0f, 10.0f}) {
        sky.turbidity = turbidity;
        const double value = luminance(glm::dvec3(preetham_sun(sky).radiance));
        EXPECT_LT(value, previous) << turbidity;
        previous = value;
    }
}

TEST(PreethamSky, RejectsSettingsOutsideTheModel) {
    const auto message = [](SkySettings sky) {
        try {
            validate_sky(sky);
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    SkySettings sky;
    EXPECT_EQ(message(sky), "accepted");
    sky.turbidity = 1.0f;
    EXPECT_EQ(message(sky), "sky turbidity 1 is outside [1.7, 10]");
    sky = {};
    sky.sun_elevation_degrees = -5.0f;
    EXPECT_EQ(message(sky), "sun elevation -5 degrees is outside [0, 90]");
    sky = {};
    sky.ground_albedo = std::nanf("");
    EXPECT_EQ(message(sky), "ground albedo nan is outside [0, 1]");
    EXPECT_THROW(preetham_sky(SkySettings{}, 7), std::invalid_argument);
    EXPECT_THROW(studio_environment(6), std::invalid_argument);
}

// ---- The studio ----

// Designed, not derived, so checked for what it promises: finite, non-negative, a floor darker
// than the surround, three light boxes far brighter than it, and a white surface facing the key
// light reading about 0.8.
TEST(StudioEnvironment, HasItsLightsWhereDocumented) {
    const HdrImage map = studio_environment(256);
    ASSERT_EQ(map.width, 256);
    ASSERT_EQ(map.height, 128);
    for (float value : map.rgb) ASSERT_TRUE(std::isfinite(value) && value >= 0.0f);
    const auto at = [&](double azimuth, double elevation) {
        const glm::dvec2 uv = environment_coordinates(
            environment_direction(azimuth / 360.0, (90.0 - elevation) / 180.0));
        return luminance(texel(map, std::min(int(uv.x * map.width), map.width - 1),
                               std::min(int(uv.y * map.height), map.height - 1)));
    };
    const double surround = at(0.0, 60.0), floor = at(0.0, -40.0);
    EXPECT_LT(floor, surround);
    EXPECT_GT(floor, 0.3 * surround);
    // Each box is centred where documented: bright there, dark past its edges on either side.
    struct Box {
        double azimuth, elevation, beyond_edge, brighter;
    };
    for (const Box& box : {Box{270.0, 40.0, 40.0, 50.0},    // key
                           Box{175.0, 15.0, 45.0, 15.0},    // fill
                           Box{45.0, 30.0, 15.0, 50.0}}) {  // rim
        const double centre = at(box.azimuth, box.elevation);
        EXPECT_GT(centre, box.brighter * surround) << box.azimuth;
        EXPECT_LT(at(box.azimuth - box.beyond_edge, box.elevation), 2.0 * surround) << box.azimuth;
        EXPECT_LT(at(box.azimuth + box.beyond_edge, box.elevation), 2.0 * surround) << box.azimuth;
    }
    // Irradiance on a surface facing the key box, over its hemisphere.
    const glm::dvec3 normal = environment_direction(270.0 / 360.0, 50.0 / 180.0);
    double irradiance = 0.0;
    for (int y = 0; y < map.height; ++y) {
        for (int x = 0; x < map.width; ++x) {
            const glm::dvec3 d =
                environment_direction((x + 0.5) / map.width, (y + 0.5) / map.height);
            const double cosine = glm::dot(d, normal);
            if (cosine > 0.0) {
                irradiance += luminance(texel(map, x, y)) * cosine *
                              environment_texel_solid_angle(y, map.width, map.height);
            }
        }
    }
    EXPECT_GT(irradiance / kPi, 0.6);
    EXPECT_LT(irradiance / kPi, 1.0);
}

// --- Which environment, and which lights ------------------------------------------------------

Scene scene_with_lights(std::string environment) {
    Scene scene;
    Light key;
    key.type = LightType::Directional;
    key.vector = {0.0f, 0.0f, 1.0f};
    Light lamp;
    lamp.type = LightType::Point;
    lamp.vector = {0.0f, 0.0f, 3.0f};
    scene.lights = {key, lamp};
    scene.environment = std::move(environment);
    return scene;
}

// A scene's own environment lights it when the user named none, turned and scaled as the user
// asks; one the user named (--environment, even "sky") is kept.
TEST(EnvironmentChoice, TheScenesOwnStandsInForOneTheUserDidNotName) {
    const Scene studio = scene_with_lights("studio");
    EnvironmentChoice unnamed;
    unnamed.intensity = 2.0f;
    unnamed.rotation_degrees = 30.0f;
    const EnvironmentChoice chosen = with_scene_environment(unnamed, studio);
    EXPECT_EQ(chosen.kind, EnvironmentKind::Studio);
    EXPECT_EQ(chosen.intensity, 2.0f);
    EXPECT_EQ(chosen.rotation_degrees, 30.0f);
    EXPECT_EQ(with_scene_environment(parse_environment("sky"), studio).kind, EnvironmentKind::Sky);
    EXPECT_EQ(with_scene_environment(unnamed, scene_with_lights("")).kind, EnvironmentKind::Sky);
    const EnvironmentChoice grey =
        with_scene_environment(unnamed, scene_with_lights("uniform:0.5"));
    EXPECT_EQ(grey.kind, EnvironmentKind::Uniform);
    EXPECT_EQ(grey.radiance, glm::vec3(0.5f));
}

// The log says what lights the path mode: under the sky its sun in place of the key light, under
// any other environment every scene light besides it, and a uniform one with scene lights says a
// furnace test wants --no-scene-lights (unless it is black).
TEST(EnvironmentChoice, TheLightsThatShineAreNamed) {
    const Scene scene = scene_with_lights("");
    EXPECT_EQ(path_lights_text(parse_environment("sky"), scene, true),
              "the sky and its sun and the scene's other 1 light (the sun in place of its key "
              "light)");
    EXPECT_EQ(path_lights_text(parse_environment("sky"), scene, false),
              "the sky and its sun alone (--no-scene-lights)");
    EXPECT_EQ(path_lights_text(parse_environment("studio"), scene, true),
              "the studio and the scene's 2 lights");
    EXPECT_EQ(path_lights_text(parse_environment("uniform"), scene, true),
              "the uniform environment and the scene's 2 lights: a furnace test wants the "
              "environment alone, --no-scene-lights");
    EXPECT_EQ(path_lights_text(parse_environment("uniform"), scene, false),
              "the uniform environment alone (--no-scene-lights)");
    // A black one lights nothing: a closed scene's, no furnace test.
    EXPECT_EQ(path_lights_text(parse_environment("uniform:0"), scene, true),
              "a black environment and the scene's 2 lights");
}

}  // namespace
}  // namespace fgr
