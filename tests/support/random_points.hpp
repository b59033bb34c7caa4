// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reproducible test points: `count` points uniform in the cube [-extent, extent]^3, from `seed`.

#include <glm/vec3.hpp>
#include <random>
#include <vector>

namespace fgr::test {

inline std::vector<glm::vec3> random_points(int count, float extent, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> coordinate(-extent, extent);
    std::vector<glm::vec3> points;
    for (int i = 0; i < count; ++i)
        points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    return points;
}

}  // namespace fgr::test
