// SPDX-License-Identifier: Apache-2.0
#pragma once
// Edits of a formula scene's sequence, as the viewer's hybrid editor makes them: add a formula,
// remove, move or repeat a slot. Each returns the edited scene, whose settings that follow from
// the sequence (distance, estimate, bailout's ceiling) are worked out again, or throws
// FormulaEditError with one line saying why the edit cannot be made. Slots keep their values as
// they move; formula_scene_to_scene renumbers their parameters (f1_, f2_ ...).

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/formulas/formulas.hpp"
#include "scene/scene.hpp"

namespace fgr {

struct FormulaEditError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// Appends `formula` (its default values, repeated once). Iterations and how far rays go grow to
// what the new formula needs, the step factor shrinks to its.
FormulaScene with_formula_added(FormulaScene scene, const Formula& formula);
FormulaScene with_slot_removed(FormulaScene scene, std::size_t slot);
// Moves slot `slot` by `offset` places (-1: up, towards the start; +1: down).
FormulaScene with_slot_moved(FormulaScene scene, std::size_t slot, int offset);
FormulaScene with_repeat(FormulaScene scene, std::size_t slot, int repeat);

// Takes the values a running scene (`running`, made from `scene` by formula_scene_to_scene) has
// for its slots' parameters into the slots, so an edit keeps what the user set.
void take_slot_values(FormulaScene& scene, const Scene& running, const std::vector<float>& values);

// The values for `after` (the scene of an edited sequence whose slots took the user's values,
// see take_slot_values): the slots' parameters are `after`'s defaults, which are those values
// wherever the slots now stand; the rest (bailout, colour, quality) are carried over from
// `before` by id, as a reload does.
std::vector<float> values_after_edit(const Scene& before, const std::vector<float>& values,
                                     const Scene& after, const FormulaScene& edited);

// The scene as a formula file (docs/sdk/formulas.md) that reads back as the
// same sequence, settings, cameras, paths and lights: every value written, the distance and
// estimate only where the sequence would not give them by itself; its "$schema" the schema beside
// the running executable (util/installed_files.hpp).
std::string formula_scene_json(const FormulaScene& scene);

}  // namespace fgr
