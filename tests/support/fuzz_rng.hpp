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

// How many cases a seeded fuzz test runs: $FGR_FUZZ_CASES, else 10000 (the CI's number; a longer
// run before a release sets more).
inline std::uint64_t fuzz_case_count() {
    if (const char* cases = std::getenv("FGR_FUZZ_CASES"); cases != nullptr && *cases != '\0') {
        return std::strtoull(cases, nullptr, 0);
    }
    return 10000;
}

// The seed of a fuzz test's first case: $FGR_FUZZ_SEED, else `fixed` (each test may have its
// own). Case i is seeded with base + i, so a failure's message names the one seed that reproduces
// it: FGR_FUZZ_SEED=<seed> FGR_FUZZ_CASES=1.
inline std::uint64_t fuzz_base_seed(std::uint64_t fixed = 20260529) {
    if (const char* seed = std::getenv("FGR_FUZZ_SEED"); seed != nullptr && *seed != '\0') {
        return std::strtoull(seed, nullptr, 0);
    }
    return fixed;
}

}  // namespace fgr::test
