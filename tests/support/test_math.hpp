// SPDX-License-Identifier: Apache-2.0
#pragma once
// Numbers the tests share: π, a quiet NaN, and the χ² test's p-value.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fgr::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// The regularised upper incomplete gamma function Q(a, x) (series below a + 1, Lentz's continued
// fraction above), for χ² p-values: P(X ≥ x) = Q(dof / 2, x / 2).
inline double upper_gamma_q(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int k = 1; k < 100000; ++k) {
            term *= x / (a + k);
            sum += term;
            if (term < sum * 1e-17) break;
        }
        return std::max(0.0, 1.0 - sum * std::exp(log_prefix));
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int k = 1; k < 100000; ++k) {
        const double an = -k * (k - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-16) break;
    }
    return std::exp(log_prefix) * h;
}

// P(χ² with `dof` degrees of freedom ≥ statistic).
inline double chi2_p_value(double statistic, int dof) {
    return upper_gamma_q(0.5 * dof, 0.5 * statistic);
}

}  // namespace fgr::test
