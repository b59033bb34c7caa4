// SPDX-License-Identifier: Apache-2.0
#include "device/math_check.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>

#include "device/cache_directory.hpp"
#include "device/kernel_assembly.hpp"
#include "device/kernel_layout.hpp"
#include "fgr/kernel_library.hpp"
#include "util/files.hpp"

namespace fgr {
namespace {

// A function the kernel library calls on lanes (kernels/core/fgr_math.cl's helpers, or a plain
// built-in): its kernel in fgr_math_check.cl, how many arguments it reads, where its
// ordinary inputs lie, and the host's answer. `reference` computes in the lane precision
// (`as_float` rounds through float) so float lanes are judged against float libm.
struct MathFunction {
    const char* kernel;  // fgr_check_<kernel> in fgr_math_check.cl
    const char* name;
    int arity;
    double a_low, a_high;
    double b_low, b_high;
    double (*reference)(double a, double b, bool as_float);
    double ulps;  // allowed error, in units in the last place of the libm result
    // fgr_pow: defined for a >= 0 only, and double's exp(b log a) loses about |b ln a| ulps.
    bool power = false;
};

// `f` in the lane precision: through float for float lanes, so they are judged against float libm.
template <typename F>
double in_precision(bool as_float, double a, double b, F&& f) {
    if (as_float) return static_cast<double>(f(static_cast<float>(a), static_cast<float>(b)));
    return f(a, b);
}

#define FGR_REFERENCE(expression)                                \
    [](double a, double b, bool as_float) {                      \
        return in_precision(as_float, a, b, [](auto x, auto y) { \
            (void)y;                                             \
            return static_cast<decltype(x)>(expression);         \
        });                                                      \
    }

// Tolerances are the OpenCL full profile's worst case for the function (16 ulp for pow, 4 for
// sin/cos, ...) rounded up; the failures this test exists for are gross (a lane swapped for
// another lane's special case), so a generous bound costs nothing.
const std::vector<MathFunction>& functions() {
    static const std::vector<MathFunction> list = {
        {"fgr_pow", "fgr_pow", 2, 0.05, 3.0, -4.0, 8.0, FGR_REFERENCE(std::pow(x, y)), 16, true},
        {"fgr_pown7", "fgr_pown(x, 7)", 1, -2.0, 2.0, 0, 0, FGR_REFERENCE(std::pow(x, 7)), 16},
        {"fgr_pown2", "fgr_pown(x, 2)", 1, -3.0, 3.0, 0, 0, FGR_REFERENCE(std::pow(x, 2)), 16},
        {"fgr_sin", "fgr_sin", 1, -10.0, 10.0, 0, 0, FGR_REFERENCE(std::sin(x)), 4},
        {"fgr_cos", "fgr_cos", 1, -10.0, 10.0, 0, 0, FGR_REFERENCE(std::cos(x)), 4},
        {"exp", "exp", 1, -20.0, 20.0, 0, 0, FGR_REFERENCE(std::exp(x)), 4},
        {"log", "log", 1, 0.01, 100.0, 0, 0, FGR_REFERENCE(std::log(x)), 4},
        {"sqrt", "sqrt", 1, 0.0, 100.0, 0, 0, FGR_REFERENCE(std::sqrt(x)), 4},
        {"rsqrt", "rsqrt", 1, 0.01, 100.0, 0, 0, FGR_REFERENCE(1 / std::sqrt(x)), 4},
        {"atan2", "atan2", 2, -5.0, 5.0, -5.0, 5.0, FGR_REFERENCE(std::atan2(x, y)), 8},
        {"asin", "asin", 1, -0.99, 0.99, 0, 0, FGR_REFERENCE(std::asin(x)), 4},
        {"floor", "floor", 1, -50.0, 50.0, 0, 0, FGR_REFERENCE(std::floor(x)), 0},
        {"fabs", "fabs", 1, -50.0, 50.0, 0, 0, FGR_REFERENCE(std::fabs(x)), 0},
    };
    return list;
}

#undef FGR_REFERENCE

// Lane values that take a built-in down its special-case paths.
std::vector<double> edge_values(bool as_float) {
    const double denormal = as_float ? double(std::numeric_limits<float>::denorm_min()) * 5.0
                                     : std::numeric_limits<double>::denorm_min() * 5.0;
    const double inf = std::numeric_limits<double>::infinity();
    return {0.0, -0.0, denormal, -denormal, inf, -inf, std::numeric_limits<double>::quiet_NaN()};
}

bool is_denormal(double value, bool as_float) {
    const double smallest =
        as_float ? double(std::numeric_limits<float>::min()) : std::numeric_limits<double>::min();
    return value != 0.0 && std::fabs(value) < smallest;
}

// Devices may flush float denormals to zero (OpenCL makes denormals optional for float), so a
// lane is also right if it matches libm on the flushed inputs, and a result below the smallest
// normal may come back as zero.
double flushed(double value, bool as_float) {
    return is_denormal(value, as_float) ? std::copysign(0.0, value) : value;
}

bool close_enough(double expected, double got, double ulps, bool as_float) {
    if (std::isnan(expected)) return std::isnan(got);
    if (std::isinf(expected)) return got == expected;
    if (!std::isfinite(got)) return false;
    const double ulp =
        as_float ? double(std::nextafter(float(std::fabs(expected)),
                                         std::numeric_limits<float>::infinity())) -
                       std::fabs(expected)
                 : std::nextafter(std::fabs(expected), std::numeric_limits<double>::infinity()) -
                       std::fabs(expected);
    double tolerance = ulps * ulp;
    const double smallest =
        as_float ? double(std::numeric_limits<float>::min()) : std::numeric_limits<double>::min();
    if (std::fabs(expected) < smallest) tolerance = std::max(tolerance, smallest);
    return std::fabs(got - expected) <= tolerance;
}

// Deterministic ordinary values in [low, high].
struct Lcg {
    uint32_t state = 12345u;
    double next(double low, double high) {
        state = state * 1664525u + 1013904223u;
        return low + (high - low) * double(state >> 8) / double(1u << 24);
    }
};

std::string lanes_text(const std::vector<double>& values, size_t first, int width) {
    std::string text;
    for (int lane = 0; lane < width; ++lane) {
        text += fmt::format("{}{:.3g}", lane ? ", " : "", values[first + size_t(lane)]);
    }
    return width == 1 ? text : "(" + text + ")";
}

struct CaseInputs {
    std::vector<double> a, b;        // W lanes per case
    std::vector<size_t> first_case;  // per function: its first case (and one past the end)
    size_t cases() const { return first_case.back(); }
};

// For each function the precision uses: ordinary lanes, then for each edge value and each lane
// position (and each argument of a two-argument function) one case with that lane set to the edge
// value.
CaseInputs case_inputs(int width, bool as_float) {
    CaseInputs inputs;
    Lcg random;
    for (const MathFunction& function : functions()) {
        inputs.first_case.push_back(inputs.a.size() / size_t(width));
        auto add_case = [&](int edge_argument, int edge_lane, double edge) {
            for (int lane = 0; lane < width; ++lane) {
                double a = random.next(function.a_low, function.a_high);
                double b = function.arity == 2 ? random.next(function.b_low, function.b_high) : 0.0;
                if (as_float) {
                    a = double(float(a));
                    b = double(float(b));
                }
                if (lane == edge_lane) (edge_argument == 0 ? a : b) = edge;
                inputs.a.push_back(a);
                inputs.b.push_back(b);
            }
        };
        for (int repeat = 0; repeat < 4; ++repeat) add_case(-1, -1, 0.0);
        for (int argument = 0; argument < function.arity; ++argument) {
            for (double edge : edge_values(as_float)) {
                if (function.power && argument == 0 && std::signbit(edge)) continue;
                for (int lane = 0; lane < width; ++lane) add_case(argument, lane, edge);
            }
        }
    }
    inputs.first_case.push_back(inputs.a.size() / size_t(width));
    return inputs;
}

template <typename To, typename From>
std::vector<To> converted(const std::vector<From>& values) {
    return std::vector<To>(values.begin(), values.end());
}

template <typename T>
cl::Buffer input_buffer(const ComputeDevice& device, std::vector<T>& values) {
    return cl::Buffer(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                      values.size() * sizeof(T), values.data());
}

// Runs every function's cases on the device, one kernel each; returns the lane results.
template <typename T>
std::vector<double> run_cases(const ComputeDevice& device, const cl::Program& program,
                              const CaseInputs& inputs) {
    std::vector<T> a = converted<T>(inputs.a), b = converted<T>(inputs.b);
    const size_t lanes = a.size();
    cl::Buffer a_buffer = input_buffer(device, a), b_buffer = input_buffer(device, b);
    cl::Buffer out_buffer(device.context, CL_MEM_WRITE_ONLY, lanes * sizeof(T));
    for (size_t index = 0; index < functions().size(); ++index) {
        const size_t count = inputs.first_case[index + 1] - inputs.first_case[index];
        if (count == 0) continue;
        cl::Kernel kernel(program, fmt::format("fgr_check_{}", functions()[index].kernel).c_str());
        kernel.setArg(FGR_MATH_CHECK_ARG_A, a_buffer);
        kernel.setArg(FGR_MATH_CHECK_ARG_B, b_buffer);
        kernel.setArg(FGR_MATH_CHECK_ARG_OUT, out_buffer);
        kernel.setArg(FGR_MATH_CHECK_ARG_FIRST_CASE, cl_int(inputs.first_case[index]));
        device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(count),
                                          cl::NDRange(1));
    }
    std::vector<T> out(lanes);
    device.queue.enqueueReadBuffer(out_buffer, CL_TRUE, 0, lanes * sizeof(T), out.data());
    return converted<double>(out);
}

// The first wrong lane of `function`, as a line for the report, or "".
std::string first_failure(const MathFunction& function, size_t function_index,
                          const CaseInputs& inputs, const std::vector<double>& got, int width,
                          bool as_float) {
    const size_t begin = inputs.first_case[function_index] * size_t(width);
    const size_t end = inputs.first_case[function_index + 1] * size_t(width);
    for (size_t i = begin; i < end; ++i) {
        const double a = inputs.a[i], b = inputs.b[i];
        const double expected = function.reference(a, b, as_float);
        const double expected_flushed =
            function.reference(flushed(a, as_float), flushed(b, as_float), as_float);
        const double ulps = function.power && std::isfinite(std::log(a) * b)
                                ? function.ulps + 2.0 * std::fabs(b * std::log(a))
                                : function.ulps;
        const bool right = close_enough(expected, got[i], ulps, as_float) ||
                           close_enough(expected_flushed, got[i], ulps, as_float);
        if (!right) {
            const size_t first = i - i % size_t(width);
            return fmt::format(
                "{}: lane {} of {}{} gave {:.6g}, libm {:.6g}", function.name, i % size_t(width),
                lanes_text(inputs.a, first, width),
                function.arity == 2 ? " and " + lanes_text(inputs.b, first, width) : std::string(),
                got[i], expected);
        }
    }
    return {};
}

std::string precision_label(bool double_precision, int packet_width) {
    return fmt::format("{}{}", double_precision ? "double" : "float",
                       packet_width == 1 ? std::string() : std::to_string(packet_width));
}

}  // namespace

AssembledProgram math_check_program(bool double_precision, int packet_width) {
    // The library's types and lane-safe maths, then the check kernels, built with the switches a
    // render at this width and precision gets.
    AssembledProgram program;
    for (const KernelFile& file : kernel_prelude()) {
        program.source += file.source;
        if (std::string_view(file.name) == "fgr_math.cl") break;
    }
    program.source += math_check_source();
    KernelSwitches switches;
    switches.packet_width = packet_width;
    switches.double_precision = double_precision;
    program.options = switch_options(switches);
    // PoCL picks its built-in library per CPU, and this variable overrides the pick: a verdict
    // holds for one library only.
    if (const char* library = std::getenv("POCL_KERNELLIB_NAME"); library && *library) {
        program.source += fmt::format("\n/* POCL_KERNELLIB_NAME={} */\n", library);
    }
    return program;
}

MathCheckReport run_math_check(const ComputeDevice& device, ProgramCache& cache,
                               bool double_precision, int packet_width,
                               const std::string& extra_options) {
    if (double_precision && !device.info.has_fp64) {
        throw std::runtime_error(
            fmt::format("{} has no double precision (cl_khr_fp64)", device.info.name));
    }
    MathCheckReport report;
    report.double_precision = double_precision;
    report.packet_width = packet_width;
    AssembledProgram check = math_check_program(double_precision, packet_width);
    if (!extra_options.empty()) check.options += " " + extra_options;
    cl::Program program = cache.build(device, check);
    const bool as_float = !double_precision;
    const CaseInputs inputs = case_inputs(packet_width, as_float);
    const std::vector<double> got = double_precision ? run_cases<cl_double>(device, program, inputs)
                                                     : run_cases<cl_float>(device, program, inputs);
    report.lanes_checked = static_cast<int>(got.size());
    for (size_t index = 0; index < functions().size(); ++index) {
        std::string failure =
            first_failure(functions()[index], index, inputs, got, packet_width, as_float);
        if (!failure.empty()) report.failures.push_back(std::move(failure));
    }
    return report;
}

std::string math_check_verdict(const ComputeDevice& device, ProgramCache& cache,
                               bool double_precision, int packet_width) {
    static std::mutex mutex;
    static std::map<std::pair<std::filesystem::path, std::string>, std::string> verdicts;
    const std::string key =
        "math-" +
        ProgramCache::cache_key(device, math_check_program(double_precision, packet_width));
    std::lock_guard lock(mutex);
    const auto memory_key = std::make_pair(cache.directory(), key);
    if (auto found = verdicts.find(memory_key); found != verdicts.end()) return found->second;

    const std::filesystem::path file =
        cache.directory().empty() ? std::filesystem::path() : cache.directory() / (key + ".txt");
    if (!file.empty()) {
        // Bounded, and only a regular file: the verdict is a line, anything else a damaged entry
        // that the self-test replaces.
        std::string text;
        constexpr std::uintmax_t kMaxVerdictBytes = 64 * 1024;
        if (!read_file_bytes(file, text, kMaxVerdictBytes).empty()) text.clear();
        const std::string line = text.substr(0, text.find('\n'));
        if (line == "pass" ||
            (line.rfind("fail: ", 0) == 0 && line.find('\0') == std::string::npos)) {
            touch_cache_entry(file);  // recently used, like a program the cache hands out
            std::string verdict = line == "pass" ? std::string() : line.substr(6);
            return verdicts[memory_key] = verdict;
        }
    }
    const MathCheckReport report = run_math_check(device, cache, double_precision, packet_width);
    // The first failure in full, then the names of the other failing built-ins.
    std::string verdict;
    for (const std::string& failure : report.failures) {
        verdict += verdict.empty() ? failure : ", " + failure.substr(0, failure.find(':'));
    }
    spdlog::debug("math self-test {} on {}: {} lanes, {}",
                  precision_label(double_precision, packet_width), device.info.name,
                  report.lanes_checked, verdict.empty() ? "pass" : verdict);
    if (!file.empty()) {
        // An entry of the kernel cache like the programs: atomic, and under its size limit.
        const std::string failure = store_cache_entry(
            file, (verdict.empty() ? "pass" : "fail: " + verdict) + "\n", cache.size_limit());
        // Like the program cache, the verdict file only saves time.
        if (!failure.empty()) {
            spdlog::debug("could not store the math self-test verdict: {}", failure);
        }
    }
    return verdicts[memory_key] = verdict;
}

int trusted_packet_width(const ComputeDevice& device, ProgramCache& cache, bool double_precision,
                         int requested, const std::function<void(const std::string&)>& warn) {
    const std::string broken = math_check_verdict(device, cache, double_precision, requested);
    if (broken.empty()) return requested;
    const int minimum = double_precision ? 4 : 1;
    for (int width : {16, 8, 4, 1}) {
        if (width >= requested || width < minimum) continue;
        if (math_check_verdict(device, cache, double_precision, width).empty()) {
            if (warn) {
                warn(fmt::format(
                    "{} built-ins on {} failed the math self-test ({}): using "
                    "{}-ray packets",
                    precision_label(double_precision, requested), device.info.name, broken, width));
            }
            return width;
        }
    }
    if (warn) {
        warn(
            fmt::format("{} built-ins on {} failed the math self-test ({}) and no narrower "
                        "packet passed: some pixels may be wrong",
                        precision_label(double_precision, requested), device.info.name, broken));
    }
    return requested;
}

}  // namespace fgr
