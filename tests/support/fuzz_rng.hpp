// SPDX-License-Identifier: Apache-2.0
#pragma once
// The random numbers of the seeded fuzz tests (plugin descriptions, IFS files). Deterministic on
// every platform: only mt19937_64's raw output is used, no <random> distributions (their results
// are implementation-defined), so a case seed reproduces a failure anywhere.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

namespace fgr::test {

class FuzzRng {
public:
    explicit FuzzRng(uint64_t seed) : engine_(seed) {}
    uint64_t next() { return engine_(); }
    // Uniform in [0, n) (modulo bias is irrelevant here); 0 when n is 0.
    uint32_t below(uint64_t n) { return n == 0 ? 0 : static_cast<uint32_t>(next() % n); }
    int range(int low, int high) { return low + static_cast<int>(below(uint64_t(high - low) + 1)); }
    bool chance(double p) { return unit() < p; }
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    float uniform(float low, float high) {
        return static_cast<float>(low + (double{high} - double{low}) * unit());
    }
    template <typename T, std::size_t N>
    const T& pick(const T (&items)[N]) {
        return items[below(N)];
    }

private:
    std::mt19937_64 engine_;
};

// How many cases a fuzz test runs: FGR_FUZZ_CASES, default 10000 (a longer run before a release
// sets more).
inline std::uint64_t fuzz_case_count() {
    const char* text = std::getenv("FGR_FUZZ_CASES");
    return text != nullptr && *text != '\0' ? std::stoull(text) : 10000;
}

// The seed of a fuzz test's case 0 (case i is seeded with base + i): FGR_FUZZ_SEED, default fixed.
inline std::uint64_t fuzz_base_seed() {
    const char* text = std::getenv("FGR_FUZZ_SEED");
    return text != nullptr && *text != '\0' ? std::stoull(text) : 20260529;
}

}  // namespace fgr::test
