// SPDX-License-Identifier: Apache-2.0
// The path tracer's materials (kernels/shading/fgr_bsdf.cl), run as the kernels run them: through
// test kernels built on the kernel library at each packet width and precision. Truths are
// independent of the kernel's formulas: χ² goodness of fit of the sampled directions against the
// kernel's own pdf integrated on the host (Mitsuba 3's chi2.py is the model), the pdf's and the
// albedo's integrals by host quadrature of what the kernel evaluates, reciprocity, closed forms
// (the mirror's reflection, a Lambertian lobe's exact weight, a mirror-plus-diffuse material's mean
// weight) and finite outputs on the inputs that break naive code.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "kernel_test_program.hpp"
#include "render/precision.hpp"
#include "test_math.hpp"

namespace fgr {
namespace {

using glm::dvec3;
using test::chi2_p_value;
using test::kPi;

// The kernels under test: each work-item runs `per_item` cases of FGR_WIDTH lanes. A case's
// inputs are IN fields of one real per lane (field f of case c is the run of FGR_WIDTH lanes at
// (c * IN + f) * FGR_WIDTH), its outputs likewise.
constexpr const char* kBsdfTestKernels = R"CLC(
#if FGR_WIDTH == 1
#define LOAD(i, p) ((real)(p)[i])
#define STORE(v, i, p) ((p)[i] = (v))
#else
#define LOAD(i, p) FGR_PASTE(vload, FGR_WIDTH)(i, p)
#define STORE(v, i, p) FGR_PASTE(vstore, FGR_WIDTH)(v, i, p)
#endif
typedef FGR_LANES(float, double) lane_scalar;

#define IN 16
inline vec3 in3(__global const lane_scalar* in, int c, int f) {
    return v3(LOAD(c * IN + f, in), LOAD(c * IN + f + 1, in), LOAD(c * IN + f + 2, in));
}
inline void out3(__global lane_scalar* out, int fields, int c, int f, vec3 v) {
    STORE(v.x, c * fields + f, out);
    STORE(v.y, c * fields + f + 1, out);
    STORE(v.z, c * fields + f + 2, out);
}
/* Fields 0-6: albedo, specular, roughness; 7-9 the normal; 10-12 wo; 13-15 (u_lobe, u1, u2) or
 * wi. The emission is large, and must not reach any result. */
inline material in_material(__global const lane_scalar* in, int c) {
    material m = diffuse_material(in3(in, c, 0));
    m.specular = in3(in, c, 3);
    m.roughness = LOAD(c * IN + 6, in);
    m.emission = v3_splat(100.0f, 200.0f, 300.0f);
    return m;
}
inline real truth(mask m) { return select(fgr_real(0.0f), fgr_real(1.0f), m); }

#define CASES_OF_ITEM                                            \
    const int first = (int)get_global_id(0) * per_item;          \
    for (int c = first; c < min(first + per_item, cases); ++c)

__kernel __attribute__((reqd_work_group_size(1, 1, 1))) void test_bsdf_sample(
    __global const lane_scalar* in, __global lane_scalar* out, int cases, int per_item) {
    CASES_OF_ITEM {
        const material m = in_material(in, c);
        const vec3 n = in3(in, c, 7), wo = in3(in, c, 10);
        const bsdf_sample s = bsdf_sample_direction(m, n, wo, LOAD(c * IN + 13, in),
                                                    LOAD(c * IN + 14, in), LOAD(c * IN + 15, in));
        out3(out, 13, c, 0, s.wi);
        out3(out, 13, c, 3, s.weight);
        STORE(s.pdf, c * 13 + 6, out);
        STORE(truth(s.delta), c * 13 + 7, out);
        STORE(truth(s.valid), c * 13 + 8, out);
        out3(out, 13, c, 9, bsdf_eval(m, n, wo, s.wi));
        STORE(bsdf_pdf(m, n, wo, s.wi), c * 13 + 12, out);
    }
}

__kernel __attribute__((reqd_work_group_size(1, 1, 1))) void test_bsdf_eval(
    __global const lane_scalar* in, __global lane_scalar* out, int cases, int per_item) {
    CASES_OF_ITEM {
        const material m = in_material(in, c);
        const vec3 n = in3(in, c, 7), wo = in3(in, c, 10), wi = in3(in, c, 13);
        out3(out, 4, c, 0, bsdf_eval(m, n, wo, wi));
        STORE(bsdf_pdf(m, n, wo, wi), c * 4 + 3, out);
    }
}

__kernel __attribute__((reqd_work_group_size(1, 1, 1))) void test_diffuse_material(
    __global const lane_scalar* in, __global lane_scalar* out, int cases, int per_item) {
    CASES_OF_ITEM {
        const material m = diffuse_material(in3(in, c, 0));
        out3(out, 10, c, 0, m.albedo);
        out3(out, 10, c, 3, m.specular);
        STORE(m.roughness, c * 10 + 6, out);
        out3(out, 10, c, 7, m.emission);
    }
}
)CLC";

struct Material {
    dvec3 albedo{0.0}, specular{0.0};
    double roughness = 1.0;
};

Material diffuse(dvec3 albedo) { return {albedo, dvec3(0.0), 1.0}; }
Material metal(dvec3 colour, double roughness) { return {dvec3(0.0), colour, roughness}; }
Material plastic(dvec3 albedo, double roughness) { return {albedo, dvec3(0.04), roughness}; }

// One lane: the material, the normal, wo and either the three uniform numbers or wi.
struct Lane {
    Material m;
    dvec3 n, wo, last;
};

struct SampleOut {
    dvec3 wi, weight;
    double pdf;
    bool delta, valid;
    dvec3 eval;     // bsdf_eval at the sampled wi
    double pdf_at;  // bsdf_pdf at the sampled wi
};

struct EvalOut {
    dvec3 value;
    double pdf;
};

// The test kernels at one width and precision.
class BsdfKernels {
public:
    BsdfKernels(const ComputeDevice& device, ProgramCache& cache, int width, bool double_precision)
        : device_(device),
          width_(width),
          double_(double_precision),
          program_(build(device, cache, width, double_precision)) {}

    int width() const { return width_; }
    bool double_precision() const { return double_; }

    std::vector<SampleOut> sample(const std::vector<Lane>& lanes) const {
        const std::vector<double> out = run("test_bsdf_sample", lanes, 13);
        std::vector<SampleOut> results(lanes.size());
        for (size_t i = 0; i < lanes.size(); ++i) {
            SampleOut& r = results[i];
            r.wi = field3(out, 13, i, 0);
            r.weight = field3(out, 13, i, 3);
            r.pdf = field(out, 13, i, 6);
            r.delta = field(out, 13, i, 7) != 0.0;
            r.valid = field(out, 13, i, 8) != 0.0;
            r.eval = field3(out, 13, i, 9);
            r.pdf_at = field(out, 13, i, 12);
        }
        return results;
    }

    std::vector<EvalOut> eval(const std::vector<Lane>& lanes) const {
        const std::vector<double> out = run("test_bsdf_eval", lanes, 4);
        std::vector<EvalOut> results(lanes.size());
        for (size_t i = 0; i < lanes.size(); ++i) {
            results[i] = {field3(out, 4, i, 0), field(out, 4, i, 3)};
        }
        return results;
    }

    // diffuse_material(albedo) as its ten lane values.
    std::vector<double> diffuse_material_fields(dvec3 albedo) const {
        const std::vector<double> out = run(
            "test_diffuse_material", std::vector<Lane>(1, Lane{diffuse(albedo), {}, {}, {}}), 10);
        std::vector<double> fields;
        for (int f = 0; f < 10; ++f) fields.push_back(field(out, 10, 0, f));
        return fields;
    }

private:
    static cl::Program build(const ComputeDevice& device, ProgramCache& cache, int width,
                             bool double_precision) {
        try {
            return test::build_library_test_program(device, cache, kBsdfTestKernels, width,
                                                    double_precision);
        } catch (const KernelBuildError& error) {
            throw std::runtime_error(fmt::format("{} (width {}, {}):\n{}", error.what(), width,
                                                 double_precision ? "double" : "float",
                                                 error.build_log().substr(0, 4000)));
        }
    }

    // Lane i's field f in a kernel's output of `fields` fields per case.
    double field(const std::vector<double>& out, int fields, size_t i, int f) const {
        const size_t w = size_t(width_);
        return out[((i / w) * size_t(fields) + size_t(f)) * w + i % w];
    }
    dvec3 field3(const std::vector<double>& out, int fields, size_t i, int f) const {
        return {field(out, fields, i, f), field(out, fields, i, f + 1),
                field(out, fields, i, f + 2)};
    }

    std::vector<double> run(const char* name, const std::vector<Lane>& lanes,
                            int out_fields) const {
        if (double_) return run_as<cl_double>(name, lanes, out_fields);
        return run_as<cl_float>(name, lanes, out_fields);
    }

    template <typename T>
    std::vector<double> run_as(const char* name, const std::vector<Lane>& lanes,
                               int out_fields) const {
        constexpr int kIn = 16;
        const size_t w = size_t(width_);
        const size_t cases = (lanes.size() + w - 1) / w;
        // Padding lanes repeat the last lane, so every lane computes something ordinary.
        std::vector<T> in(cases * kIn * w);
        for (size_t i = 0; i < cases * w; ++i) {
            const Lane& lane = lanes[std::min(i, lanes.size() - 1)];
            const double values[kIn] = {
                lane.m.albedo.x,   lane.m.albedo.y,   lane.m.albedo.z,  lane.m.specular.x,
                lane.m.specular.y, lane.m.specular.z, lane.m.roughness, lane.n.x,
                lane.n.y,          lane.n.z,          lane.wo.x,        lane.wo.y,
                lane.wo.z,         lane.last.x,       lane.last.y,      lane.last.z};
            for (int f = 0; f < kIn; ++f)
                in[((i / w) * kIn + size_t(f)) * w + i % w] = T(values[f]);
        }
        std::vector<T> out(cases * size_t(out_fields) * w);
        cl::Buffer in_buffer(device_.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                             in.size() * sizeof(T), in.data());
        cl::Buffer out_buffer(device_.context, CL_MEM_WRITE_ONLY, out.size() * sizeof(T));
        const int per_item = 64;
        cl::Kernel kernel(program_, name);
        kernel.setArg(0, in_buffer);
        kernel.setArg(1, out_buffer);
        kernel.setArg(2, cl_int(cases));
        kernel.setArg(3, cl_int(per_item));
        device_.queue.enqueueNDRangeKernel(
            kernel, cl::NullRange, cl::NDRange((cases + per_item - 1) / per_item), cl::NDRange(1));
        device_.queue.enqueueReadBuffer(out_buffer, CL_TRUE, 0, out.size() * sizeof(T), out.data());
        return std::vector<double>(out.begin(), out.end());
    }

    const ComputeDevice& device_;
    int width_;
    bool double_;
    cl::Program program_;
};

// ---- Host-side mathematics (independent of the kernel) ----------------------------------------

dvec3 spherical(double cos_theta, double phi, dvec3 axis) {
    // Any orthonormal frame about axis: the truths below do not depend on which.
    const dvec3 helper = std::abs(axis.x) < 0.6 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    const dvec3 t1 = glm::normalize(glm::cross(helper, axis));
    const dvec3 t2 = glm::cross(axis, t1);
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return glm::normalize(axis * cos_theta + (t1 * std::cos(phi) + t2 * std::sin(phi)) * sin_theta);
}

dvec3 reflect(dvec3 wo, dvec3 n) { return 2.0 * glm::dot(n, wo) * n - wo; }

// Uniform numbers in [0, 1) that the lane precision holds exactly (24 or 53 bits), so a float
// lane never rounds one up to 1.
class Uniforms {
public:
    Uniforms(uint64_t seed, bool double_precision)
        : engine_(seed), bits_(double_precision ? 53 : 24) {}
    double next() { return double(engine_() >> (64 - bits_)) * std::ldexp(1.0, -bits_); }
    dvec3 next3() {
        const double a = next(), b = next();
        return {a, b, next()};
    }

private:
    std::mt19937_64 engine_;
    int bits_;
};

// Gauss-Legendre nodes and weights on [0, 1].
std::vector<std::pair<double, double>> gauss_legendre(int order) {
    std::vector<std::pair<double, double>> rule;
    for (int i = 0; i < order; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (order + 0.5));
        double derivative = 0.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= order; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = order * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-16) break;
        }
        rule.emplace_back(0.5 * (1.0 - x), 1.0 / ((1.0 - x * x) * derivative * derivative));
    }
    return rule;
}

// A smooth monotone map of u in [0, 1] onto x in [low, high] whose steps are finest at `centre`
// and grow in proportion to the distance from it beyond `scale`: x = centre + scale sinh(t), t
// linear in u. A lobe of size `scale` gets as many cells as the rest of the range, and the map
// is smooth, so Gauss-Legendre cells keep their order of accuracy across the centre.
class Warp {
public:
    Warp(double low, double high, double centre, double scale)
        : centre_(centre),
          scale_(scale),
          left_(std::asinh((centre - low) / scale)),
          total_(left_ + std::asinh((high - centre) / scale)) {}
    double x(double u) const { return centre_ + scale_ * std::sinh(u * total_ - left_); }
    double dx_du(double u) const { return total_ * scale_ * std::cosh(u * total_ - left_); }
    double u(double x) const { return (std::asinh((x - centre_) / scale_) + left_) / total_; }

private:
    double centre_, scale_, left_, total_;
};

// Cells on the hemisphere above n in (θ, φ), bounded by the horizon and finest about a lobe's
// centre (the mirror direction of wo): cells uniform in (cos θ, φ) would hold a whole roughness-0.1
// lobe in one. Cell cells() collects directions below the horizon (the pdf is 0 there).
class HemisphereGrid {
public:
    HemisphereGrid(dvec3 n, dvec3 centre, double scale, int res_theta, int res_phi)
        : n_(n),
          phi_centre_(azimuth(centre)),
          res_theta_(res_theta),
          res_phi_(res_phi),
          theta_(0.0, kPi / 2, polar(centre), scale),
          phi_(phi_centre_ - kPi, phi_centre_ + kPi, phi_centre_,
               std::min(kPi, scale / std::max(std::sin(polar(centre)), 1e-9))) {}
    int cells() const { return res_theta_ * res_phi_; }
    int cell(dvec3 d) const {
        if (!(glm::dot(d, n_) > 0.0)) return cells();
        const int i = std::clamp(int(theta_.u(polar(d)) * res_theta_), 0, res_theta_ - 1);
        const double phi = phi_centre_ + std::remainder(azimuth(d) - phi_centre_, 2.0 * kPi);
        const int j = std::clamp(int(phi_.u(phi) * res_phi_), 0, res_phi_ - 1);
        return i * res_phi_ + j;
    }
    // Quadrature points (direction, weight) of cell k: a Gauss-Legendre product rule in (u, v).
    template <typename F>
    void for_each_point(int k, const std::vector<std::pair<double, double>>& rule, F&& f) const {
        const int i = k / res_phi_, j = k % res_phi_;
        const double du = 1.0 / res_theta_, dv = 1.0 / res_phi_;
        for (const auto& [a, wa] : rule) {
            const double u = (i + a) * du, theta = theta_.x(u);
            const double jacobian_u = std::sin(theta) * theta_.dx_du(u);
            for (const auto& [b, wb] : rule) {
                const double v = (j + b) * dv, phi = phi_.x(v);
                f(direction(theta, phi), wa * wb * du * dv * jacobian_u * phi_.dx_du(v));
            }
        }
    }

private:
    dvec3 tangent() const {
        const dvec3 helper = std::abs(n_.x) < 0.6 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
        return glm::normalize(glm::cross(helper, n_));
    }
    double polar(dvec3 d) const {
        return std::atan2(glm::length(glm::cross(d, n_)), glm::dot(d, n_));
    }
    double azimuth(dvec3 d) const {
        const dvec3 t1 = tangent(), t2 = glm::cross(n_, t1);
        return std::atan2(glm::dot(d, t2), glm::dot(d, t1));
    }
    dvec3 direction(double theta, double phi) const {
        const dvec3 t1 = tangent(), t2 = glm::cross(n_, t1);
        return glm::normalize(n_ * std::cos(theta) +
                              (t1 * std::cos(phi) + t2 * std::sin(phi)) * std::sin(theta));
    }

    dvec3 n_;
    double phi_centre_;
    int res_theta_, res_phi_;
    Warp theta_, phi_;
};

// The integrals over each cell of the kernel's bsdf_pdf and bsdf_eval (f cos) at (m, n, wo).
struct CellIntegrals {
    std::vector<double> pdf;
    std::vector<dvec3> eval;
    double pdf_total() const {
        double sum = 0.0;
        for (double value : pdf) sum += value;
        return sum;
    }
    dvec3 eval_total() const {
        dvec3 sum(0.0);
        for (const dvec3& value : eval) sum += value;
        return sum;
    }
};

CellIntegrals integrate_cells(const BsdfKernels& kernels, const Material& m, dvec3 n, dvec3 wo,
                              const HemisphereGrid& grid, int order) {
    const auto rule = gauss_legendre(order);
    std::vector<Lane> lanes;
    std::vector<double> weights;
    lanes.reserve(size_t(grid.cells()) * rule.size() * rule.size());
    for (int k = 0; k < grid.cells(); ++k) {
        grid.for_each_point(k, rule, [&](dvec3 wi, double weight) {
            lanes.push_back({m, n, wo, wi});
            weights.push_back(weight);
        });
    }
    const std::vector<EvalOut> values = kernels.eval(lanes);
    CellIntegrals result{std::vector<double>(size_t(grid.cells()), 0.0),
                         std::vector<dvec3>(size_t(grid.cells()), dvec3(0.0))};
    const size_t per_cell = rule.size() * rule.size();
    for (size_t i = 0; i < values.size(); ++i) {
        result.pdf[i / per_cell] += values[i].pdf * weights[i];
        result.eval[i / per_cell] += values[i].value * weights[i];
    }
    return result;
}

// The z of a two-sided normal test at `significance` shared by `tests` tests (Bonferroni),
// and never below 3: bisection on erfc.
double bonferroni_z(double significance, int tests) {
    const double target = significance / tests;
    double low = 0.0, high = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (low + high);
        (std::erfc(mid / std::sqrt(2.0)) > target ? low : high) = mid;
    }
    return std::max(3.0, high);
}

struct Chi2Outcome {
    double statistic = 0.0;
    int dof = 0;
    double p_value = 0.0;
    int pooled = 0;
    std::string failure;  // a reason to reject before the statistic
};

// Pearson's χ² of observed counts against expected ones, as Mitsuba 3's chi2 test does it:
// cells sorted by expected count, the smallest pooled until each pool expects at least 5.
Chi2Outcome chi2_test(const std::vector<double>& observed, const std::vector<double>& expected) {
    Chi2Outcome outcome;
    std::vector<size_t> order(expected.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    double pool_observed = 0.0, pool_expected = 0.0;
    int cells = 0;
    for (size_t i : order) {
        if (expected[i] <= 0.0) {
            if (observed[i] > 0.0 && outcome.failure.empty()) {
                outcome.failure = fmt::format("{} samples in a cell of expected count {}",
                                              observed[i], expected[i]);
            }
            continue;
        }
        pool_observed += observed[i];
        pool_expected += expected[i];
        if (pool_expected < 5.0) {
            ++outcome.pooled;
            continue;
        }
        outcome.statistic +=
            (pool_observed - pool_expected) * (pool_observed - pool_expected) / pool_expected;
        ++cells;
        pool_observed = pool_expected = 0.0;
    }
    if (pool_expected > 0.0) {
        outcome.statistic +=
            (pool_observed - pool_expected) * (pool_observed - pool_expected) / pool_expected;
        ++cells;
    }
    outcome.dof = cells - 1;
    if (outcome.dof < 1 && outcome.failure.empty()) outcome.failure = "fewer than 2 cells";
    outcome.p_value = chi2_p_value(outcome.statistic, std::max(outcome.dof, 1));
    return outcome;
}

// ---- Fixture ----------------------------------------------------------------------------------

struct BsdfVariant {
    int width;
    bool double_precision;
};

std::string label(const BsdfKernels& kernels) {
    return fmt::format("{}{}", kernels.double_precision() ? "double" : "float", kernels.width());
}

class BsdfTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { device_ = new ComputeDevice(open_device(-1)); }
    static void TearDownTestSuite() {
        kernels_.clear();
        delete device_;
        device_ = nullptr;
    }

    static const BsdfKernels& kernels(int width, bool double_precision) {
        auto& slot = kernels_[{width, double_precision}];
        if (!slot) slot = std::make_unique<BsdfKernels>(*device_, cache_, width, double_precision);
        return *slot;
    }

    // Every width and precision the device runs (the kernel library does not build with scalar
    // double lanes: see kMinDoublePacketWidth).
    static std::vector<BsdfVariant> all_precisions() {
        std::vector<BsdfVariant> list;
        for (bool double_precision : {false, true}) {
            if (double_precision && !device_->info.has_fp64) continue;
            for (int width : {1, 4, 8, 16}) {
                if (double_precision && width < kMinDoublePacketWidth) continue;
                list.push_back({width, double_precision});
            }
        }
        return list;
    }
    // The statistical tests' two: the widest float packet and the narrowest double one.
    static std::vector<BsdfVariant> statistical_precisions() {
        std::vector<BsdfVariant> list{{16, false}};
        if (device_->info.has_fp64) list.push_back({kMinDoublePacketWidth, true});
        return list;
    }

    static ComputeDevice* device_;
    static ProgramCache cache_;
    static std::map<std::pair<int, bool>, std::unique_ptr<BsdfKernels>> kernels_;
};
ComputeDevice* BsdfTest::device_ = nullptr;
ProgramCache BsdfTest::cache_{std::filesystem::path()};
std::map<std::pair<int, bool>, std::unique_ptr<BsdfKernels>> BsdfTest::kernels_;

// A few fixed normals, none on an axis but one (whose frame takes the sign branch).
const std::vector<dvec3>& normals() {
    static const std::vector<dvec3> list = {glm::normalize(dvec3(0.3, -0.5, 0.8)),
                                            dvec3(0.0, 0.0, -1.0),
                                            glm::normalize(dvec3(-0.7, 0.2, -0.4))};
    return list;
}

// wo at `degrees` from n (towards an arbitrary azimuth).
dvec3 incident(dvec3 n, double degrees, double azimuth = 0.7) {
    return spherical(std::cos(degrees * kPi / 180.0), azimuth, n);
}

std::vector<Lane> sample_lanes(const Material& m, dvec3 n, dvec3 wo, size_t count, Uniforms& u) {
    std::vector<Lane> lanes(count);
    for (Lane& lane : lanes) lane = {m, n, wo, u.next3()};
    return lanes;
}

// `count` samples of (m, n, wo), each handed to `f`, drawn from `u` in the order sample_lanes
// draws them but a chunk at a time: a million lanes and their results at once are hundreds of
// megabytes, and allocating and filling them took most of the statistical tests' time.
template <typename F>
void for_each_sample(const BsdfKernels& k, const Material& m, dvec3 n, dvec3 wo, size_t count,
                     Uniforms& u, F&& f) {
    constexpr size_t kChunk = size_t(1) << 14;  // a multiple of every width and work-item batch
    for (size_t done = 0; done < count; done += kChunk) {
        for (const SampleOut& s :
             k.sample(sample_lanes(m, n, wo, std::min(kChunk, count - done), u))) {
            f(s);
        }
    }
}

// ---- The tests --------------------------------------------------------------------------------

// diffuse_material fills every field: the albedo given, no glossy lobe, roughness 1, no emission.
TEST_F(BsdfTest, DiffuseMaterialFields) {
    for (const BsdfVariant& p : all_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        const std::vector<double> fields = k.diffuse_material_fields(dvec3(0.25, 0.5, 0.75));
        const std::vector<double> expected = {0.25, 0.5, 0.75, 0, 0, 0, 1, 0, 0, 0};
        EXPECT_EQ(fields, expected) << label(k);
    }
}

// The p-value helper against closed forms: dof 1 is erfc(sqrt(x / 2)), an even dof 2k the
// Poisson sum exp(-x/2) Σ_{i<k} (x/2)^i / i!.
TEST_F(BsdfTest, ChiSquarePValueMatchesClosedForms) {
    for (double x : {0.1, 1.0, 6.634897, 30.0}) {
        EXPECT_NEAR(chi2_p_value(x, 1), std::erfc(std::sqrt(0.5 * x)), 1e-12) << x;
    }
    for (int k : {1, 5, 50, 500}) {
        for (double x : {0.5 * k, 2.0 * k, 2.0 * k + 3.0 * std::sqrt(2.0 * k)}) {
            double term = std::exp(-0.5 * x), sum = 0.0;
            for (int i = 0; i < k; ++i) {
                sum += term;
                term *= 0.5 * x / (i + 1);
            }
            EXPECT_NEAR(chi2_p_value(x, 2 * k), sum, 1e-10) << "dof " << 2 * k << " x " << x;
        }
    }
    // Tabulated 1% critical values.
    EXPECT_NEAR(chi2_p_value(23.209251, 10), 0.01, 1e-7);
    EXPECT_NEAR(chi2_p_value(135.806723, 100), 0.01, 1e-7);
}

// One χ² configuration: a material seen from wo, with its lobe's axis and size for the grid.
struct Chi2Case {
    std::string name;
    Material m;
    dvec3 n, wo;
    double scale;  // the lobe's angular size, for HemisphereGrid
};

std::vector<Chi2Case> chi2_cases() {
    std::vector<Chi2Case> cases;
    const dvec3 n0 = normals()[0], n1 = normals()[1], n2 = normals()[2];
    for (double degrees : {0.0, 85.0}) {
        const std::string at = degrees == 0.0 ? "normal" : "grazing";
        const dvec3 n = degrees == 0.0 ? n0 : n2;
        const dvec3 wo = incident(n, degrees);
        cases.push_back({"diffuse " + at, diffuse({0.7, 0.5, 0.3}), n, wo, 1.0});
        for (double roughness : {0.1, 0.3, 0.7, 1.0}) {
            const double alpha = roughness * roughness;
            cases.push_back({fmt::format("metal {} {}", roughness, at),
                             metal({0.95, 0.64, 0.54}, roughness), n, wo,
                             std::max(2.0 * alpha, 0.02)});
        }
        for (double roughness : {0.3, 0.7}) {
            cases.push_back({fmt::format("plastic {} {}", roughness, at),
                             plastic({0.8, 0.5, 0.2}, roughness), n1, incident(n1, degrees),
                             2.0 * roughness * roughness});
        }
        cases.push_back({"half metal 0.1 " + at, {dvec3(0.5), dvec3(0.5), 0.1}, n, wo, 0.02});
    }
    return cases;
}

// The sampled directions follow bsdf_pdf: χ² at significance 0.01 over every configuration and
// precision (Bonferroni), on cells about each lobe's mirror direction, with the samples that left
// the hemisphere (invalid) as one more cell whose expected count is what the pdf leaves of 1.
TEST_F(BsdfTest, SampledDirectionsFollowThePdf) {
    const std::vector<Chi2Case> cases = chi2_cases();
    const int tests = int(cases.size() * statistical_precisions().size());
    const double significance = 0.01 / tests;
    for (const BsdfVariant& p : statistical_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        Uniforms u(1234, p.double_precision);
        for (const Chi2Case& c : cases) {
            SCOPED_TRACE(label(k) + " " + c.name);
            const size_t count = 1000000;
            const HemisphereGrid grid(c.n, reflect(c.wo, c.n), c.scale, 32, 64);
            const CellIntegrals integrals = integrate_cells(k, c.m, c.n, c.wo, grid, 5);
            // The grid's cells, the cell below the horizon, the invalid samples.
            std::vector<double> observed(size_t(grid.cells()) + 2, 0.0), expected;
            size_t deltas = 0;
            for_each_sample(k, c.m, c.n, c.wo, count, u, [&](const SampleOut& s) {
                deltas += s.delta ? 1 : 0;
                observed[s.valid ? size_t(grid.cell(s.wi)) : observed.size() - 1] += 1.0;
            });
            ASSERT_EQ(deltas, 0u);
            for (double integral : integrals.pdf) expected.push_back(double(count) * integral);
            expected.push_back(0.0);
            expected.push_back(std::max(0.0, double(count) * (1.0 - integrals.pdf_total())));
            const Chi2Outcome outcome = chi2_test(observed, expected);
            std::printf("%s %s: chi2 %.1f, %d dof (%d cells pooled), p %.3g; %g invalid\n",
                        label(k).c_str(), c.name.c_str(), outcome.statistic, outcome.dof,
                        outcome.pooled, outcome.p_value, observed.back());
            EXPECT_EQ(outcome.failure, "");
            EXPECT_GE(outcome.p_value, significance)
                << "χ² " << outcome.statistic << " with " << outcome.dof << " dof ("
                << outcome.pooled << " cells pooled); " << observed.back()
                << " invalid samples, expected " << expected.back();
        }
    }
}

// The pdf integrates to 1 over the hemisphere, less what visible-normal sampling reflects below
// the horizon. That mass is α² / (1 + α²) for a GGX lobe at normal incidence (the visible
// normals are D cos θ there, P(tan² θh ≤ t) = t / (α² + t), and a normal beyond 45° reflects
// n below the horizon); elsewhere it is measured as the fraction of invalid samples.
TEST_F(BsdfTest, PdfIntegratesToOneLessTheMassBelowTheHorizon) {
    const std::vector<Chi2Case> cases = chi2_cases();
    const double z = bonferroni_z(0.01, int(cases.size() * statistical_precisions().size()));
    for (const BsdfVariant& p : statistical_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        Uniforms u(99, p.double_precision);
        for (const Chi2Case& c : cases) {
            SCOPED_TRACE(label(k) + " " + c.name);
            const dvec3 centre = reflect(c.wo, c.n);
            const double coarse =
                integrate_cells(k, c.m, c.n, c.wo, HemisphereGrid(c.n, centre, c.scale, 24, 48), 5)
                    .pdf_total();
            const double fine =
                integrate_cells(k, c.m, c.n, c.wo, HemisphereGrid(c.n, centre, c.scale, 48, 96), 6)
                    .pdf_total();
            // The quadrature's error: well below its change from the coarse grid to the fine one.
            const double quadrature = std::abs(fine - coarse) + 1e-9;
            const bool normal_incidence = glm::dot(c.n, c.wo) > 1.0 - 1e-12;
            const double alpha = c.m.roughness * c.m.roughness;
            if (c.m.specular == dvec3(0.0)) {
                EXPECT_NEAR(fine, 1.0, 1e-6 + quadrature);
            } else if (normal_incidence && c.m.albedo == dvec3(0.0)) {
                EXPECT_NEAR(fine, 1.0 / (1.0 + alpha * alpha), 1e-6 + quadrature);
            } else {
                const size_t count = 400000;
                double invalid = 0.0;
                for_each_sample(k, c.m, c.n, c.wo, count, u,
                                [&](const SampleOut& s) { invalid += s.valid ? 0.0 : 1.0; });
                const double fraction = invalid / double(count);
                const double standard_error = std::sqrt(
                    std::max(fraction * (1.0 - fraction), 1.0 / double(count)) / double(count));
                EXPECT_NEAR(fine + fraction, 1.0, z * standard_error + quadrature)
                    << "pdf integral " << fine << ", invalid fraction " << fraction;
            }
        }
    }
}

// The materials the cheap tests run through: each kind of lobe and mixture, black and clamped
// inputs.
std::vector<Material> assorted_materials() {
    return {diffuse({0.7, 0.5, 0.3}),       diffuse(dvec3(1.0)),
            metal({0.95, 0.64, 0.54}, 0.1), metal(dvec3(1.0), 0.3),
            metal({1.0, 0.78, 0.34}, 0.7),  metal(dvec3(0.9), 1.0),
            plastic({0.8, 0.5, 0.2}, 0.05), plastic({0.2, 0.6, 0.9}, 0.5),
            {dvec3(0.5), dvec3(0.5), 0.2},  {dvec3(0.0), dvec3(0.0), 0.5},  // black
            {dvec3(0.3), dvec3(0.01), 0.4},   // F0 below 2%: a faded lobe
            {dvec3(1.5), dvec3(-0.2), 1.7}};  // out of range: clamped
}

// A sample's weight is bsdf_eval / bsdf_pdf at the sampled direction, its pdf bsdf_pdf there, and
// an invalid sample weighs and measures nothing.
TEST_F(BsdfTest, WeightIsEvalOverPdfAtTheSampledDirection) {
    for (const BsdfVariant& p : all_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        const double eps = p.double_precision ? 1e-12 : 1e-5;
        Uniforms u(7, p.double_precision);
        std::vector<Lane> lanes;
        for (const Material& m : assorted_materials()) {
            for (const dvec3& n : normals()) {
                for (double degrees : {0.0, 30.0, 60.0, 85.0, 89.9}) {
                    const std::vector<Lane> some =
                        sample_lanes(m, n, incident(n, degrees, u.next() * 2.0 * kPi), 256, u);
                    lanes.insert(lanes.end(), some.begin(), some.end());
                }
            }
        }
        const std::vector<SampleOut> samples = k.sample(lanes);
        long checked = 0, wrong = 0;
        std::string first;
        for (size_t i = 0; i < samples.size(); ++i) {
            const SampleOut& s = samples[i];
            bool ok = !s.delta;
            if (s.valid) {
                ++checked;
                ok = ok && s.pdf > 0.0 && std::abs(s.pdf - s.pdf_at) <= eps * s.pdf;
                for (int c = 0; c < 3; ++c) {
                    const double expected = s.eval[c] / s.pdf_at;
                    ok = ok && s.weight[c] >= 0.0 &&
                         std::abs(s.weight[c] - expected) <= eps * std::max(expected, 1e-3);
                }
            } else {
                ok = ok && s.weight == dvec3(0.0) && s.pdf == 0.0;
            }
            if (!ok && wrong++ == 0) {
                first = fmt::format(
                    "lane {}: valid {} weight ({}, {}, {}) pdf {}; eval ({}, {}, "
                    "{}) pdf {}",
                    i, s.valid, s.weight.x, s.weight.y, s.weight.z, s.pdf, s.eval.x, s.eval.y,
                    s.eval.z, s.pdf_at);
            }
        }
        EXPECT_EQ(wrong, 0) << label(k) << " " << first;
        EXPECT_GT(checked, long(samples.size() / 2)) << label(k);
    }
}

// Reciprocity: f(wo, wi) = f(wi, wo), i.e. bsdf_eval(wo, wi) / cos_i = bsdf_eval(wi, wo) / cos_o,
// and bsdf_eval is 0 with either direction below the surface.
TEST_F(BsdfTest, EvalIsReciprocal) {
    for (const BsdfVariant& p : all_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        const double eps = p.double_precision ? 1e-13 : 1e-6;
        Uniforms u(11, p.double_precision);
        std::vector<Lane> forward, backward;
        for (const Material& m : assorted_materials()) {
            for (const dvec3& n : normals()) {
                for (int i = 0; i < 400; ++i) {
                    // Mostly above (cosines down to 0.01), some below the surface.
                    const double cos_o = i % 10 == 0 ? -u.next() : 0.01 + 0.99 * u.next();
                    const double cos_i = i % 10 == 5 ? -u.next() : 0.01 + 0.99 * u.next();
                    const dvec3 wo = spherical(cos_o, 2.0 * kPi * u.next(), n);
                    const dvec3 wi = spherical(cos_i, 2.0 * kPi * u.next(), n);
                    forward.push_back({m, n, wo, wi});
                    backward.push_back({m, n, wi, wo});
                }
            }
        }
        const std::vector<EvalOut> there = k.eval(forward), back = k.eval(backward);
        long wrong = 0;
        std::string first;
        for (size_t i = 0; i < forward.size(); ++i) {
            const double cos_o = glm::dot(forward[i].n, forward[i].wo);
            const double cos_i = glm::dot(forward[i].n, forward[i].last);
            bool ok = true;
            for (int c = 0; c < 3; ++c) {
                if (cos_o <= 0.0 || cos_i <= 0.0) {
                    ok = ok && there[i].value[c] == 0.0 && back[i].value[c] == 0.0;
                    continue;
                }
                const double f = there[i].value[c] / cos_i, f_back = back[i].value[c] / cos_o;
                // Float inputs put rounding of ~eps / cos into the kernel's cosines.
                const double tolerance = 16.0 * eps * (1.0 + 1.0 / cos_i + 1.0 / cos_o);
                ok = ok && f >= 0.0 && std::abs(f - f_back) <= tolerance * std::max(f, f_back);
            }
            if (!ok && wrong++ == 0) {
                first =
                    fmt::format("pair {}: cos_o {}, cos_i {}: ({}, {}, {}) and ({}, {}, {})", i,
                                cos_o, cos_i, there[i].value.x, there[i].value.y, there[i].value.z,
                                back[i].value.x, back[i].value.y, back[i].value.z);
            }
        }
        EXPECT_EQ(wrong, 0) << label(k) << " " << first;
    }
}

// A white Lambertian material returns every valid sample with weight exactly 1 (f cos / pdf
// shares its cos / π), every sample is valid, and bsdf_eval integrates to 1 over the hemisphere.
TEST_F(BsdfTest, WhiteDiffuseWeightIsExactlyOne) {
    for (const BsdfVariant& p : all_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        Uniforms u(5, p.double_precision);
        std::vector<Lane> lanes;
        for (const dvec3& n : normals()) {
            for (double degrees : {0.0, 45.0, 89.0}) {
                const std::vector<Lane> some =
                    sample_lanes(diffuse(dvec3(1.0)), n, incident(n, degrees), 20000, u);
                lanes.insert(lanes.end(), some.begin(), some.end());
            }
        }
        // The extremes of the uniform numbers.
        const double below_one = 1.0 - std::ldexp(1.0, p.double_precision ? -53 : -24);
        for (double u1 : {0.0, below_one}) {
            for (double u2 : {0.0, below_one}) {
                lanes.push_back({diffuse(dvec3(1.0)), normals()[0], normals()[0], {0.5, u1, u2}});
            }
        }
        long not_one = 0;
        for (const SampleOut& s : k.sample(lanes)) {
            not_one += !(s.valid && s.weight == dvec3(1.0));
        }
        EXPECT_EQ(not_one, 0) << label(k) << ": samples of " << lanes.size();
        const dvec3 n = normals()[2];
        const dvec3 albedo = integrate_cells(k, diffuse(dvec3(1.0)), n, incident(n, 40.0),
                                             HemisphereGrid(n, n, 1.0, 16, 32), 6)
                                 .eval_total();
        const double tolerance = p.double_precision ? 1e-9 : 1e-5;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(albedo[c], 1.0, tolerance) << label(k);
    }
}

// The mean sample weight (a Monte Carlo estimate of the directional albedo) equals the host's
// quadrature of bsdf_eval over the hemisphere, per channel, within z standard errors (z for
// significance 0.01 over all checks, Bonferroni) plus the quadrature's own error.
struct AlbedoCheck {
    double mean, standard_error, quadrature, quadrature_error;
};

AlbedoCheck directional_albedo(const BsdfKernels& k, const Material& m, dvec3 n, dvec3 wo,
                               double scale, size_t count, Uniforms& u, int channel) {
    double sum = 0.0, sum2 = 0.0;
    for_each_sample(k, m, n, wo, count, u, [&](const SampleOut& s) {
        sum += s.weight[channel];
        sum2 += s.weight[channel] * s.weight[channel];
    });
    const double mean = sum / double(count);
    const double variance = std::max(sum2 / double(count) - mean * mean, 0.0);
    const dvec3 centre = reflect(wo, n);
    const double coarse = integrate_cells(k, m, n, wo, HemisphereGrid(n, centre, scale, 24, 48), 5)
                              .eval_total()[channel];
    const double fine = integrate_cells(k, m, n, wo, HemisphereGrid(n, centre, scale, 40, 80), 6)
                            .eval_total()[channel];
    return {mean, std::sqrt(variance / double(count)), fine, std::abs(fine - coarse)};
}

// What the lane precision's rounding leaves in a kernel-evaluated value and in the host's sum of
// 200000 of them: a diffuse lobe's weights are all the albedo to a few ulps, so their standard
// error is 0 and rounding is the tolerance.
double rounding(const BsdfKernels& k, double value) {
    return (k.double_precision() ? 1e-10 : 2e-6) * std::abs(value);
}

TEST_F(BsdfTest, MeanWeightIsTheDirectionalAlbedo) {
    const std::vector<Chi2Case> cases = chi2_cases();
    const double z = bonferroni_z(0.01, int(3 * cases.size() * statistical_precisions().size()));
    for (const BsdfVariant& p : statistical_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        Uniforms u(21, p.double_precision);
        for (const Chi2Case& c : cases) {
            for (int channel = 0; channel < 3; ++channel) {
                SCOPED_TRACE(fmt::format("{} {} channel {}", label(k), c.name, channel));
                const AlbedoCheck a =
                    directional_albedo(k, c.m, c.n, c.wo, c.scale, 200000, u, channel);
                EXPECT_NEAR(a.mean, a.quadrature,
                            z * a.standard_error + a.quadrature_error + rounding(k, a.quadrature));
            }
        }
    }
}

// The directional albedo of the glossy lobe alone (specular 1, albedo 0): the energy a
// single-scattering microfacet lobe loses to light that would bounce between microfacets. Printed
// as a table (roughness across, incidence down) by quadrature of bsdf_eval, each entry checked
// against the mean sample weight.
TEST_F(BsdfTest, GlossyAlbedoTable) {
    const std::vector<double> roughnesses = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    const std::vector<double> angles = {0.0, 30.0, 45.0, 60.0, 70.0, 80.0, 85.0, 89.0};
    const double z = bonferroni_z(0.01, int(roughnesses.size() * angles.size()));
    const BsdfKernels& k = kernels(16, false);
    Uniforms u(33, false);
    const dvec3 n = normals()[0];
    std::string table =
        "directional albedo of the GGX lobe with specular 1 (float16)\n"
        "theta_o \\ roughness";
    for (double r : roughnesses) table += fmt::format(" {:6.1f}", r);
    for (double degrees : angles) {
        table += fmt::format("\n{:>19}", fmt::format("{:.0f} deg", degrees));
        for (double r : roughnesses) {
            SCOPED_TRACE(fmt::format("roughness {} at {} degrees", r, degrees));
            const AlbedoCheck a =
                directional_albedo(k, metal(dvec3(1.0), r), n, incident(n, degrees),
                                   std::max(2 * r * r, 0.02), 50000, u, 1);
            EXPECT_NEAR(a.mean, a.quadrature,
                        z * a.standard_error + a.quadrature_error + rounding(k, a.quadrature));
            EXPECT_GT(a.quadrature, 0.0);
            EXPECT_LE(a.quadrature, 1.0 + a.quadrature_error);
            table += fmt::format(" {:6.4f}", a.quadrature);
        }
    }
    std::printf("%s\n", table.c_str());
    RecordProperty("glossy_albedo", table);
}

// Schlick's Fresnel with F90 = 1: the mirror's weight (F0 ≥ 2%).
dvec3 schlick(dvec3 f0, double cos_theta) {
    const double x = std::pow(1.0 - cos_theta, 5.0);
    return f0 + (dvec3(1.0) - f0) * x;
}

// Roughness 0 (and GGX alpha below 1e-3) is a mirror: wi is wo reflected about n, flagged delta,
// with pdf 1 and weight F for a metal; bsdf_eval and bsdf_pdf leave the delta lobe out. Just
// above the threshold the lobe is glossy again.
TEST_F(BsdfTest, MirrorReflectsExactlyWithSchlickWeight) {
    for (const BsdfVariant& p : all_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        const double eps = p.double_precision ? 1e-14 : 1e-6;
        Uniforms u(13, p.double_precision);
        std::vector<Lane> lanes;
        for (const dvec3& f0 : {dvec3(1.0, 0.78, 0.34), dvec3(0.04), dvec3(1.0)}) {
            for (double roughness : {0.0, 0.03}) {  // alpha 0 and 9e-4
                for (const dvec3& n : normals()) {
                    for (double degrees : {0.0, 30.0, 60.0, 85.0, 89.9}) {
                        lanes.push_back({metal(f0, roughness), n,
                                         incident(n, degrees, 2.0 * kPi * u.next()), u.next3()});
                    }
                }
            }
        }
        const std::vector<SampleOut> samples = k.sample(lanes);
        for (size_t i = 0; i < samples.size(); ++i) {
            const Lane& lane = lanes[i];
            const SampleOut& s = samples[i];
            SCOPED_TRACE(
                fmt::format("{} lane {}: cos_o {}", label(k), i, glm::dot(lane.n, lane.wo)));
            ASSERT_TRUE(s.valid && s.delta);
            const dvec3 mirror = reflect(lane.wo, lane.n);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.wi[c], mirror[c], 4.0 * eps);
            const dvec3 fresnel = schlick(lane.m.specular, glm::dot(lane.n, lane.wo));
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], fresnel[c], 8.0 * eps);
            EXPECT_EQ(s.pdf, 1.0);
            EXPECT_EQ(s.eval, dvec3(0.0));
            EXPECT_EQ(s.pdf_at, 0.0);
        }
        // Roughness 0.032 (alpha 1.02e-3) is a glossy lobe.
        const dvec3 n = normals()[0];
        for (const SampleOut& s :
             k.sample(sample_lanes(metal(dvec3(1.0), 0.032), n, incident(n, 30.0), 64, u))) {
            EXPECT_FALSE(s.delta) << label(k);
        }
    }
}

// The glossy lobe's Fresnel is Schlick's in wo.h: for a narrow lobe (roughness 0.1, alpha 0.01)
// wo.h stays within ~2 alpha of cos θo, so the albedo of F0 = 0.04 over that of F0 = 1 is
// F(cos θo) up to the curvature of F across the lobe (below 3e-3 at 80 degrees).
TEST_F(BsdfTest, GlossyLobeFresnelIsSchlick) {
    for (const BsdfVariant& p : all_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        const dvec3 n = normals()[2];
        for (double degrees : {0.0, 60.0, 80.0}) {
            const dvec3 wo = incident(n, degrees);
            const HemisphereGrid grid(n, reflect(wo, n), 0.02, 24, 48);
            const double white =
                integrate_cells(k, metal(dvec3(1.0), 0.1), n, wo, grid, 5).eval_total().y;
            const double dielectric =
                integrate_cells(k, metal(dvec3(0.04), 0.1), n, wo, grid, 5).eval_total().y;
            EXPECT_NEAR(dielectric / white, schlick(dvec3(0.04), glm::dot(n, wo)).y, 0.01)
                << label(k) << " at " << degrees << " degrees";
        }
    }
}

// A mirror-coated diffuse material (roughness 0, F0 0.04 over albedo a) returns on average
// F(cos_o) through its mirror samples and (1 - 0.04) a through its diffuse ones, whatever
// probability it samples each with.
TEST_F(BsdfTest, MirrorOverDiffuseMeanWeights) {
    const dvec3 albedo(0.6, 0.4, 0.2);
    const Material m{albedo, dvec3(0.04), 0.0};
    const std::vector<double> angles = {0.0, 60.0, 85.0};
    const double z = bonferroni_z(0.01, int(2 * 3 * angles.size() * all_precisions().size()));
    for (const BsdfVariant& p : all_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        Uniforms u(17, p.double_precision);
        for (double degrees : angles) {
            const dvec3 n = normals()[1], wo = incident(n, degrees);
            const size_t count = 100000;
            dvec3 mirror_sum(0.0), mirror_sum2(0.0), diffuse_sum(0.0), diffuse_sum2(0.0);
            for (const SampleOut& s : k.sample(sample_lanes(m, n, wo, count, u))) {
                ASSERT_TRUE(s.valid);
                (s.delta ? mirror_sum : diffuse_sum) += s.weight;
                (s.delta ? mirror_sum2 : diffuse_sum2) += s.weight * s.weight;
            }
            const dvec3 fresnel = schlick(dvec3(0.04), glm::dot(n, wo));
            for (int c = 0; c < 3; ++c) {
                SCOPED_TRACE(fmt::format("{} at {} degrees, channel {}", label(k), degrees, c));
                for (const auto& [sum, sum2, expected] :
                     {std::tuple{mirror_sum[c], mirror_sum2[c], fresnel[c]},
                      std::tuple{diffuse_sum[c], diffuse_sum2[c], 0.96 * albedo[c]}}) {
                    const double mean = sum / double(count);
                    const double se = std::sqrt(std::max(sum2 / double(count) - mean * mean, 0.0) /
                                                double(count));
                    EXPECT_NEAR(mean, expected, z * se + 1e-12);
                }
            }
        }
    }
}

bool finite(dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Lanes that break naive BSDF code: wo along n, grazing (cosine 0, 1e-7, 1e-20, 1e-40: a float
// denormal), below the surface, n along ±z (the frame's sign branch) and ±x; black, specular-only
// and mirror materials, roughness just below the mirror threshold; the extreme uniform numbers.
std::vector<Lane> edge_lanes(bool double_precision) {
    const double below_one = 1.0 - std::ldexp(1.0, double_precision ? -53 : -24);
    const std::vector<Material> materials = {diffuse(dvec3(0.5)),
                                             metal(dvec3(0.8), 0.5),
                                             metal(dvec3(1.0), 0.0),
                                             metal(dvec3(1.0), 1e-2),
                                             plastic(dvec3(0.5), 1.0),
                                             {dvec3(0.0), dvec3(0.0), 0.5},
                                             {dvec3(0.0), dvec3(0.04), 0.3},
                                             {dvec3(0.5), dvec3(0.0), 0.0}};
    std::vector<std::pair<dvec3, dvec3>> geometry;  // (n, wo)
    for (const dvec3& n : {dvec3(0, 0, 1), dvec3(0, 0, -1), dvec3(1, 0, 0), normals()[0]}) {
        geometry.push_back({n, n});
        geometry.push_back({n, -n});
        for (double cos_o : {0.0, 1e-7, 1e-20, 1e-40, -0.8}) {
            geometry.push_back({n, spherical(cos_o, 0.3, n)});
        }
    }
    geometry.push_back({dvec3(0, 0, 1), dvec3(1, 0, 0)});
    geometry.push_back({dvec3(0, 0, 1), dvec3(std::sqrt(1.0 - 1e-14), 0.0, 1e-7)});
    geometry.push_back({dvec3(0, 0, 1), dvec3(0.0, 1.0, 1e-40)});
    const std::vector<dvec3> numbers = {dvec3(0.0), dvec3(below_one), dvec3(0.5, 0.0, below_one),
                                        dvec3(0.01, below_one, 0.0)};
    std::vector<Lane> lanes;
    for (const Material& m : materials) {
        for (const auto& [n, wo] : geometry) {
            for (const dvec3& un : numbers) lanes.push_back({m, n, wo, un});
        }
    }
    return lanes;
}

// No NaN or Inf anywhere, weights and pdfs never negative, a valid sample a unit direction above
// the surface, an invalid one weightless; wo below the surface is invalid.
TEST_F(BsdfTest, EdgeCasesGiveFiniteResults) {
    for (const BsdfVariant& p : all_precisions()) {
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        const std::vector<Lane> lanes = edge_lanes(p.double_precision);
        const std::vector<SampleOut> samples = k.sample(lanes);
        std::vector<Lane> eval_lanes;
        for (size_t i = 0; i < lanes.size(); ++i) {
            const Lane& lane = lanes[i];
            const SampleOut& s = samples[i];
            SCOPED_TRACE(
                fmt::format("{} lane {}: n ({}, {}, {}) wo ({}, {}, {}) u ({}, {}, {}) "
                            "roughness {}",
                            label(k), i, lane.n.x, lane.n.y, lane.n.z, lane.wo.x, lane.wo.y,
                            lane.wo.z, lane.last.x, lane.last.y, lane.last.z, lane.m.roughness));
            ASSERT_TRUE(finite(s.wi) && finite(s.weight) && finite(s.eval) &&
                        std::isfinite(s.pdf) && std::isfinite(s.pdf_at));
            EXPECT_GE(std::min({s.weight.x, s.weight.y, s.weight.z, s.pdf, s.pdf_at, s.eval.x,
                                s.eval.y, s.eval.z}),
                      0.0);
            if (s.valid) {
                EXPECT_NEAR(glm::length(s.wi), 1.0, 1e-5);
                EXPECT_GT(glm::dot(s.wi, lane.n), 0.0);
            } else {
                EXPECT_EQ(s.weight, dvec3(0.0));
                EXPECT_EQ(s.pdf, 0.0);
            }
            if (glm::dot(lane.wo, lane.n) < 0.0) {
                EXPECT_FALSE(s.valid);
            }
            for (const dvec3& wi : {lane.n, -lane.n, lane.wo, -lane.wo, reflect(lane.wo, lane.n),
                                    spherical(0.0, 1.0, lane.n), spherical(1e-7, 2.0, lane.n)}) {
                eval_lanes.push_back({lane.m, lane.n, lane.wo, wi});
            }
        }
        const std::vector<EvalOut> values = k.eval(eval_lanes);
        for (size_t i = 0; i < values.size(); ++i) {
            const Lane& lane = eval_lanes[i];
            SCOPED_TRACE(fmt::format("{} eval lane {}", label(k), i));
            ASSERT_TRUE(finite(values[i].value) && std::isfinite(values[i].pdf));
            EXPECT_GE(
                std::min({values[i].value.x, values[i].value.y, values[i].value.z, values[i].pdf}),
                0.0);
            if (glm::dot(lane.n, lane.wo) < 0.0 || glm::dot(lane.n, lane.last) < 0.0) {
                EXPECT_EQ(values[i].value, dvec3(0.0));
                EXPECT_EQ(values[i].pdf, 0.0);
            }
        }
    }
}

// An ordinary lane's results do not depend on its neighbours: the same lanes sampled in packets
// of their own and interleaved with the edge cases above agree bit for bit (a vector built-in
// that lets one lane's 0, denormal or Inf corrupt another would show here).
TEST_F(BsdfTest, LanesDoNotAffectEachOther) {
    for (const BsdfVariant& p : all_precisions()) {
        if (p.width == 1) continue;
        const BsdfKernels& k = kernels(p.width, p.double_precision);
        Uniforms u(3, p.double_precision);
        const std::vector<Material> materials = assorted_materials();
        std::vector<Lane> ordinary;
        for (int i = 0; i < 512; ++i) {
            const dvec3 n = normals()[size_t(i) % normals().size()];
            ordinary.push_back({materials[size_t(i) % materials.size()], n,
                                spherical(0.05 + 0.95 * u.next(), 2.0 * kPi * u.next(), n),
                                u.next3()});
        }
        const std::vector<Lane> edges = edge_lanes(p.double_precision);
        std::vector<Lane> mixed;
        std::vector<size_t> where;
        for (size_t i = 0; i < ordinary.size(); ++i) {
            if (i % 3 != 1) mixed.push_back(edges[(i * 7) % edges.size()]);
            where.push_back(mixed.size());
            mixed.push_back(ordinary[i]);
        }
        const std::vector<SampleOut> alone = k.sample(ordinary), together = k.sample(mixed);
        long differ = 0;
        for (size_t i = 0; i < ordinary.size(); ++i) {
            const SampleOut& a = alone[i];
            const SampleOut& b = together[where[i]];
            differ += a.wi != b.wi || a.weight != b.weight || a.pdf != b.pdf ||
                      a.valid != b.valid || a.delta != b.delta || a.eval != b.eval ||
                      a.pdf_at != b.pdf_at;
        }
        EXPECT_EQ(differ, 0) << label(k) << ": lanes of " << ordinary.size();
    }
}

}  // namespace
}  // namespace fgr
