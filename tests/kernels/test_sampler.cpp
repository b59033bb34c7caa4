// SPDX-License-Identifier: Apache-2.0
// The path tracer's sampler (kernels/sampling/fgr_sampler.cl), run through a test kernel at every
// packet width and precision. What is asserted are properties an Owen-scrambled Sobol sampler must
// have whatever its code: every aligned block of 2^k samples of a pixel is a (0,k,2)-net in each
// pair of dimensions; every lane, width and precision gives the pixel's own numbers; pixels, seeds
// and dimensions are uncorrelated and uniform (z-scores and χ² at stated significance levels); a
// smooth integrand converges much faster than with independent samples; the same inputs give the
// same bits.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "kernel_test_program.hpp"
#include "render/precision.hpp"
#include "test_math.hpp"

namespace fgr {
namespace {

using test::chi2_p_value;
using test::upper_gamma_q;

// Each work-item runs one packet: lane i is pixel p = packet * FGR_WIDTH + i, at
// (pixels[2p], pixels[2p + 1]). For each sample it starts the sampler and makes the calls in
// `calls` (2: sampler_next_2d, 1: sampler_next_1d), writing value v of pixel p, sample s at
// out[(p * sample_count + s) * values + v].
constexpr const char* kSamplerTestKernel = R"CL(
typedef FGR_LANES(float, double) test_real;

__kernel void sampler_test(__global const float* pixels, int first_sample, int sample_count,
                           uint seed, __global const int* calls, int call_count, int values,
                           __global test_real* out) {
    const int packet = get_global_id(0);
    real px, py;
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        const int p = packet * FGR_WIDTH + lane;
        ((test_real*)&px)[lane] = pixels[2 * p];
        ((test_real*)&py)[lane] = pixels[2 * p + 1];
    }
    for (int i = 0; i < sample_count; ++i) {
        sampler s = sampler_start(px, py, first_sample + i, seed);
        int v = 0;
        for (int c = 0; c < call_count; ++c) {
            const int n = calls[c];
            real a, b = fgr_real(0.0f);
            if (n == 2) {
                const real2 u = sampler_next_2d(&s);
                a = u.x;
                b = u.y;
            } else {
                a = sampler_next_1d(&s);
            }
            for (int lane = 0; lane < FGR_WIDTH; ++lane) {
                const long at = ((long)(packet * FGR_WIDTH + lane) * sample_count + i) * values + v;
                out[at] = ((test_real*)&a)[lane];
                if (n == 2) out[at + 1] = ((test_real*)&b)[lane];
            }
            v += n;
        }
    }
}
)CL";

struct Pixel {
    float x, y;
};

// A width x height block of pixels from (x0, y0), row by row.
std::vector<Pixel> pixel_grid(int width, int height, int x0 = 0, int y0 = 0) {
    std::vector<Pixel> pixels;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) pixels.push_back({float(x0 + x), float(y0 + y)});
    }
    return pixels;
}

// One launch's numbers: value v of pixel p, sample s (counted from the launch's first sample).
struct SamplerValues {
    std::vector<double> values;
    int samples = 0;
    int per_sample = 0;
    double at(size_t pixel, int sample, int value) const {
        return values[(pixel * size_t(samples) + size_t(sample)) * size_t(per_sample) +
                      size_t(value)];
    }
};

struct Build {
    int width;
    bool double_precision;
    std::string label() const {
        return fmt::format("{}{}", double_precision ? "double" : "float", width);
    }
};

class SamplerTest : public test::DeviceSuite<> {
protected:
    // Every packet width, in float and (where the device has it) double. Double lanes come in
    // packets of 4 or more (kMinDoublePacketWidth, precision.hpp: the library's scalar double
    // build is ambiguous between float and double built-ins), so double starts at 4.
    static std::vector<Build> builds() {
        std::vector<Build> list;
        for (bool double_precision : {false, true}) {
            if (double_precision && !device_->info.has_fp64) continue;
            for (int width : {1, 4, 8, 16}) {
                if (!double_precision || width >= kMinDoublePacketWidth) {
                    list.push_back({width, double_precision});
                }
            }
        }
        return list;
    }

    // Samples first_sample .. first_sample + samples - 1 of every pixel, each making `calls`.
    // Every value must lie in [0, 1); a value outside fails the test here.
    static SamplerValues run(const Build& build, std::vector<Pixel> pixels, int first_sample,
                             int samples, uint32_t seed, const std::vector<int>& calls) {
        cl::Program program;
        try {
            program = test::build_library_test_program(*device_, *cache_, kSamplerTestKernel,
                                                       build.width, build.double_precision);
        } catch (const KernelBuildError& error) {
            ADD_FAILURE() << build.label() << ": " << error.what() << "\n" << error.build_log();
            throw;
        }
        const size_t count = pixels.size();
        // Whole packets: the last one is filled up with copies of the last pixel.
        while (pixels.size() % size_t(build.width) != 0) pixels.push_back(pixels.back());
        SamplerValues result;
        result.samples = samples;
        for (int call : calls) result.per_sample += call;
        const size_t total = pixels.size() * size_t(samples) * size_t(result.per_sample);
        const size_t scalar = build.double_precision ? sizeof(cl_double) : sizeof(cl_float);

        std::vector<cl_int> call_list(calls.begin(), calls.end());
        cl::Buffer pixel_buffer(device_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                pixels.size() * sizeof(Pixel), pixels.data());
        cl::Buffer call_buffer(device_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                               call_list.size() * sizeof(cl_int), call_list.data());
        cl::Buffer out_buffer(device_->context, CL_MEM_WRITE_ONLY, total * scalar);
        cl::Kernel kernel(program, "sampler_test");
        kernel.setArg(0, pixel_buffer);
        kernel.setArg(1, cl_int(first_sample));
        kernel.setArg(2, cl_int(samples));
        kernel.setArg(3, cl_uint(seed));
        kernel.setArg(4, call_buffer);
        kernel.setArg(5, cl_int(call_list.size()));
        kernel.setArg(6, cl_int(result.per_sample));
        kernel.setArg(7, out_buffer);
        device_->queue.enqueueNDRangeKernel(kernel, cl::NullRange,
                                            cl::NDRange(pixels.size() / size_t(build.width)),
                                            cl::NDRange(1));
        if (build.double_precision) {
            std::vector<cl_double> out(total);
            device_->queue.enqueueReadBuffer(out_buffer, CL_TRUE, 0, total * scalar, out.data());
            result.values.assign(out.begin(), out.end());
        } else {
            std::vector<cl_float> out(total);
            device_->queue.enqueueReadBuffer(out_buffer, CL_TRUE, 0, total * scalar, out.data());
            result.values.assign(out.begin(), out.end());
        }
        result.values.resize(count * size_t(samples) * size_t(result.per_sample));
        const auto outside = std::count_if(result.values.begin(), result.values.end(),
                                           [](double u) { return !(u >= 0.0 && u < 1.0); });
        EXPECT_EQ(outside, 0) << build.label() << ": values outside [0, 1)";
        return result;
    }
};

// Which of the 2^bits equal intervals of [0, 1) holds u.
int interval(double u, int bits) { return int(std::floor(std::ldexp(u, bits))); }

// Every aligned block of 2^k samples (k = 0..9, within the first 512) of a pixel is a (0,k,2)-net
// in every pair of dimensions: each elementary interval 2^-a x 2^-b with a + b = k holds exactly
// one point. Every dimension, a pair's halves and the 1D ones alike, puts exactly one point in
// each interval of length 2^-k. The pattern mixes 1D and 2D calls, so pairs sit at odd slots too.
TEST_F(SamplerTest, EveryPowerOfTwoBlockIsANet) {
    const std::vector<int> calls{2, 1, 2, 2, 1, 2};  // values 0-1, 2, 3-4, 5-6, 7, 8-9
    const std::vector<int> pairs{0, 3, 5, 8};
    const std::vector<Pixel> pixels{{0, 0}, {37, 5}, {1919, 1079}, {640, 1}};
    constexpr int log_samples = 9, samples = 1 << log_samples;
    for (const Build& build : builds()) {
        const SamplerValues run_values = run(build, pixels, 0, samples, 0u, calls);
        int failures = 0;
        std::string first;
        auto fail = [&](const std::string& what) {
            if (failures++ == 0) first = what;
        };
        for (size_t p = 0; p < pixels.size(); ++p) {
            for (int k = 0; k <= log_samples; ++k) {
                const int n = 1 << k;
                for (int start = 0; start < samples; start += n) {
                    for (int value = 0; value < run_values.per_sample; ++value) {
                        std::vector<int> count(size_t(n), 0);
                        for (int s = start; s < start + n; ++s) {
                            ++count[size_t(interval(run_values.at(p, s, value), k))];
                        }
                        if (std::any_of(count.begin(), count.end(), [](int c) { return c != 1; })) {
                            fail(
                                fmt::format("pixel {} samples {}..{}: value {} not stratified in "
                                            "2^{} intervals",
                                            p, start, start + n - 1, value, k));
                        }
                    }
                    for (int pair : pairs) {
                        for (int a = 0; a <= k; ++a) {
                            std::vector<int> count(size_t(n), 0);
                            for (int s = start; s < start + n; ++s) {
                                const int ix = interval(run_values.at(p, s, pair), a);
                                const int iy = interval(run_values.at(p, s, pair + 1), k - a);
                                ++count[size_t((ix << (k - a)) + iy)];
                            }
                            if (std::any_of(count.begin(), count.end(),
                                            [](int c) { return c != 1; })) {
                                fail(
                                    fmt::format("pixel {} samples {}..{}: values {},{} not a net "
                                                "in 2^-{} x 2^-{} intervals",
                                                p, start, start + n - 1, pair, pair + 1, a, k - a));
                            }
                        }
                    }
                }
            }
        }
        EXPECT_EQ(failures, 0) << build.label() << ": " << first;
    }
}

// A pixel's numbers do not depend on the packet width, on the lane it runs in, or (beyond the
// final rounding) on the precision: every width gives the narrowest width's bits, and a float
// sample is the double one truncated to 24 bits (so 0 <= double - float < 2^-24).
TEST_F(SamplerTest, SameNumbersAtEveryWidthAndPrecision) {
    // 37 pixels (no width divides it, so the last packet is padded), five of them repeated in
    // other lanes and packets, and coordinates from 0 to 65535.
    std::vector<Pixel> pixels = pixel_grid(5, 5, 100, 200);
    for (Pixel pixel : {Pixel{0, 0}, Pixel{4095, 2159}, Pixel{65535, 65535}, Pixel{1, 0},
                        Pixel{0, 1}, Pixel{102, 201}, Pixel{104, 204}}) {
        pixels.push_back(pixel);
    }
    const size_t repeats = pixels.size();
    for (size_t i = 0; i < 5; ++i) pixels.push_back(pixels[i * 3]);
    const std::vector<int> calls{2, 1, 2, 1, 1, 2};
    for (int first_sample : {0, 123456}) {
        std::map<bool, SamplerValues> reference;
        for (const Build& build : builds()) {
            const SamplerValues values = run(build, pixels, first_sample, 8, 7u, calls);
            // The same pixel in other lanes and packets: the same numbers.
            for (size_t i = 0; i < 5; ++i) {
                for (int value = 0; value < values.per_sample; ++value) {
                    EXPECT_EQ(values.at(repeats + i, 3, value), values.at(i * 3, 3, value))
                        << build.label();
                }
            }
            if (reference.count(build.double_precision) == 0) {
                reference[build.double_precision] = values;
                continue;
            }
            const SamplerValues& expected = reference.at(build.double_precision);
            ASSERT_EQ(values.values.size(), expected.values.size());
            size_t differing = 0;
            for (size_t i = 0; i < values.values.size(); ++i) {
                differing += values.values[i] != expected.values[i];
            }
            EXPECT_EQ(differing, 0u)
                << build.label() << " vs the narrowest width, from sample " << first_sample;
        }
        const SamplerValues& floats = reference.at(false);
        if (reference.count(true) == 0) continue;
        const SamplerValues& doubles = reference.at(true);
        size_t not_truncation = 0;
        double largest_gap = 0;
        for (size_t i = 0; i < floats.values.size(); ++i) {
            const double truncated = std::ldexp(std::floor(std::ldexp(doubles.values[i], 24)), -24);
            not_truncation += floats.values[i] != truncated;
            largest_gap = std::max(largest_gap, doubles.values[i] - floats.values[i]);
        }
        EXPECT_EQ(not_truncation, 0u) << "float samples are double ones truncated to 24 bits";
        EXPECT_LT(largest_gap, std::ldexp(1.0, -24));
        // Double carries more than float's 24 bits (else the check above is empty).
        EXPECT_GT(largest_gap, 0.0);
    }
}

// Pixels, seeds and dimension slots each get their own sequence: over a 64x64 block, no two
// pixels share their first four samples (16 numbers), another seed changes (practically) every
// number, and a slot's pair never repeats the previous slot's.
TEST_F(SamplerTest, PixelsSeedsAndDimensionsGetTheirOwnSequences) {
    const std::vector<Pixel> pixels = pixel_grid(64, 64);
    const std::vector<int> calls{2, 2};
    for (const Build& build : builds()) {
        const SamplerValues seed0 = run(build, pixels, 0, 4, 0u, calls);
        const SamplerValues seed1 = run(build, pixels, 0, 4, 1u, calls);
        std::set<std::vector<double>> sequences;
        for (size_t p = 0; p < pixels.size(); ++p) {
            const auto begin = seed0.values.begin() + std::ptrdiff_t(p * 16);
            sequences.insert(std::vector<double>(begin, begin + 16));
        }
        EXPECT_EQ(sequences.size(), pixels.size()) << build.label() << ": pixels share sequences";
        // Equal 24-bit numbers by chance: expected 65536 * 2^-24 = 0.004 of them.
        size_t same_by_seed = 0, same_by_slot = 0;
        for (size_t i = 0; i < seed0.values.size(); ++i) {
            same_by_seed += seed0.values[i] == seed1.values[i];
        }
        for (size_t i = 0; i < seed0.values.size(); i += 4) {
            same_by_slot += seed0.values[i] == seed0.values[i + 2];
            same_by_slot += seed0.values[i + 1] == seed0.values[i + 3];
        }
        EXPECT_LE(same_by_seed, 2u) << build.label() << ": seeds 0 and 1 agree";
        EXPECT_LE(same_by_slot, 2u) << build.label() << ": slots 0 and 1 agree";
    }
}

// z-score of the mean of `terms` against 0, with the standard error estimated from the terms.
double z_score(const std::vector<double>& terms) {
    const double n = double(terms.size());
    double mean = 0;
    for (double t : terms) mean += t;
    mean /= n;
    double variance = 0;
    for (double t : terms) variance += (t - mean) * (t - mean);
    variance /= n - 1;
    return mean / std::sqrt(variance / n);
}

// No correlation between dimensions, nor between neighbouring pixels.
//
// Dimensions: for each pair of the 8 dimensions of {2, 2, 2, 1, 1}, over 1024 pixels x 16 samples,
// the per-pixel sums S = Σ_s (u - 1/2)(v - 1/2) have mean 0 if the dimensions are uncorrelated.
// Pixels are independent (their own hashes), so the z-score of the mean of S uses the standard
// error measured from the 1024 sums, whatever a pixel's stratification does to its own sum.
//
// Neighbours: sample 0 (and sample 5) of the pixels of disjoint horizontal, vertical and diagonal
// neighbour pairs of a 64x64 block. Under independence, (u - 1/2)(v - 1/2) has mean 0 and
// variance exactly 1/144, so the correlation estimate r = 12 mean(...) has standard error
// 1/sqrt(N).
//
// 28 + 24 z-scores: each must stay within 4.5, so a correct sampler fails any with probability
// under 52 * 6.8e-6 = 3.5e-4 (two-sided normal tail at 4.5, Bonferroni). The data are
// deterministic, so that is the chance that the fixed seeds were an unlucky draw.
TEST_F(SamplerTest, DimensionsAndNeighboursAreUncorrelated) {
    constexpr double bound = 4.5;
    for (const Build& build : builds()) {
        const std::vector<Pixel> block = pixel_grid(32, 32);
        const SamplerValues dims = run(build, block, 0, 16, 0u, {2, 2, 2, 1, 1});
        double worst = 0;
        std::string worst_what;
        for (int i = 0; i < dims.per_sample; ++i) {
            for (int j = i + 1; j < dims.per_sample; ++j) {
                std::vector<double> sums;
                for (size_t p = 0; p < block.size(); ++p) {
                    double sum = 0;
                    for (int s = 0; s < dims.samples; ++s) {
                        sum += (dims.at(p, s, i) - 0.5) * (dims.at(p, s, j) - 0.5);
                    }
                    sums.push_back(sum);
                }
                const double z = z_score(sums);
                if (std::fabs(z) > std::fabs(worst)) {
                    worst = z;
                    worst_what = fmt::format("dimensions {} and {}", i, j);
                }
            }
        }
        EXPECT_LT(std::fabs(worst), bound) << build.label() << ": " << worst_what;
        if (build.width == 16) {
            std::printf("%s: largest |z| between dimensions %.2f (%s)\n", build.label().c_str(),
                        std::fabs(worst), worst_what.c_str());
        }

        const std::vector<Pixel> grid = pixel_grid(64, 64);
        const SamplerValues first = run(build, grid, 0, 6, 0u, {2, 2});
        worst = 0;
        const std::vector<std::pair<int, int>> directions{{1, 0}, {0, 1}, {1, 1}};
        for (int sample : {0, 5}) {
            for (auto [dx, dy] : directions) {
                for (int value = 0; value < first.per_sample; ++value) {
                    double sum = 0;
                    int n = 0;
                    // Disjoint pairs: (x, y) with x, y even for a diagonal, x (or y) even
                    // otherwise.
                    for (int y = 0; y + dy < 64; y += 1 + dy) {
                        for (int x = 0; x + dx < 64; x += 1 + dx) {
                            const double u = first.at(size_t(y * 64 + x), sample, value);
                            const double v =
                                first.at(size_t((y + dy) * 64 + x + dx), sample, value);
                            sum += (u - 0.5) * (v - 0.5);
                            ++n;
                        }
                    }
                    const double z = 12.0 * sum / n * std::sqrt(double(n));
                    if (std::fabs(z) > std::fabs(worst)) {
                        worst = z;
                        worst_what = fmt::format("sample {}, value {}, neighbours ({}, {})", sample,
                                                 value, dx, dy);
                    }
                }
            }
        }
        EXPECT_LT(std::fabs(worst), bound) << build.label() << ": " << worst_what;
        if (build.width == 16) {
            std::printf("%s: largest |z| between neighbours %.2f (%s)\n", build.label().c_str(),
                        std::fabs(worst), worst_what.c_str());
        }
    }
}

// Pearson's χ² of counts against a uniform expectation.
double chi2_uniform(const std::vector<int>& counts, double expected) {
    double statistic = 0;
    for (int c : counts) statistic += (c - expected) * (c - expected) / expected;
    return statistic;
}

// Over 4096 pixels, each sample's numbers are uniform: for every sample 0..255, a 16x16-cell χ²
// (expected 16 a cell, 255 degrees of freedom) for each of three pairs and a 64-cell χ² (expected
// 64, 63 d.o.f.) for a 1D dimension: 1024 tests. Pixels are independent, so a sample's values over
// pixels are independent uniform draws and each statistic has the χ² distribution; its p-value is
// then uniform. Two checks, each at significance 0.1%: the smallest p-value is above 0.001 / 1024
// (Bonferroni), and the 1024 p-values are uniform (Kolmogorov-Smirnov, D < 1.95 / sqrt(1024)).
// The numbers are deterministic, so 0.2% is the chance that a correct sampler's fixed inputs are
// an unlucky draw.
TEST_F(SamplerTest, UniformOverPixels) {
    // The p-value function against closed forms: Q(1, x) = e^-x; χ² with 2 d.o.f. at 5.991 is 5%.
    EXPECT_NEAR(upper_gamma_q(1.0, 0.3), std::exp(-0.3), 1e-12);
    EXPECT_NEAR(upper_gamma_q(1.0, 7.0), std::exp(-7.0), 1e-12);
    EXPECT_NEAR(upper_gamma_q(0.5, 2.0), std::erfc(std::sqrt(2.0)), 1e-12);
    EXPECT_NEAR(chi2_p_value(5.991464547, 2), 0.05, 1e-8);

    const std::vector<Pixel> pixels = pixel_grid(64, 64);
    const std::vector<int> calls{2, 1, 2, 2};  // values 0-1, 2, 3-4, 5-6
    constexpr int samples = 256;
    for (const Build& build : builds()) {
        const SamplerValues values = run(build, pixels, 0, samples, 0u, calls);
        std::vector<double> p_values;
        double smallest = 1;
        std::string smallest_what;
        auto add = [&](double p, const std::string& what) {
            p_values.push_back(p);
            if (p < smallest) {
                smallest = p;
                smallest_what = what;
            }
        };
        for (int sample = 0; sample < samples; ++sample) {
            for (int pair : {0, 3, 5}) {
                std::vector<int> counts(256, 0);
                for (size_t p = 0; p < pixels.size(); ++p) {
                    ++counts[size_t(interval(values.at(p, sample, pair), 4) * 16 +
                                    interval(values.at(p, sample, pair + 1), 4))];
                }
                add(chi2_p_value(chi2_uniform(counts, 16.0), 255),
                    fmt::format("sample {}, pair at {}", sample, pair));
            }
            std::vector<int> counts(64, 0);
            for (size_t p = 0; p < pixels.size(); ++p) {
                ++counts[size_t(interval(values.at(p, sample, 2), 6))];
            }
            add(chi2_p_value(chi2_uniform(counts, 64.0), 63), fmt::format("sample {}, 1D", sample));
        }
        const double n = double(p_values.size());
        EXPECT_GT(smallest, 0.001 / n) << build.label() << ": " << smallest_what;
        std::sort(p_values.begin(), p_values.end());
        double distance = 0;
        for (size_t i = 0; i < p_values.size(); ++i) {
            distance = std::max({distance, std::fabs(p_values[i] - double(i) / n),
                                 std::fabs(p_values[i] - double(i + 1) / n)});
        }
        EXPECT_LT(distance, 1.95 / std::sqrt(n)) << build.label() << ": p-values not uniform";
        if (build.width == 16) {
            std::printf("%s: smallest χ² p-value %.2g (%s) of %d; KS distance %.3f\n",
                        build.label().c_str(), smallest, smallest_what.c_str(), int(n), distance);
        }
    }
}

// Integrating f(x, y) = x e^{xy} over the unit square (exactly e - 2; the variance of f under a
// uniform point is σ² = (e² - 1)/8 - (e - 2)²) with the first N = 2^k samples of a pixel's pair,
// over 256 pixels:
//   - one sample is a uniform point, so the RMS error at N = 1 is σ (within 4 standard errors of
//     the mean squared error, measured from the pixels); with independent samples it would stay
//     σ/sqrt(N) (slope -1/2);
//   - Owen-scrambled nets have variance O(N^-3 log N) for such a smooth f (Owen 1997, "Scrambled
//     net variance for integrals of smooth functions"): the log-log slope of the RMS error from
//     N = 4 to 256 must be below -1.2 (-1.5 less the sqrt(log N) factor's ~0.2), and the error at
//     N = 256 at least 30 times below independent sampling's σ/16 (the slope from N = 1 predicts
//     256^-0.7 ≈ 1/48 at the least, and typically ~1/100);
//   - the estimate is unbiased: the mean over pixels at N = 256 lies within 4 standard errors of
//     e - 2.
TEST_F(SamplerTest, SmoothIntegrandConvergesFasterThanIndependentSamples) {
    const double e = std::numbers::e;
    const double exact = e - 2;
    const double sigma = std::sqrt((e * e - 1) / 8 - exact * exact);
    const auto f = [](double x, double y) { return x * std::exp(x * y); };
    const std::vector<Pixel> pixels = pixel_grid(16, 16, 300, 40);
    constexpr int log_samples = 8;
    for (const Build& build : builds()) {
        const SamplerValues values = run(build, pixels, 0, 1 << log_samples, 3u, {2, 1, 2});
        for (int pair : {0, 3}) {
            std::vector<double> log_rms;
            double rms_256 = 0, mean_256 = 0, se_mean_256 = 0;
            for (int k = 0; k <= log_samples; ++k) {
                const int n = 1 << k;
                std::vector<double> estimates, squared_errors;
                for (size_t p = 0; p < pixels.size(); ++p) {
                    double sum = 0;
                    for (int s = 0; s < n; ++s) {
                        sum += f(values.at(p, s, pair), values.at(p, s, pair + 1));
                    }
                    estimates.push_back(sum / n);
                    squared_errors.push_back((sum / n - exact) * (sum / n - exact));
                }
                double mse = 0;
                for (double q : squared_errors) mse += q;
                mse /= double(pixels.size());
                if (k == 0) {
                    // Mean squared error against σ²: z within 4.
                    std::vector<double> deviations;
                    for (double q : squared_errors) deviations.push_back(q - sigma * sigma);
                    EXPECT_LT(std::fabs(z_score(deviations)), 4.0)
                        << build.label() << ": one sample's RMS error " << std::sqrt(mse)
                        << " vs σ " << sigma;
                }
                log_rms.push_back(std::log2(std::sqrt(mse)));
                if (k == log_samples) {
                    rms_256 = std::sqrt(mse);
                    std::vector<double> deviations;
                    for (double v : estimates) deviations.push_back(v - exact);
                    double mean = 0;
                    for (double v : estimates) mean += v;
                    mean_256 = mean / double(estimates.size());
                    se_mean_256 = std::fabs((mean_256 - exact) / z_score(deviations));
                    EXPECT_LT(std::fabs(z_score(deviations)), 4.0)
                        << build.label() << ": biased, mean " << mean_256 << " vs " << exact;
                }
            }
            // Least-squares slope of log2 RMS against log2 N over N = 4 .. 256.
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            int points = 0;
            for (int k = 2; k <= log_samples; ++k, ++points) {
                sx += k;
                sy += log_rms[size_t(k)];
                sxx += double(k) * k;
                sxy += k * log_rms[size_t(k)];
            }
            const double slope = (points * sxy - sx * sy) / (points * sxx - sx * sx);
            const double independent_rms = sigma / 16;
            EXPECT_LT(slope, -1.2) << build.label() << ", pair at " << pair;
            EXPECT_LT(rms_256 * 30, independent_rms)
                << build.label() << ", pair at " << pair << ": RMS " << rms_256;
            if (build.width == 16) {
                std::string series;
                for (double l : log_rms) series += fmt::format(" {:.3g}", std::exp2(l));
                std::printf(
                    "%s pair at %d: RMS error at N = 1..256:%s; slope %.3f; "
                    "N = 256: %.2fx below independent samples; mean %.6f ± %.1e\n",
                    build.label().c_str(), pair, series.c_str(), slope, independent_rms / rms_256,
                    mean_256, se_mean_256);
            }
        }
    }
}

// The same inputs give the same bits: twice in a row, with the pixels in another order (another
// packet and lane for each), and with the samples launched from another first sample.
TEST_F(SamplerTest, SameInputsGiveSameBits) {
    const std::vector<Pixel> pixels = pixel_grid(10, 10, 7, 3);
    std::vector<Pixel> reversed(pixels.rbegin(), pixels.rend());
    const std::vector<int> calls{1, 2, 2, 1};
    for (const Build& build : builds()) {
        const SamplerValues once = run(build, pixels, 0, 16, 42u, calls);
        const SamplerValues again = run(build, pixels, 0, 16, 42u, calls);
        EXPECT_TRUE(once.values == again.values) << build.label() << ": two runs differ";
        const SamplerValues backwards = run(build, reversed, 0, 16, 42u, calls);
        const SamplerValues later = run(build, pixels, 8, 8, 42u, calls);
        size_t differing = 0;
        for (size_t p = 0; p < pixels.size(); ++p) {
            for (int s = 0; s < 16; ++s) {
                for (int v = 0; v < once.per_sample; ++v) {
                    differing += once.at(p, s, v) != backwards.at(pixels.size() - 1 - p, s, v);
                    if (s >= 8) differing += once.at(p, s, v) != later.at(p, s - 8, v);
                }
            }
        }
        EXPECT_EQ(differing, 0u) << build.label();
    }
}

}  // namespace
}  // namespace fgr
