// SPDX-License-Identifier: Apache-2.0
// The formula library's table: what each kernels/fractals/formulas/<family>.cl function takes,
// where it comes from, and what its scene starts with. The kernel function's arguments after (z, w,
// dr, c) are its params in this order (then the rotation, for those that have one).
#include <algorithm>

#include "scene/formulas/formulas.hpp"

namespace fgr {
namespace {

FormulaParam scalar(const char* id, const char* label, float min_value, float max_value,
                    float default_value, const char* description) {
    return {id,         label,     ParamType::Float,
            min_value,  max_value, {default_value, default_value, default_value},
            description};
}

FormulaParam vector(const char* id, const char* label, float min_value, float max_value, float x,
                    float y, float z, const char* description) {
    return {id, label, ParamType::Vec3, min_value, max_value, {x, y, z}, description};
}

FormulaParam power(float default_value) {
    return scalar("power", "Power", 2.0f, 16.0f, default_value, "the exponent n of z^n");
}

FormulaParam julia(float x, float y, float z) {
    return vector("julia", "Julia constant", -2.0f, 2.0f, x, y, z,
                  "the constant added each step instead of the point");
}

FormulaParam julia_w(float w) {
    return scalar("julia_w", "Julia constant w", -2.0f, 2.0f, w, "the constant's fourth part");
}

// The rotation's parameters, last: axis and angle (degrees).
void add_rotation(Formula& formula, float x, float y, float z, float degrees) {
    formula.rotation = true;
    formula.params.push_back(
        vector("axis", "Rotation axis", -1.0f, 1.0f, x, y, z, "the axis each step turns about"));
    formula.params.push_back(scalar("angle", "Rotation angle", -180.0f, 180.0f, degrees,
                                    "the turn each step adds, degrees"));
}

CameraView view(double px, double py, double pz, double tx, double ty, double tz, float fov) {
    CameraView v;
    v.position = {px, py, pz};
    v.target = {tx, ty, tz};
    v.up = {0.0f, 0.0f, 1.0f};
    v.fov_degrees = fov;
    return v;
}

Formula formula(const char* name, const char* title, const char* family,
                std::vector<std::string> tags, const char* summary, const char* origin,
                FormulaDistance distance, std::vector<FormulaParam> params) {
    Formula f;
    f.name = name;
    f.title = title;
    f.family = family;
    f.tags = std::move(tags);
    f.summary = summary;
    f.origin = origin;
    f.distance = distance;
    f.params = std::move(params);
    return f;
}

// A formula that iterates like `base` (same family, distance, estimate, numbers and view) under
// another name: a Julia form, a higher power.
Formula variant(Formula base, const char* name, const char* title, std::vector<std::string> tags,
                const char* summary) {
    base.name = name;
    base.title = title;
    base.tags = std::move(tags);
    base.summary = summary;
    return base;
}

// Bulbs: polynomial steps, logarithmic distance; the DE overestimates a little. 0.8 steps are
// enough for the camera rays, but soft shadow rays, which march out of the creases, overshot into
// the surface at 0.8 and 0.7 and speckled the bulbs with black pixels: 0.6 does not.
Formula bulb(Formula f, int iterations = 10, float bailout = 4.0f) {
    f.iterations = iterations;
    f.bailout = bailout;
    f.max_bailout = 64.0f;  // r^16 of the largest power stays a float
    f.step_factor = 0.6f;
    f.palette = 0;  // ember: the bulbs' warm relief
    f.max_distance = 10.0f;
    f.view = view(2.0, -2.2, 1.2, 0.0, 0.0, 0.0, 50.0f);
    return f;
}

// Quadratic and cubic steps: the logarithmic estimate is only good once |z| is well past 1, and
// where the number of steps before escape changes (|c| at the bailout) it jumps by about
// log(bailout) / bailout of itself; squares and cubes of 256 stay floats.
Formula low_power(Formula f) {
    f.bailout = 256.0f;
    f.max_bailout = 10000.0f;
    return f;
}

// The step factor `fgr check` found safe for the formula's scene, a little lower.
Formula stepping(Formula f, float step_factor) {
    f.step_factor = step_factor;
    return f;
}

// No estimate passed `fgr check` (the map is not conformal, or stretches unboundedly): the
// formula's scenes are inside tests, rendered by brute force. max_distance is where sampling
// along a ray ends.
Formula inside_only(Formula f) {
    f.estimate = FormulaEstimate::Inside;
    return f;
}

// Boxes: the whole box in view from a corner (`distance` about 1.9 times its half size, as far
// again as its corner), 24 steps so that the folds carve its faces (at 12 they are nearly flat),
// coloured by the steps an orbit took (the point trap's rings wallpapered the faces).
Formula box(Formula f, double distance = 9.0) {
    f.iterations = 24;
    f.colour_mode = 3;  // iterations
    f.palette = 0;      // ember
    f.bailout = 10000.0f;
    f.max_bailout = 1e6f;
    f.step_factor = 1.0f;
    f.max_distance = 40.0f;
    f.view = view(distance, -distance * 1.15, distance * 0.7, 0.0, 0.0, 0.0, 50.0f);
    return f;
}

// Box Julia sets and the Amazing Box: nearly every orbit takes all the steps, so the steps colour
// them one flat shade; the point trap draws ornaments on their faces instead.
Formula ornamented(Formula f) {
    f.colour_mode = 0;  // point
    return f;
}

Formula kifs(Formula f, double distance = 3.0) {
    f.iterations = 10;
    f.bailout = 10000.0f;
    f.max_bailout = 1e6f;
    f.step_factor = 1.0f;
    f.max_distance = 20.0f;
    f.view = view(distance, -distance * 1.2, distance * 0.75, 0.0, 0.0, 0.0, 50.0f);
    return f;
}

std::vector<Formula> build_library() {
    using D = FormulaDistance;
    std::vector<Formula> all;
    // --- bulbs ---
    all.push_back(bulb(formula("mandelbulb", "Mandelbulb", "bulbs", {"bulb", "power"},
                               "z^n + c in spherical coordinates, polar angle from +z",
                               "Daniel White and Paul Nylander, 2009 (skytopia.com)",
                               D::Logarithmic, {power(8.0f)})));
    all.push_back(bulb(formula(
        "mandelbulb_latitude", "Mandelbulb (latitude)", "bulbs", {"bulb", "power", "mandelbulber"},
        "z^n + c with the polar angle from the xy-plane: Mandelbulber 2's Mandelbulb",
        "Mandelbulber 2 (Krzysztof Marczak et al.)", D::Logarithmic, {power(8.0f)})));
    all.push_back(bulb(formula("juliabulb", "Juliabulb", "bulbs", {"bulb", "power", "julia"},
                               "the Mandelbulb's step with a fixed constant: its Julia sets",
                               "Daniel White and Paul Nylander, 2009", D::Logarithmic,
                               {power(8.0f), julia(0.45f, 0.5f, 0.0f)})));
    all.push_back(
        bulb(formula("juliabulb_latitude", "Juliabulb (latitude)", "bulbs",
                     {"bulb", "power", "julia", "mandelbulber"},
                     "the latitude-form Mandelbulb's step with a fixed constant",
                     "after White and Nylander, 2009, in Mandelbulber 2's angle convention",
                     D::Logarithmic, {power(8.0f), julia(0.45f, 0.5f, 0.0f)})));
    all.push_back(low_power(
        bulb(formula("white_nylander", "White-Nylander power 2", "bulbs", {"bulb", "polynomial"},
                     "the power-2 bulb written out as a polynomial: no trigonometry",
                     "Daniel White, 2009 (skytopia.com)", D::Logarithmic, {}))));
    all.push_back(
        bulb(formula("mandelbar_bulb", "Mandelbar bulb", "bulbs", {"bulb", "power", "tricorn"},
                     "the Mandelbulb of the mirror image (x, -y, z), the tricorn's conjugate in 3D",
                     "after Crowe, Hasson, Rippon and Strain-Clark, 1989 (the Mandelbar)",
                     D::Logarithmic, {power(8.0f)})));
    all.push_back(bulb(formula(
        "xenodreambuie", "Xenodreambuie", "bulbs", {"bulb", "power"},
        "the Mandelbulb with both angles turned after multiplying",
        "Xenodreambuie, fractalforums.com 2009 (Mandelbulber 2)", D::Logarithmic,
        {power(8.0f),
         scalar("alpha", "Azimuth turn", -180.0f, 180.0f, 0.0f, "added to n phi, degrees"),
         scalar("beta", "Polar turn", -180.0f, 180.0f, 45.0f, "added to n theta, degrees")})));
    all.push_back(stepping(
        low_power(bulb(formula(
            "makin", "Makin 3D", "bulbs", {"bulb", "polynomial", "revolution"},
            "(x^2 - y^2 - z^2, 2xy, 2xz) + c: the Mandelbrot set turned about the real axis",
            "David Makin, fractalforums.com 2009", D::Logarithmic, {}))),
        0.7f));
    all.push_back(stepping(
        low_power(bulb(formula(
            "benesi_pine_tree", "Benesi pine tree", "bulbs", {"bulb", "polynomial", "benesi"},
            "x^2 - y^2 - z^2, and (y, z) turned by 2x / |(y, z)|: Benesi's pine tree",
            "Matt Benesi, fractalforums.com 2010 (Mandelbulber 2)", D::Logarithmic, {}))),
        0.7f));
    Formula lambdabulb = inside_only(bulb(formula(
        "lambdabulb", "Lambdabulb", "bulbs", {"bulb", "power", "julia", "lambda"},
        "the logistic map lambda (z - z^n) in triplex numbers: the Mandelbulb's Lambda form",
        "Paul Nylander (bugman123.com) and fractalrebels, fractalforums.com 2011 (Mandelbulber 2's "
        "Mandelbulb Lambda), after Mandelbrot's lambda map (1980)",
        D::Logarithmic,
        {power(2.0f), vector("lambda", "Lambda", -4.0f, 4.0f, 1.6f, 0.4f, 0.3f,
                             "the constant the difference is multiplied by")})));
    lambdabulb.view = view(2.8, -3.2, 1.8, 0.3, 0.0, 0.0, 50.0f);
    all.push_back(lambdabulb);
    Formula riemann = inside_only(bulb(formula(
        "riemann_sphere", "Riemann sphere", "bulbs", {"bulb", "sphere", "stereographic"},
        "stereographic projection, a sine fold in the plane and back, radius |z|^(2 (1 + s^2 + "
        "t^2))",
        "msltoe, fractalforums.com 2011 (Mandelbulber 2's Riemann Sphere Msltoe)", D::Logarithmic,
        {scalar("scale", "Scale", 0.5f, 2.0f, 1.0f, "the sphere z is scaled onto"),
         scalar("shift_s", "Shift s", -3.14159f, 3.14159f, 0.0f, "the fold's phase along s"),
         scalar("shift_t", "Shift t", -3.14159f, 3.14159f, 0.0f, "the fold's phase along t")})));
    riemann.bailout = 10.0f;
    riemann.view = view(2.6, -3.0, 1.8, 0.0, 0.0, 0.0, 50.0f);
    all.push_back(riemann);
    // --- hypercomplex ---
    const Formula quaternion_plain = low_power(
        bulb(formula("quaternion", "Quaternion Mandelbrot", "hypercomplex",
                     {"hypercomplex", "quaternion"}, "q^2 + c in the quaternions, slice w = 0",
                     "Hart, Sandin and Kauffman, SIGGRAPH 1989", D::Logarithmic, {}),
             12));
    // the quaternions' squares are not conformal: `fgr check` measured 1.3x overestimates
    Formula quaternion_base = stepping(quaternion_plain, 0.7f);
    quaternion_base.palette = 1;  // ocean: the hypercomplex shells cool beside the warm bulbs
    all.push_back(quaternion_base);
    Formula quaternion_julia = variant(quaternion_base, "quaternion_julia", "Quaternion Julia",
                                       {"hypercomplex", "quaternion", "julia"},
                                       "q^2 + k for a fixed quaternion k, slice w = 0");
    quaternion_julia.origin = "Alan Norton, 1982; Hart, Sandin and Kauffman, SIGGRAPH 1989";
    quaternion_julia.params = {julia(-0.2f, 0.6f, 0.2f), julia_w(0.2f)};
    all.push_back(quaternion_julia);
    Formula cubic =
        variant(quaternion_base, "quaternion_cubic", "Cubic quaternion Mandelbrot",
                {"hypercomplex", "quaternion", "cubic"}, "q^3 + c in the quaternions, slice w = 0");
    all.push_back(cubic);
    Formula cubic_julia =
        variant(quaternion_base, "quaternion_cubic_julia", "Cubic quaternion Julia",
                {"hypercomplex", "quaternion", "cubic", "julia"},
                "q^3 + k for a fixed quaternion k, slice w = 0");
    cubic_julia.params = {julia(-0.5f, 0.4f, 0.2f), julia_w(0.0f)};
    all.push_back(cubic_julia);
    Formula qpower = variant(quaternion_base, "quaternion_power", "Quaternion power",
                             {"hypercomplex", "quaternion", "power"},
                             "q^n + c in the quaternions (polar form), slice w = 0");
    qpower.origin = "after Hart, Sandin and Kauffman, 1989; the polar form of quaternion powers";
    qpower.params = {scalar("power", "Power", 2.0f, 8.0f, 4.0f, "the exponent n")};
    qpower.max_bailout = 64.0f;
    qpower.bailout = 16.0f;
    all.push_back(qpower);
    Formula qpower_julia = variant(qpower, "quaternion_power_julia", "Quaternion power Julia",
                                   {"hypercomplex", "quaternion", "power", "julia"},
                                   "q^n + k for a fixed quaternion k (polar form), slice w = 0");
    qpower_julia.params = {scalar("power", "Power", 2.0f, 8.0f, 3.0f, "the exponent n"),
                           julia(-0.2f, 0.6f, 0.2f), julia_w(0.0f)};
    all.push_back(qpower_julia);
    Formula tetrabrot = inside_only(low_power(bulb(
        formula("tetrabrot", "Tetrabrot", "hypercomplex", {"hypercomplex", "bicomplex"},
                "the bicomplex Mandelbrot set z^2 + c, slice w = 0",
                "Dominic Rochon, 2000, in Corrado Segre's bicomplex numbers (1892)", D::Own, {}),
        12)));
    tetrabrot.distance_reiterates = true;
    // Rendered by brute force, but `fgr check` still marches its reiterated distance: at the bulbs'
    // 0.6 too few of its sample points reach the surface in four steps for the check to judge.
    tetrabrot.step_factor = 0.8f;
    tetrabrot.palette = 1;  // ocean, as the other hypercomplex sets
    tetrabrot.view = view(1.4, -2.6, 1.6, -0.6, 0.0, 0.0, 50.0f);
    all.push_back(tetrabrot);
    Formula bicomplex_julia = variant(tetrabrot, "bicomplex_julia", "Bicomplex Julia",
                                      {"hypercomplex", "bicomplex", "julia"},
                                      "z^2 + k for a fixed bicomplex k, slice w = 0");
    bicomplex_julia.origin = "after Rochon, 2000 (bicomplex Julia sets)";
    // Both idempotent parts of k, -0.12 + 0.65i and -0.12 + 0.75i, in the Mandelbrot set: their
    // Julia sets are connected, which Koebe's bound needs.
    bicomplex_julia.params = {julia(-0.12f, 0.7f, 0.05f), julia_w(0.0f)};
    bicomplex_julia.view = view(1.8, -2.4, 1.4, 0.0, 0.0, 0.0, 50.0f);
    all.push_back(bicomplex_julia);
    // --- boxes ---
    const std::vector<FormulaParam> mandelbox_params = {
        scalar("scale", "Scale", -3.0f, 3.0f, 2.0f, "the step's scale (|scale| at least 1.2)"),
        scalar("folding_limit", "Folding limit", 0.5f, 1.5f, 1.0f, "where the box fold reflects"),
        scalar("min_radius", "Min radius", 0.1f, 1.5f, 0.5f, "the sphere fold's inner radius"),
        scalar("fixed_radius", "Fixed radius", 0.5f, 1.5f, 1.0f, "the sphere fold's outer radius")};
    all.push_back(box(formula("mandelbox", "Mandelbox", "boxes", {"box", "folding"},
                              "scale * sphere_fold(box_fold(z)) + c",
                              "Tom Lowe, fractalforums.com 2010", D::Linear, mandelbox_params),
                      22.0));
    std::vector<FormulaParam> julia_box = mandelbox_params;
    julia_box.push_back(julia(1.0f, 1.0f, 1.0f));
    all.push_back(stepping(ornamented(box(formula("mandelbox_julia", "Mandelbox Julia", "boxes",
                                                  {"box", "folding", "julia"},
                                                  "the Mandelbox's step with a fixed constant",
                                                  "after Tom Lowe, 2010", D::Linear, julia_box),
                                          13.0)),
                           0.9f));
    // Scale -1.5, as Mandelbulber 2's Amazing Box examples have it (-1.5 to -1.8): a box half the
    // size of scale 2's, its faces carved deeper, the turn breaking their symmetry.
    std::vector<FormulaParam> amazing_params = mandelbox_params;
    amazing_params[0].default_value.fill(-1.5f);
    Formula amazing =
        box(formula("amazing_box", "Amazing Box", "boxes", {"box", "folding", "rotation"},
                    "the Mandelbox with a turn after the folds",
                    "Tglad's Amazing Box, fractalforums.com 2010 (Mandelbulber 2)", D::Linear,
                    amazing_params),
            7.0);
    amazing = stepping(ornamented(amazing), 0.75f);
    add_rotation(amazing, 0.3f, 0.4f, 1.0f, 12.0f);
    all.push_back(amazing);
    Formula surf = box(formula(
        "amazing_surf", "Amazing Surf", "boxes", {"box", "folding", "surface", "rotation"},
        "box fold on x and y only, sphere fold, scale: a surface along z",
        "Kali and M. Benesi, fractalforums.com 2011 (Mandelbulber 2)", D::Linear,
        {scalar("scale", "Scale", -3.0f, 3.0f, 1.8f, "the step's scale (|scale| at least 1.2)"),
         vector("fold", "Fold", 0.0f, 2.0f, 1.0f, 1.0f, 0.0f,
                "the box fold's limits on x and y (z is not folded)"),
         scalar("min_radius", "Min radius", 0.1f, 1.0f, 0.5f, "the sphere fold's inner radius"),
         scalar("c_scale", "c scale", 0.0f, 2.0f, 1.0f, "how much of the point is added")}));
    // Unturned, the surface is a flat slab: a turn about a tilted axis lifts its pattern into
    // relief, seen obliquely from near it, as Mandelbulber 2's Amazing Surf examples look.
    add_rotation(surf, 1.0f, 0.5f, 0.0f, 25.0f);
    surf.view = view(3.0, -4.0, 2.5, 0.0, 0.0, 0.0, 50.0f);
    surf = stepping(surf, 0.75f);
    all.push_back(surf);
    all.push_back(box(
        formula(
            "abox", "ABox (per-axis folds)", "boxes", {"box", "folding"},
            "the Mandelbox with a folding limit per axis",
            "after Tglad's box fold (Mandelbulber 2's ABox Mod)", D::Linear,
            {scalar("scale", "Scale", -3.0f, 3.0f, 2.0f, "the step's scale (|scale| at least 1.2)"),
             vector("limits", "Folding limits", 0.5f, 1.5f, 1.0f, 1.0f, 1.3f, "per-axis box fold"),
             scalar("min_radius", "Min radius", 0.1f, 1.5f, 0.5f, "the sphere fold's inner radius"),
             scalar("fixed_radius", "Fixed radius", 0.5f, 1.5f, 1.0f,
                    "the sphere fold's outer radius")}),
        22.0));
    all.push_back(stepping(
        ornamented(box(formula("abox_julia", "ABox Julia", "boxes", {"box", "folding", "julia"},
                               "the ABox's step with a fixed constant",
                               "after Tglad's box fold (Mandelbulber 2's ABox Mod)", D::Linear,
                               {scalar("scale", "Scale", -3.0f, 3.0f, 2.0f,
                                       "the step's scale (|scale| at least 1.2)"),
                                vector("limits", "Folding limits", 0.5f, 1.5f, 1.0f, 1.0f, 1.3f,
                                       "per-axis box fold"),
                                scalar("min_radius", "Min radius", 0.1f, 1.5f, 0.5f,
                                       "the sphere fold's inner radius"),
                                scalar("fixed_radius", "Fixed radius", 0.5f, 1.5f, 1.0f,
                                       "the sphere fold's outer radius"),
                                julia(1.0f, 1.0f, 1.0f)}),
                       13.0)),
        0.9f));
    std::vector<FormulaParam> amazing_julia_params = mandelbox_params;
    amazing_julia_params.push_back(julia(1.0f, 0.6f, 0.8f));
    Formula amazing_julia = box(formula("amazing_box_julia", "Amazing Box Julia", "boxes",
                                        {"box", "folding", "rotation", "julia"},
                                        "the Amazing Box's step with a fixed constant",
                                        "after Tglad's Amazing Box, fractalforums.com 2010",
                                        D::Linear, amazing_julia_params),
                                13.0);
    amazing_julia = stepping(ornamented(amazing_julia), 0.9f);
    add_rotation(amazing_julia, 0.3f, 0.4f, 1.0f, 12.0f);
    all.push_back(amazing_julia);
    // --- kaleidoscopic IFS ---
    Formula menger = kifs(formula(
        "menger", "Menger sponge (KIFS)", "kifs", {"kifs", "cube"},
        "the cube's fold and a scale of 3 about (1, 1, 1)", "Knighty, fractalforums.com 2010",
        D::Own,
        {scalar("scale", "Scale", 2.0f, 4.0f, 3.0f, "the step's scale"),
         vector("offset", "Offset", 0.0f, 2.0f, 1.0f, 1.0f, 1.0f, "the vertex scaled about")}));
    add_rotation(menger, 0.0f, 0.0f, 1.0f, 0.0f);
    all.push_back(menger);
    Formula sierpinski = kifs(formula(
        "sierpinski", "Sierpinski tetrahedron (KIFS)", "kifs", {"kifs", "tetrahedron"},
        "the tetrahedron's fold and a scale of 2 about (1, 1, 1)",
        "Knighty, fractalforums.com 2010", D::Own,
        {scalar("scale", "Scale", 1.5f, 3.0f, 2.0f, "the step's scale"),
         vector("offset", "Offset", 0.0f, 2.0f, 1.0f, 1.0f, 1.0f, "the vertex scaled about")}));
    add_rotation(sierpinski, 0.0f, 0.0f, 1.0f, 0.0f);
    all.push_back(sierpinski);
    Formula octahedral = kifs(formula(
        "octahedral", "Octahedral KIFS", "kifs", {"kifs", "octahedron"},
        "the octahedron's fold and a scale of 2 about a vertex", "Knighty, fractalforums.com 2010",
        D::Own,
        {scalar("scale", "Scale", 1.5f, 3.0f, 2.0f, "the step's scale"),
         vector("offset", "Offset", 0.0f, 2.0f, 1.0f, 0.0f, 0.0f, "the vertex scaled about")}));
    add_rotation(octahedral, 0.0f, 0.0f, 1.0f, 0.0f);
    all.push_back(octahedral);
    Formula icosahedral = kifs(formula(
        "icosahedral", "Icosahedral KIFS", "kifs", {"kifs", "icosahedron"},
        "the icosahedral fold and a scale about the icosahedron's vertex",
        "Knighty, fractalforums.com 2010", D::Own,
        {scalar("scale", "Scale", 1.5f, 4.0f, 3.0f, "the step's scale"),
         scalar("size", "Size", 0.5f, 2.0f, 1.0f, "the vertex's distance from the centre")}));
    add_rotation(icosahedral, 0.2f, 0.5f, 1.0f, 8.0f);
    all.push_back(icosahedral);
    Formula dodecahedral = kifs(formula(
        "dodecahedral", "Dodecahedral KIFS", "kifs", {"kifs", "dodecahedron"},
        "the icosahedral fold and a scale about the dodecahedron's vertex",
        "Knighty, fractalforums.com 2010", D::Own,
        {scalar("scale", "Scale", 1.5f, 4.0f, 2.618034f, "the step's scale"),
         scalar("size", "Size", 0.5f, 2.0f, 1.0f, "the vertex's distance from the centre")}));
    add_rotation(dodecahedral, 0.0f, 0.0f, 1.0f, 0.0f);
    all.push_back(dodecahedral);
    all.push_back(kifs(formula(
        "cantor_dust", "Cantor dust (KIFS)", "kifs", {"kifs", "cube", "dust"},
        "the octant's fold and a scale of 3 about (1, 1, 1): eight cubes of eight cubes",
        "Georg Cantor's set, 1883, in three dimensions; Knighty's KIFS form", D::Own,
        {scalar("scale", "Scale", 2.2f, 4.0f, 3.0f, "the step's scale"),
         vector("offset", "Offset", 0.0f, 2.0f, 1.0f, 1.0f, 1.0f, "the vertex scaled about")})));
    // --- Kleinian ---
    Formula kleinian = formula(
        "pseudo_kleinian", "Pseudo-Kleinian", "kleinian", {"kleinian", "inversion", "interior"},
        "a per-axis box fold and a sphere inversion: a Kleinian group's limit set, nearly",
        "Knighty, fractalforums.com 2011", D::Own,
        {vector("box", "Box size", 0.5f, 2.0f, 1.0f, 1.0f, 1.3f, "the box fold's half sizes"),
         scalar("size", "Inversion size", 0.5f, 1.5f, 1.0f, "the inversion sphere's radius^2"),
         vector("offset", "Offset", -0.5f, 0.5f, 0.0f, 0.0f, 0.0f, "added after the inversion"),
         scalar("thickness", "Thickness", 0.0f, 0.1f, 0.01f, "the drawn cylinders' radius")});
    kleinian.iterations = 12;
    kleinian.bailout = 1e10f;
    kleinian.max_bailout = 1e10f;
    kleinian.max_distance = 8.0f;
    kleinian.view = view(1.7, -1.5, 0.95, 0.0, 0.5, 0.2, 70.0f);
    all.push_back(kleinian);
    Formula apollonian = formula(
        "apollonian", "Apollonian packing", "kleinian",
        {"kleinian", "inversion", "spheres", "interior"},
        "the unit cell folded and inverted over and over: a packing of spheres, cut to one cell",
        "after Paul Nylander and Knighty, fractalforums.com 2010", D::Own,
        {scalar("size", "Inversion size", 1.0f, 1.5f, 1.2f, "the inversion sphere's radius^2")});
    apollonian.iterations = 10;
    apollonian.bailout = 1e10f;
    apollonian.max_bailout = 1e10f;
    apollonian.max_distance = 6.0f;
    // Near the cell, into its spheres (from further out, its cut faces hid them).
    apollonian.view = view(1.2, -1.5, 0.9, 0.0, 0.0, 0.0, 50.0f);
    all.push_back(apollonian);
    Formula jos = inside_only(formula(
        "jos_kleinian", "Jos Leys' Kleinian", "kleinian", {"kleinian", "inversion", "mandelbulber"},
        "a slab wrapped into a box, a half turn above a waving line and a Moebius inversion: "
        "the limit set of a Kleinian group",
        "Jos Leys, fractalforums.com 2015 (after Knighty), in Mandelbulber 2's form", D::Linear,
        {scalar("kr", "Klein r", 1.5f, 2.1f, 1.9f, "the slab's height: the group's translation"),
         scalar("ki", "Klein i", -0.5f, 0.5f, 0.05f, "the half turn's and inversion's shift"),
         vector("box", "Box size", 0.5f, 1.5f, 1.0f, 1.0f, 1.0f, "the wrapping box's half sizes"),
         scalar("thickness", "Thickness", 0.001f, 0.1f, 0.04f,
                "how near the slab's floor or ceiling an orbit ends in the set")}));
    jos.own_inside = true;
    jos.iterations = 30;
    jos.bailout = 1e10f;
    jos.max_bailout = 1e10f;
    jos.max_distance = 1.9f;  // it fills space: brute force samples this far along each ray
    jos.view = view(0.4, 0.95, 1.39, 0.015, 0.95, 0.07, 60.0f);
    jos.view.up = {0.0f, 1.0f, 0.0f};
    all.push_back(jos);
    return all;
}

}  // namespace

std::span<const Formula> formula_library() {
    static const std::vector<Formula> library = build_library();
    return library;
}

FormulaEstimate strongest_estimate(const std::vector<FormulaSlot>& sequence) {
    if (sequence.size() == 1 && sequence[0].formula->distance == FormulaDistance::Own) {
        return FormulaEstimate::Analytic;
    }
    FormulaEstimate weakest = FormulaEstimate::Analytic;
    for (const FormulaSlot& slot : sequence) weakest = std::max(weakest, slot.formula->estimate);
    return weakest;
}

FormulaDistance sequence_distance(const std::vector<FormulaSlot>& sequence) {
    if (sequence.size() == 1 && sequence[0].formula->distance == FormulaDistance::Own) {
        return FormulaDistance::Own;
    }
    const bool any_log = std::any_of(sequence.begin(), sequence.end(), [](const FormulaSlot& s) {
        return s.formula->distance == FormulaDistance::Logarithmic;
    });
    return any_log ? FormulaDistance::Logarithmic : FormulaDistance::Linear;
}

float sequence_max_bailout(const std::vector<FormulaSlot>& sequence) {
    float max_bailout = kFormulaMaxBailout;
    for (const FormulaSlot& slot : sequence) {
        max_bailout = std::min(max_bailout, slot.formula->max_bailout);
    }
    return max_bailout;
}

const char* formula_estimate_name(FormulaEstimate estimate) {
    switch (estimate) {
        case FormulaEstimate::Analytic:
            return "analytic";
        case FormulaEstimate::Delta:
            return "delta";
        case FormulaEstimate::Inside:
            return "inside";
    }
    return "analytic";
}

const Formula* find_formula(std::string_view name) {
    const auto library = formula_library();
    const auto found = std::find_if(library.begin(), library.end(),
                                    [&](const Formula& f) { return f.name == name; });
    return found == library.end() ? nullptr : &*found;
}

}  // namespace fgr
