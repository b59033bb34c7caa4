// SPDX-License-Identifier: Apache-2.0
// A formula scene as the host renders it: its parameters and the OpenCL source written from the
// sequence (scene/formulas/formulas.hpp).
#include <fmt/format.h>

#include <algorithm>

#include "fgr/plugin.h"
#include "fgr/scene_helpers.h"
#include "scene/description_validation.hpp"
#include "scene/formulas/formulas.hpp"
#include "scene/scene_json.hpp"

namespace fgr {
namespace {

// The kernel name of a slot's value: param_<id> (a float or a vec3, as the scene declares it).
std::string argument(const FormulaScene& scene, std::size_t slot, const FormulaParam& param) {
    return "param_" + formula_param_id(scene.sequence.size(), slot, param.id);
}

// The arguments after (z, w, dr, c): the parameters, then the slot's rotation if it has one.
std::string arguments(const FormulaScene& scene, std::size_t slot, bool with_state) {
    const Formula& formula = *scene.sequence[slot].formula;
    std::string text = with_state ? "&z, &w, &dr, c" : "z, w, dr, c";
    for (const FormulaParam& param : formula.params) {
        if (formula.rotation && (param.id == "axis" || param.id == "angle")) continue;
        text += ", " + argument(scene, slot, param);
    }
    if (formula.rotation && with_state) text += fmt::format(", turn_{}", slot + 1);
    return text;
}

std::string step_call(const FormulaScene& scene, std::size_t slot) {
    return fmt::format("formula_{}({});", scene.sequence[slot].formula->name,
                       arguments(scene, slot, true));
}

// Which slot runs at iteration i: the slots in turn, each `repeat` times, over and over.
std::string loop_body(const FormulaScene& scene) {
    if (scene.sequence.size() == 1) {
        return "        " + step_call(scene, 0) + "\n";
    }
    int period = 0;
    for (const FormulaSlot& slot : scene.sequence) period += slot.repeat;
    std::string text = fmt::format("        const int phase = i % {};\n", period);
    int end = 0;
    for (std::size_t slot = 0; slot < scene.sequence.size(); ++slot) {
        end += scene.sequence[slot].repeat;
        const std::string call = step_call(scene, slot);
        if (slot == 0) {
            text += fmt::format("        if (phase < {}) {}\n", end, call);
        } else if (slot + 1 < scene.sequence.size()) {
            text += fmt::format("        else if (phase < {}) {}\n", end, call);
        } else {
            text += fmt::format("        else {}\n", call);  // the rest of the period
        }
    }
    return text;
}

// The distance from the final z, w and dr (and r, their length).
std::string distance_expression(const FormulaScene& scene) {
    switch (scene.distance) {
        case FormulaDistance::Logarithmic:
            // dr = 0 or below float's range (a Julia orbit through 0, or one that never escapes
            // shrinking it away) has no estimate: 0, as on the surface.
            return "select(0.5f * log(r) * r / dr, fgr_real(0.0f), (r <= 0.0f) | (dr <= 1e-30f))";
        case FormulaDistance::Linear:
            return "select(r / fabs(dr), fgr_real(0.0f), dr == 0.0f)";
        case FormulaDistance::Own: {
            const Formula& formula = *scene.sequence[0].formula;
            return fmt::format(
                "formula_{}_distance({}{})", formula.name, arguments(scene, 0, false),
                formula.distance_reiterates ? ", param_iterations, param_bailout" : "");
        }
    }
    return "r";
}

// The delta estimate: the same steps from c nudged by FORMULA_DELTA along each axis (stopping
// where c's orbit stopped, whatever the bailout says), |z| differenced into a gradient that
// replaces dr.
std::string delta_distance(const FormulaScene& scene) {
    std::string text =
        "    orbit_trap unused;\n"
        "    real gradient2 = fgr_real(0.0f);\n"
        "    for (int axis = 0; axis < 3; ++axis) {\n"
        "        const vec3 nudge = v3_splat(axis == 0 ? FORMULA_DELTA : 0.0f,\n"
        "                                    axis == 1 ? FORMULA_DELTA : 0.0f,\n"
        "                                    axis == 2 ? FORMULA_DELTA : 0.0f);\n"
        "        vec3 zn;\n"
        "        real wn, drn;\n"
        "        mask stepsn;\n"
        "        formula_scene_iterate(v3_add(c, nudge), PARAMS_PASS, steps, INFINITY, 0, "
        "&unused,\n"
        "                              &zn, &wn, &drn, &stepsn);\n"
        "        const real slope = (sqrt(v3_length2(zn) + wn * wn) - r) / FORMULA_DELTA;\n"
        "        gradient2 += slope * slope;\n"
        "    }\n"
        "    const real gradient = sqrt(gradient2);\n";
    text += scene.distance == FormulaDistance::Logarithmic
                ? "    return select(0.5f * log(r) * r / gradient, fgr_real(0.0f),\n"
                  "                  (r <= 0.0f) | (gradient <= 0.0f));\n"
                : "    return select(r / gradient, fgr_real(0.0f), gradient <= 0.0f);\n";
    return text;
}

}  // namespace

std::string formula_param_id(std::size_t slots, std::size_t slot, const std::string& param) {
    return slots == 1 ? param : fmt::format("f{}_{}", slot + 1, param);
}

std::string formula_kernel_source(const FormulaScene& scene) {
    std::string source = "#define FGR_KERNEL_API 2\n#define FGR_SCENE_HAS_COLOUR\n";
    // An inside test, not a distance: the host reads this line (Scene::inside_only) and renders
    // the scene by brute force.
    if (scene.estimate == FormulaEstimate::Inside) source += "#define FGR_SCENE_INSIDE_ONLY\n";
    source += fmt::format("#line 1 \"{}.formula.cl\"\n", scene.id);
    if (scene.estimate == FormulaEstimate::Delta) {
        source +=
            "/* the nudge of the delta estimate: small against the features, large against\n"
            " * float rounding of |z| after the steps */\n"
            "#define FORMULA_DELTA 1e-4f\n";
    }
    // The orbit of c: at most `limit` steps per lane, stopping once past the bailout; the final
    // z, w, dr and the steps each lane took.
    source +=
        "inline void formula_scene_iterate(const vec3 c, PARAMS, const mask limit,\n"
        "                                  const float bailout2, const int record,\n"
        "                                  orbit_trap* trap, vec3* z_out, real* w_out,\n"
        "                                  real* dr_out, mask* steps_out) {\n";
    for (std::size_t slot = 0; slot < scene.sequence.size(); ++slot) {
        const Formula& formula = *scene.sequence[slot].formula;
        if (!formula.rotation) continue;
        source +=
            fmt::format("    const rotation3 turn_{} = rotation_about_axis({}, {});\n", slot + 1,
                        "param_" + formula_param_id(scene.sequence.size(), slot, "axis"),
                        "param_" + formula_param_id(scene.sequence.size(), slot, "angle"));
    }
    source +=
        "    vec3 z = c;\n"
        "    real w = fgr_real(0.0f);\n"
        "    real dr = fgr_real(1.0f);\n"
        "    mask steps = (mask)(0);\n"
        "    for (int i = 0; i < param_iterations; ++i) {\n"
        "        const mask active = !(v3_length2(z) + w * w > bailout2) & (i < limit);\n"
        "        if (!fgr_any(active)) break;\n"
        "        const vec3 z_before = z;\n"
        "        const real w_before = w, dr_before = dr;\n";
    source += loop_body(scene);
    source +=
        "        z = v3_select(z_before, z, active);\n"
        "        w = select(w_before, w, active);\n"
        "        dr = select(dr_before, dr, active);\n"
        "        steps = select(steps, steps + 1, active);\n"
        "        if (record) *trap = trap_update(*trap, z, active);\n"
        "    }\n"
        "    *z_out = z;\n"
        "    *w_out = w;\n"
        "    *dr_out = dr;\n"
        "    *steps_out = steps;\n"
        "}\n";
    if (scene.estimate == FormulaEstimate::Inside) {
        source +=
            "inline mask formula_scene_inside(const vec3 c, PARAMS, const int record,\n"
            "                                 orbit_trap* trap) {\n"
            "    const float bailout2 = param_bailout * param_bailout;\n"
            "    vec3 z;\n"
            "    real w, dr;\n"
            "    mask steps;\n"
            "    formula_scene_iterate(c, PARAMS_PASS, (mask)(param_iterations), bailout2,\n"
            "                          record, trap, &z, &w, &dr, &steps);\n"
            "    (void)dr;\n"
            "    (void)steps;\n";
        const Formula& first = *scene.sequence[0].formula;
        if (scene.sequence.size() == 1 && first.own_inside) {
            source += fmt::format("    return formula_{}_inside({}) != 0;\n", first.name,
                                  arguments(scene, 0, false));
        } else {
            source +=
                "    return v3_length2(z) + w * w <= bailout2;  /* a NaN orbit is outside */\n";
        }
        source +=
            "}\n"
            "FGR_TRAP_COLOURED_INSIDE_SCENE(formula_scene_inside)\n";
        return source;
    }
    source +=
        "inline real formula_scene_orbit(const vec3 c, PARAMS, const int record,\n"
        "                                orbit_trap* trap) {\n"
        "    vec3 z;\n"
        "    real w, dr;\n"
        "    mask steps;\n"
        "    formula_scene_iterate(c, PARAMS_PASS, (mask)(param_iterations),\n"
        "                          param_bailout * param_bailout, record, trap, &z, &w, &dr,\n"
        "                          &steps);\n"
        "    const real r = sqrt(v3_length2(z) + w * w);\n";
    if (scene.estimate == FormulaEstimate::Delta) {
        source += delta_distance(scene);
    } else {
        source += fmt::format("    (void)steps;\n    return {};\n", distance_expression(scene));
    }
    source += "}\n";
    source += "FGR_TRAP_COLOURED_SCENE(formula_scene_orbit)\n";
    return source;
}

Scene formula_scene_to_scene(const FormulaScene& formula_scene, const std::filesystem::path& file) {
    Scene scene = scene_json::scene_of_file(formula_scene, formula_kernel_source(formula_scene),
                                            ".formula.cl", file);
    scene.tags = formula_scene.tags;
    scene.effects = FGR_EFFECT_AMBIENT_OCCLUSION | FGR_EFFECT_SOFT_SHADOWS;
    scene.march = formula_scene.march;
    scene.default_mode =
        formula_scene.estimate == FormulaEstimate::Inside ? RenderMode::Brute : RenderMode::Shaded;
    const std::size_t slots = formula_scene.sequence.size();
    for (std::size_t slot = 0; slot < slots; ++slot) {
        const FormulaSlot& entry = formula_scene.sequence[slot];
        const std::string group =
            slots == 1 ? std::string("Fractal")
                       : fmt::format("Formula {}: {}", slot + 1, entry.formula->title);
        for (std::size_t i = 0; i < entry.formula->params.size(); ++i) {
            const FormulaParam& param = entry.formula->params[i];
            ParamInfo info;
            info.id = formula_param_id(slots, slot, param.id);
            info.label = param.label;
            info.group = group;
            info.description = param.description;
            info.type = param.type;
            info.min_value = param.min_value;
            info.max_value = param.max_value;
            info.default_value = entry.values[i];
            scene.params.push_back(info);
        }
    }
    ParamInfo bailout;
    bailout.id = "bailout";
    bailout.label = "Bailout";
    bailout.group = "Fractal";
    bailout.description = "an orbit stops once |z| passes this";
    bailout.min_value = 0.5f;
    bailout.max_value = formula_scene.max_bailout;
    bailout.default_value.fill(formula_scene.bailout);
    scene.params.push_back(bailout);
    // The orbit-trap colouring's parameters, as FGR_COLOUR_PARAMS gives a plugin, starting as
    // the first formula's scene does (as its view does).
    const Formula& first = *formula_scene.sequence.front().formula;
    const fgr_param_desc colour[] = {
        FGR_COLOUR_PARAMS(first.colour_mode, first.palette, 1.0f, 0.96f, 0.9f)};
    for (ParamInfo& param : copy_param_descriptions(colour)) scene.params.push_back(param);
    add_builtin_params(scene);
    return scene;
}

}  // namespace fgr
