// SPDX-License-Identifier: Apache-2.0
#pragma once
// A plain C++ Mandelbulb, written straight from the formulas with trigonometry, to check the
// kernel's DE (which uses complex powers for integer exponents) and its march against.

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace fgr::test {

enum class BulbForm { Colatitude = 0, Latitude = 1 };

struct BulbParams {
    double power = 8.0;
    double bailout = 2.0;
    int iterations = 12;
    BulbForm form = BulbForm::Colatitude;
};

template <typename Real>
Real mandelbulb_de(Real px, Real py, Real pz, const BulbParams& bulb) {
    const Real n = static_cast<Real>(bulb.power);
    Real x = px, y = py, z = pz;
    Real dr = 1;
    Real r = std::sqrt(x * x + y * y + z * z);
    for (int i = 0; i < bulb.iterations && r <= static_cast<Real>(bulb.bailout); ++i) {
        const Real rho = std::sqrt(x * x + y * y);
        const Real theta = bulb.form == BulbForm::Colatitude
                               ? std::atan2(rho, z)
                               : std::asin(r > 0 ? std::clamp(z / r, Real(-1), Real(1)) : Real(0));
        const Real phi = std::atan2(y, x);
        const Real r_pow = std::pow(r, n - 1);
        dr = n * r_pow * dr + 1;
        const Real r_n = r_pow * r;
        const Real horizontal =
            bulb.form == BulbForm::Colatitude ? std::sin(n * theta) : std::cos(n * theta);
        const Real vertical =
            bulb.form == BulbForm::Colatitude ? std::cos(n * theta) : std::sin(n * theta);
        x = r_n * horizontal * std::cos(n * phi) + px;
        y = r_n * horizontal * std::sin(n * phi) + py;
        z = r_n * vertical + pz;
        r = std::sqrt(x * x + y * y + z * z);
    }
    if (r == 0) return 0;
    return Real(0.5) * std::log(r) * r / dr;
}

// Pixels of the canonical view (camera (2,-2,1) -> origin, up +z, tan(fov/2) = 0.5) whose ray
// hits: DE < t * pixel_angle within 256 steps and t <= 10, exactly the reference renderer's rule.
inline long canonical_view_hits(int width, int height, const BulbParams& bulb) {
    const glm::dvec3 eye(2.0, -2.0, 1.0);
    const glm::dvec3 forward = glm::dvec3(-2.0, 2.0, -1.0) / 3.0;
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 0, 1)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double pixel_angle = 1.0 / width;
    long hits = 0;
    for (int py = 0; py < height; ++py) {
        for (int px = 0; px < width; ++px) {
            const double u = (2.0 * (px + 0.5) / width - 1.0) * 0.5;
            const double v = (1.0 - 2.0 * (py + 0.5) / height) * 0.5 * height / width;
            const glm::dvec3 dir = glm::normalize(forward + right * u + up * v);
            double t = 0.0;
            for (int step = 0; step < 256; ++step) {
                const glm::dvec3 p = eye + dir * t;
                const float dist =
                    mandelbulb_de<float>(static_cast<float>(p.x), static_cast<float>(p.y),
                                         static_cast<float>(p.z), bulb);
                if (dist < t * pixel_angle) {
                    ++hits;
                    break;
                }
                t += dist;
                if (t > 10.0) break;
            }
        }
    }
    return hits;
}

}  // namespace fgr::test
