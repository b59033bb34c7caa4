// SPDX-License-Identifier: Apache-2.0
#pragma once
// The formula library and formula scenes. A formula is one step of an escape-time iteration,
// formula_NAME(&z, &w, &dr, c, parameters...) in kernels/fractals/formulas/<family>.cl; a formula
// scene (NAME.formula.json beside the plugins) iterates a sequence of them, each repeated some
// times, the sequence over and over: one formula is a classic fractal, several a hybrid
// (Mandelbulber's idea: two Mandelbulb steps, then an Amazing Box step, ...). The host writes the
// scene's OpenCL source from the sequence at load time: the families it uses, the per-point set-up
// (rotation matrices), the loop, and the distance the formulas' kinds call for.

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace fgr {

// How a formula's orbit escapes, which decides the distance estimate (Hart, Sandin and
// Kauffman 1989): polynomial growth r^n (0.5 log(r) r / dr), linear growth (r / |dr|: folds and
// scales), or a distance of the formula's own (formula_NAME_distance: the Kleinian surfaces).
enum class FormulaDistance { Logarithmic, Linear, Own };

// How a scene's distance is had: from the running derivative dr the formulas carry (analytic);
// by Mandelbulber's "delta DE": |z| after the same number of steps from the point nudged along
// each axis, its gradient by finite differences (four orbits a distance instead of one), for maps
// whose dr is no bound or to compare with the analytic one; or not at all (inside): the scene is
// an inside test, the orbit staying within the bailout for every step, that the brute-force mode
// renders (--mode brute), for maps neither estimate is safe for. In this order each is a weaker
// claim than the one before.
enum class FormulaEstimate { Analytic, Delta, Inside };

struct FormulaParam {
    std::string id;  // the kernel argument's name; a scene's parameter id (prefixed in hybrids)
    std::string label;
    ParamType type = ParamType::Float;  // Float or Vec3
    float min_value = 0.0f;
    float max_value = 1.0f;
    std::array<float, 3> default_value{};
    std::string description;
};

struct Formula {
    std::string name;    // formula_NAME in the kernel library; the name scene files use
    std::string title;   // "Amazing Surf"
    std::string family;  // kernels/fractals/formulas/<family>.cl
    std::vector<std::string> tags;
    std::string summary;  // what it does, one line
    std::string origin;   // where it comes from (author, year, place)
    FormulaDistance distance = FormulaDistance::Logarithmic;
    // Takes "axis" and "angle" parameters, passed to the kernel as one rotation3 built once per
    // point (after the formula's other parameters).
    bool rotation = false;
    // The strongest estimate its scenes can have: analytic where dr bounds how fast the orbit
    // moves with the point (`fgr check`'s Lipschitz and march-safety checks pass with it), inside
    // where no estimate passed them (a sequence takes its weakest member's).
    FormulaEstimate estimate = FormulaEstimate::Analytic;
    // An inside-only formula whose set is not "the orbit stays bounded" (a Kleinian limit set,
    // whose orbits never escape) decides inside itself: formula_NAME_inside(z, w, dr, c,
    // parameters...) on the orbit's end, when the formula is its scene's only one.
    bool own_inside = false;
    // Its own distance (formula_NAME_distance) runs orbits of its own from c, so the scene passes
    // it its iterations and bailout after the parameters (the bicomplex formulas: two complex
    // orbits). Such a distance stands even where the formula's dr is no bound (estimate Inside):
    // alone, its scenes measure it; in a hybrid they are inside tests.
    bool distance_reiterates = false;
    std::vector<FormulaParam> params;  // in the kernel function's order (axis and angle last)
    // What its scene starts with: iterations, bailout, the march's step factor (the DE's
    // overestimate, as `fgr check` measures it) and how far rays go, and a view.
    int iterations = 10;
    float bailout = 4.0f;
    // The largest bailout the step takes without overflowing a float (r^n for powers n).
    float max_bailout = 64.0f;
    float step_factor = 1.0f;
    float max_distance = 10.0f;
    CameraView view;
    // How its scene is coloured at first: the colour_mode and palette enums' indices
    // (point|planes|axes|iterations, ember|ocean|forest|pastel|mono).
    int colour_mode = 0;
    int palette = 1;
};

// "analytic", "delta" or "inside", as scene files spell it.
const char* formula_estimate_name(FormulaEstimate estimate);

// Every formula, by family then name.
std::span<const Formula> formula_library();
const Formula* find_formula(std::string_view name);

// --- Formula scene files ---------------------------------------------------------------------

inline constexpr int kFormulaFormatVersion = 1;
inline constexpr std::size_t kFormulaMaxFileBytes = 256u << 10;
// Slots in a sequence, and repeats of one slot: far beyond any hybrid worth iterating.
inline constexpr std::size_t kFormulaMaxSlots = 16;
inline constexpr int kFormulaMaxRepeat = 64;
// The largest bailout a formula scene may set, whatever its formulas allow.
inline constexpr float kFormulaMaxBailout = 1e10f;
// The ranges of a file's "iterations", "step_factor" and "max_distance".
inline constexpr int kFormulaMaxIterations = 1000;
inline constexpr double kFormulaMinStepFactor = 0.05, kFormulaMaxStepFactor = 1.0;
inline constexpr double kFormulaMinMaxDistance = 1e-3, kFormulaMaxMaxDistance = 1e6;

struct FormulaSlot {
    const Formula* formula = nullptr;
    int repeat = 1;
    // The scene's parameter values for this slot, in formula->params' order (the file's values
    // where it gave them, else the formula's defaults).
    std::vector<std::array<float, 3>> values;
};

struct FormulaScene {
    int version = kFormulaFormatVersion;
    std::string id;
    std::string name;
    std::string description;
    std::vector<std::string> tags;
    std::vector<FormulaSlot> sequence;
    FormulaDistance distance = FormulaDistance::Logarithmic;
    FormulaEstimate estimate = FormulaEstimate::Analytic;
    int iterations = 10;
    float bailout = 4.0f;
    float max_bailout = 64.0f;  // the least of the sequence's formulas'
    MarchSettings march;
    std::vector<NamedCamera> cameras;  // [0] is the default view
    std::vector<CameraPath> camera_paths;
    std::vector<Light> lights;
    std::string environment;  // the path mode's when the user names none; "" for the sky
};

// The strongest estimate a sequence allows: a formula alone with a distance of its own has it
// (analytic); otherwise the weakest of its formulas' estimates.
FormulaEstimate strongest_estimate(const std::vector<FormulaSlot>& sequence);

// The distance a sequence calls for when nobody chooses: a formula's own only alone; else
// logarithmic when any step is polynomial (its growth wins), linear when all fold and scale.
FormulaDistance sequence_distance(const std::vector<FormulaSlot>& sequence);

// The largest bailout every formula of the sequence keeps finite: the least of their ceilings.
float sequence_max_bailout(const std::vector<FormulaSlot>& sequence);

// A formula scene file's problem, one line starting with the file's name.
struct FormulaError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

bool is_formula_file_name(const std::filesystem::path& file);
// Parses and checks a formula scene document; `origin` (a file name) starts every message.
FormulaScene parse_formula_json(const std::string& text, const std::string& origin);
FormulaScene read_formula_file(const std::filesystem::path& file);

// The Scene the host renders: the generated source, the slots' parameters (prefixed f1_, f2_ ...
// when there are several), bailout, colour and the built-ins.
Scene formula_scene_to_scene(const FormulaScene& formula_scene, const std::filesystem::path& file);
// The OpenCL source of the scene's distance estimate and colour.
std::string formula_kernel_source(const FormulaScene& formula_scene);
// The scene parameter id of slot `slot`'s parameter `param` in a sequence of `slots` slots.
std::string formula_param_id(std::size_t slots, std::size_t slot, const std::string& param);

}  // namespace fgr
