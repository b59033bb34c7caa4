// SPDX-License-Identifier: Apache-2.0
#pragma once
// Deep zooms into the Mandelbulb, where float's coordinates are coarser than a pixel: the views
// `--precision auto` must render in double.

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "mandelbulb_reference.hpp"
#include "scene/scene.hpp"

namespace fgr::test {

// How far in front of the surface a deep zoom's camera stands.
constexpr double kDeepZoomStandoff = 2e-6;

// A view `across` units wide, `standoff` in front of the Mandelbulb's surface where the canonical
// view's central ray meets it (found by a long-double march down to 1e-12); position and target
// are exact doubles. `bulb` is the mandelbulb plugin's scene with its default parameters.
inline CameraView mandelbulb_deep_zoom(const Scene& bulb, double across = 1e-7,
                                       double standoff = kDeepZoomStandoff) {
    const CameraView canonical = bulb.cameras.front().view;
    const glm::dvec3 eye(canonical.position);
    const glm::dvec3 direction = glm::normalize(glm::dvec3(canonical.target) - eye);
    long double t = 0.0L;
    for (int step = 0; step < 10000; ++step) {
        const glm::dvec3 p = eye + direction * double(t);
        const long double de = mandelbulb_de<long double>(p.x, p.y, p.z, BulbParams{});
        if (de < 1e-12L) break;
        t += de;
    }
    const glm::dvec3 surface = eye + direction * double(t);
    CameraView view = canonical;
    view.position = surface - direction * standoff;
    view.target = surface;
    view.fov_degrees = float(glm::degrees(2.0 * std::atan(0.5 * across / standoff)));
    return view;
}

}  // namespace fgr::test
