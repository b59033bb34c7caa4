// SPDX-License-Identifier: Apache-2.0
#pragma once
// Parameter values as the kernel reads them: one float per scalar, three per vec3/colour, in the
// scene's parameter order. The OpenCL accessors (param_<id>) index the same layout.

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace fgr {

// Bad user input (a value that does not parse or is out of range): one line, shown as is.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Offset of each parameter in the buffer, plus the total size as the last element.
std::vector<int> param_offsets(const Scene& scene);

// The scene's defaults, laid out for the kernel.
std::vector<float> default_param_values(const Scene& scene);

// Applies "id=value" to `values`. Values: numbers for float/int (ints must be integral; enum
// parameters also take a choice name), true/false/on/off/1/0 for bool, "x,y,z" for vec3/colour.
// Throws UsageError naming the parameter and the accepted range on any problem.
void set_param_from_text(const Scene& scene, std::vector<float>& values,
                         std::string_view assignment);

// Values for `to` (a new version of the scene `from`): a parameter the user changed from its
// default in `values` keeps that value (clamped to the new range) when `to` still has it with the
// same type; every other parameter takes `to`'s default, so a rebuilt plugin's new defaults show.
std::vector<float> carry_param_values(const Scene& from, const std::vector<float>& values,
                                      const Scene& to);

// A parameter's value at `value` (its components) as --set takes it: a number, an enum's choice
// name, true/false, or x,y,z.
std::string param_text(const ParamInfo& param, const float* value);

// "id=value" (param_text) for each parameter whose value in `values` differs from its default, in
// the scene's order: what a user set, e.g. for a report to say what it was made at.
std::vector<std::string> changed_params(const Scene& scene, const std::vector<float>& values);

// Reads a parameter's first component back, e.g. for the built-in quality knobs.
float param_value(const Scene& scene, const std::vector<float>& values, std::string_view id);

}  // namespace fgr
