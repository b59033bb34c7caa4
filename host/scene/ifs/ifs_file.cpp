// SPDX-License-Identifier: Apache-2.0
// IFS scene files (`NAME.ifs.json`): reading, validating, and the bounding sphere of the maps.
// The format is documented in docs/sdk/ifs.md.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "camera/view_validation.hpp"
#include "scene/description_validation.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/ifs/ifs_cost.hpp"
#include "scene/scene_json.hpp"
#include "util/json_fields.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

using json_fields::check_keys;
using json_fields::dvec3_from;
using json_fields::fail;
using json_fields::finite_double;
using json_fields::shown;
using nlohmann::json;
using scene_json::array_from;
using scene_json::require_object;
using scene_json::text_from;

constexpr const char* kIfsFormat = "fgr-ifs";
constexpr std::string_view kIfsSuffix = ".ifs.json";

// Numbers in a map (matrix entries, scales, translations): a contraction's entries are below 1
// anyway; translations are bounded so the kernel's float arithmetic stays meaningful.
constexpr double kMaxMapNumber = 1e6;
// A map whose smallest singular value is below this times its largest flattens space: the exact
// ray tracer needs every map's inverse.
constexpr double kSingularRatio = 1e-9;
// How far from the origin the attractor's bounding sphere may reach.
constexpr double kMaxExtent = 1e5;

// Validation stops at the first problem with a one-line reason; parse_ifs_json puts the file's
// name in front. json_fields throws std::runtime_error the same way.

// --- Small readers -------------------------------------------------------------------------------

// A colour in [0, 1]: a map's albedo.
glm::vec3 albedo_from(const json& object, const std::string& where) {
    const glm::dvec3 colour = dvec3_from(object, "colour", where);
    for (int i = 0; i < 3; ++i) {
        if (colour[i] < 0.0 || colour[i] > 1.0) {
            fail("{} \"colour\" components must be in [0, 1]", where);
        }
    }
    return glm::vec3(colour);
}

// --- Maps ----------------------------------------------------------------------------------------

// x -> T + R S x from "scale", "rotate" and "translate", each optional.
void compose_map(const json& entry, const std::string& where, IfsMap& map) {
    glm::dvec3 scale(1.0);
    if (entry.contains("scale")) {
        const json& value = entry.at("scale");
        if (value.is_array()) {
            scale = dvec3_from(entry, "scale", where, kMaxMapNumber);
        } else {
            scale = glm::dvec3(finite_double(value, where + " \"scale\"", kMaxMapNumber));
        }
    }
    glm::dmat3 rotation(1.0);
    if (entry.contains("rotate")) {
        const json& rotate = entry.at("rotate");
        const std::string rotate_where = where + " \"rotate\"";
        require_object(rotate, rotate_where);
        check_keys(rotate, {"axis", "degrees"}, rotate_where);
        const glm::dvec3 axis = dvec3_from(rotate, "axis", rotate_where, kMaxMapNumber);
        if (!rotate.contains("degrees")) fail("{} \"degrees\" is missing", rotate_where);
        const double degrees =
            finite_double(rotate.at("degrees"), rotate_where + " \"degrees\"", 1e6);
        const double length = glm::length(axis);
        if (!(length > 1e-12)) fail("{} \"axis\" must not be zero", rotate_where);
        rotation = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis / length));
    }
    map.linear = rotation * glm::dmat3(glm::dvec3(scale.x, 0, 0), glm::dvec3(0, scale.y, 0),
                                       glm::dvec3(0, 0, scale.z));
    map.offset = entry.contains("translate") ? dvec3_from(entry, "translate", where, kMaxMapNumber)
                                             : glm::dvec3(0.0);
}

// "matrix": three rows [a, b, c, t]: the linear part's row and the translation's component.
void matrix_map(const json& entry, const std::string& where, IfsMap& map) {
    const std::string what = where + " \"matrix\"";
    const json& rows = entry.at("matrix");
    const auto shape_error = [&] { fail("{} must be 3 rows of 4 numbers", what); };
    if (!rows.is_array() || rows.size() != 3) shape_error();
    for (int r = 0; r < 3; ++r) {
        const json& row = rows[static_cast<std::size_t>(r)];
        if (!row.is_array() || row.size() != 4) shape_error();
        for (int c = 0; c < 3; ++c) {
            map.linear[c][r] = finite_double(row[static_cast<std::size_t>(c)], what, kMaxMapNumber);
        }
        map.offset[r] = finite_double(row[3], what, kMaxMapNumber);
    }
}

IfsMap map_from(const json& entry, std::size_t index) {
    const std::string where = fmt::format("map {}", index);
    require_object(entry, where);
    check_keys(entry, {"matrix", "scale", "rotate", "translate", "colour"}, where);
    IfsMap map;
    if (entry.contains("matrix")) {
        if (entry.contains("scale") || entry.contains("rotate") || entry.contains("translate")) {
            fail("{}: \"matrix\" cannot be combined with \"scale\", \"rotate\" or \"translate\"",
                 where);
        }
        matrix_map(entry, where, map);
    } else {
        compose_map(entry, where, map);
    }
    if (entry.contains("colour")) map.colour = albedo_from(entry, where);
    return map;  // checked with the others by validate_ifs_maps
}

// Numbers a map may hold: finite and at most kMaxMapNumber in size.
bool map_numbers_ok(const IfsMap& map) {
    const auto ok = [](double value) { return std::abs(value) <= kMaxMapNumber; };  // false for NaN
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            if (!ok(map.linear[c][r])) return false;
        }
        if (!ok(map.offset[c])) return false;
    }
    return true;
}

// One map, wherever it came from: its numbers and colour, contractive and invertible. Sets its
// contraction factor.
void check_map(IfsMap& map, const std::string& where) {
    if (!map_numbers_ok(map)) {
        fail("{}: matrix numbers must be finite and at most {:g} in size", where, kMaxMapNumber);
    }
    for (int i = 0; i < 3; ++i) {
        if (!(map.colour[i] >= 0.0f && map.colour[i] <= 1.0f)) {
            fail("{}: colour components must be in [0, 1]", where);
        }
    }
    const glm::dvec3 sigma = singular_values(map.linear);
    if (!(sigma[0] < 1.0)) {
        fail("{} is not contractive (largest singular value {:.6g} >= 1)", where, sigma[0]);
    }
    if (!(sigma[2] > kSingularRatio * sigma[0])) {
        fail(
            "{} is singular (smallest singular value {:.3g}, largest {:.3g}): every map must be "
            "invertible",
            where, sigma[2], sigma[0]);
    }
    map.contraction = sigma[0];
}

void check_maps(IfsScene& scene, std::string_view map_word) {
    const std::size_t count = scene.maps.size();
    if (count < 1 || count > static_cast<std::size_t>(kIfsMaxMaps)) {
        fail("{} {}s; 1 to {} allowed", count, map_word, kIfsMaxMaps);
    }
    for (std::size_t i = 0; i < count; ++i) {
        check_map(scene.maps[i], fmt::format("{} {}", map_word, i));
    }
    for (const int depth : {scene.default_depth, scene.max_depth}) {
        if (depth < 0 || depth > kIfsMaxDepth)
            fail("depth {} outside [0, {}]", depth, kIfsMaxDepth);
    }
    if (scene.default_depth > scene.max_depth) {
        fail("default depth {} is above the maximum {}", scene.default_depth, scene.max_depth);
    }
    scene.bounds = ifs_bounding_sphere(scene.maps);
    const double extent = glm::length(scene.bounds.centre) + scene.bounds.radius;
    // One map, or maps that all fix the same point: the attractor is that point, nothing to draw
    // (and a ball of radius 0 to trace).
    if (!(scene.bounds.radius > 1e-9 * std::max(1.0, glm::length(scene.bounds.centre)))) {
        fail(
            "the attractor is a single point ({:.4g} {:.4g} {:.4g}): the {}s must not all fix "
            "the same point",
            scene.bounds.centre.x, scene.bounds.centre.y, scene.bounds.centre.z, map_word);
    }
    if (!(extent <= kMaxExtent)) {
        fail(
            "the attractor's bounding sphere (centre {:.4g} {:.4g} {:.4g}, radius {:.4g}) reaches "
            "beyond {:g} from the origin",
            scene.bounds.centre.x, scene.bounds.centre.y, scene.bounds.centre.z,
            scene.bounds.radius, kMaxExtent);
    }
}

// --- Depth ---------------------------------------------------------------------------------------

void depth_from(const json& document, IfsScene& scene) {
    set_ifs_depths(scene, std::nullopt, std::nullopt);
    if (!document.contains("depth")) return;
    const json& depth = document.at("depth");
    require_object(depth, "\"depth\"");
    check_keys(depth, {"default", "max"}, "\"depth\"");
    const auto read = [&](const char* key) {
        std::int64_t value = 0;
        if (!json_fields::integer_in(depth.at(key), 0, kIfsMaxDepth, value)) {
            fail("\"depth\" \"{}\" {} must be an integer in [0, {}]", key, shown(depth.at(key)),
                 kIfsMaxDepth);
        }
        return static_cast<int>(value);
    };
    std::optional<int> default_depth, max_depth;
    if (depth.contains("default")) default_depth = read("default");
    if (depth.contains("max")) max_depth = read("max");
    set_ifs_depths(scene, default_depth, max_depth);
    if (scene.default_depth > scene.max_depth) {
        fail("\"depth\" \"default\" {} is above \"max\" {}", scene.default_depth, scene.max_depth);
    }
}

// --- Leaf shape ----------------------------------------------------------------------------------

// The half-space n . x <= h through a, b, c whose inside holds `inside`.
glm::dvec4 plane_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                         const glm::dvec3& inside) {
    glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
    if (glm::dot(n, inside - a) > 0.0) n = -n;
    return {n, glm::dot(n, a)};
}

// "leaf": {"shape": "ball"} (the default), {"shape": "box", "min": [..], "max": [..]} or
// {"shape": "tetrahedron", "vertices": [4 points]}. A polytope must lie inside the bounding ball,
// which culls every node's subtree, leaf shapes included.
IfsLeaf leaf_from(const json& document, const IfsBounds& bounds) {
    IfsLeaf leaf;
    if (!document.contains("leaf")) return leaf;
    const json& entry = document.at("leaf");
    require_object(entry, "\"leaf\"");
    leaf.shape = text_from(entry, "shape", "\"leaf\"", true);
    std::vector<glm::dvec3> corners;
    if (leaf.shape == "ball") {
        check_keys(entry, {"shape"}, "\"leaf\"");
        return leaf;
    } else if (leaf.shape == "box") {
        check_keys(entry, {"shape", "min", "max"}, "\"leaf\"");
        const glm::dvec3 low = dvec3_from(entry, "min", "\"leaf\"", kMaxMapNumber);
        const glm::dvec3 high = dvec3_from(entry, "max", "\"leaf\"", kMaxMapNumber);
        for (int axis = 0; axis < 3; ++axis) {
            if (!(low[axis] < high[axis]))
                fail("\"leaf\" box: \"min\" must be below \"max\" on every axis");
            glm::dvec3 n(0.0);
            n[axis] = 1.0;
            leaf.planes.push_back({n, high[axis]});
            leaf.planes.push_back({-n, -low[axis]});
        }
        for (int corner = 0; corner < 8; ++corner) {
            corners.emplace_back(corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y,
                                 corner & 4 ? high.z : low.z);
        }
    } else if (leaf.shape == "tetrahedron") {
        check_keys(entry, {"shape", "vertices"}, "\"leaf\"");
        if (!entry.contains("vertices")) fail("\"leaf\" tetrahedron needs \"vertices\"");
        const json& vertices = array_from(entry, "vertices", 4, 4, "\"leaf\" \"vertices\"");
        for (std::size_t i = 0; i < 4; ++i) {
            corners.push_back(json_fields::dvec3_from(json{{"v", vertices[i]}}, "v",
                                                      fmt::format("\"leaf\" vertex {}", i),
                                                      kMaxMapNumber));
        }
        const double volume =
            std::abs(glm::dot(corners[1] - corners[0],
                              glm::cross(corners[2] - corners[0], corners[3] - corners[0]))) /
            6.0;
        const double size = glm::length(corners[1] - corners[0]);
        if (!(volume > 1e-9 * size * size * size)) fail("\"leaf\" tetrahedron is flat");
        for (int face = 0; face < 4; ++face) {
            leaf.planes.push_back(plane_through(corners[(face + 1) % 4], corners[(face + 2) % 4],
                                                corners[(face + 3) % 4], corners[face]));
        }
    } else {
        fail("\"leaf\" \"shape\" '{}' must be \"ball\", \"box\" or \"tetrahedron\"",
             printable_excerpt(leaf.shape));
    }
    for (const glm::dvec3& corner : corners) {
        if (glm::length(corner - bounds.centre) > bounds.radius * (1.0 + 1e-6)) {
            fail(
                "\"leaf\" {} corner ({:.4g} {:.4g} {:.4g}) lies outside the maps' bounding sphere "
                "(centre {:.4g} {:.4g} {:.4g}, radius {:.4g}), which must hold it",
                leaf.shape, corner.x, corner.y, corner.z, bounds.centre.x, bounds.centre.y,
                bounds.centre.z, bounds.radius);
        }
    }
    return leaf;
}

// --- Cameras, paths, lights ----------------------------------------------------------------------

// --- Defaults ------------------------------------------------------------------------------------

// Looks at the bounding sphere's centre from the front right, above, from where a sphere of the
// bounding radius is a little narrower than the view at 60 degrees: distance R / sin(30 degrees),
// plus a tenth.
NamedCamera default_camera(const IfsBounds& bounds) {
    const double fov_degrees = 60.0;
    const double radius = std::max(bounds.radius, 1e-6 * std::max(1.0, glm::length(bounds.centre)));
    const double distance = 1.1 * radius / std::sin(glm::radians(fov_degrees / 2.0));
    const glm::dvec3 direction = glm::normalize(glm::dvec3(1.0, -1.3, 0.75));
    NamedCamera camera;
    camera.name = "default";
    camera.view.position = bounds.centre + distance * direction;
    camera.view.target = bounds.centre;
    camera.view.up = glm::vec3(0.0f, 0.0f, 1.0f);
    camera.view.fov_degrees = static_cast<float>(fov_degrees);
    if (const std::string problem = view_problem(camera.view); !problem.empty()) {
        fail("cannot place a default camera for the attractor: {}", problem);
    }
    return camera;
}

// --- The document --------------------------------------------------------------------------------

IfsScene parse_ifs_document(const std::string& text) {
    if (text.size() > kIfsMaxFileBytes) {
        fail("{} bytes, more than the {} an IFS file may have", text.size(), kIfsMaxFileBytes);
    }
    const json document = scene_json::parse_object(text);
    check_keys(document,
               {"$schema", "format", "version", "id", "name", "description", "depth", "maps",
                "leaf", "cameras", "camera_paths", "lights", "environment"},
               "top level");
    json_fields::check_schema_key(document);
    IfsScene scene;
    scene_json::check_format(document, kIfsFormat, kIfsFormatVersion);
    scene.version = kIfsFormatVersion;
    const scene_json::Header header = scene_json::header_from(document);
    scene.id = header.id;
    scene.name = header.name;
    scene.description = header.description;
    depth_from(document, scene);
    if (!document.contains("maps")) fail("\"maps\" is missing");
    const json& maps =
        array_from(document, "maps", 1, static_cast<std::size_t>(kIfsMaxMaps), "\"maps\"");
    for (std::size_t i = 0; i < maps.size(); ++i) scene.maps.push_back(map_from(maps[i], i));
    check_maps(scene, "map");
    scene.leaf = leaf_from(document, scene.bounds);
    scene.cameras = scene_json::cameras_from(document);
    if (scene.cameras.empty()) scene.cameras.push_back(default_camera(scene.bounds));
    scene.camera_paths = scene_json::camera_paths_from(document);
    if (scene.camera_paths.empty())
        scene.camera_paths.push_back(scene_json::default_orbit(scene.cameras[0]));
    scene.lights = scene_json::lights_from(document);
    if (scene.lights.empty()) scene.lights.push_back(scene_json::default_light());
    scene.environment = scene_json::environment_from(document);
    settle_ifs_default_depth(scene);
    return scene;
}

// --- Bounding sphere -----------------------------------------------------------------------------

struct Contraction {
    glm::dmat3 linear;
    glm::dvec3 offset;
    double factor;  // s_i
};

// R(c) = max_i |w_i(c) - c| / (1 - s_i): the smallest radius of a ball about c that every map
// sends into itself, given only the maps' contraction factors.
double radius_about(const std::vector<Contraction>& maps, const glm::dvec3& centre) {
    double radius = 0.0;
    for (const Contraction& map : maps) {
        const glm::dvec3 image = map.linear * centre + map.offset;
        radius = std::max(radius, glm::length(image - centre) / (1.0 - map.factor));
    }
    return radius;
}

// Nelder-Mead downhill simplex (Nelder and Mead, 1965) on R(c). R is convex in c (a maximum of
// norms of affine functions), so a simplex search from a good start finds a centre near the best;
// it needs no derivatives, which R lacks where two maps tie for the maximum.
glm::dvec3 minimise_radius(const std::vector<Contraction>& maps, glm::dvec3 start, double size) {
    std::array<glm::dvec3, 4> points{start, start, start, start};
    std::array<double, 4> values{};
    for (int k = 0; k < 3; ++k) points[static_cast<std::size_t>(k + 1)][k] += size;
    for (std::size_t i = 0; i < 4; ++i) values[i] = radius_about(maps, points[i]);
    for (int iteration = 0; iteration < 2000; ++iteration) {
        std::array<std::size_t, 4> order{0, 1, 2, 3};
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
        const std::size_t best = order[0];
        const std::size_t worst = order[3];
        const std::size_t second_worst = order[2];
        if (values[worst] - values[best] <= 1e-15 * std::max(values[best], 1e-300)) break;
        glm::dvec3 centroid(0.0);
        for (std::size_t i = 0; i < 3; ++i) centroid += points[order[i]] / 3.0;
        const auto at = [&](double t) { return centroid + t * (points[worst] - centroid); };
        const glm::dvec3 reflected = at(-1.0);
        const double reflected_value = radius_about(maps, reflected);
        if (reflected_value < values[best]) {
            const glm::dvec3 expanded = at(-2.0);
            const double expanded_value = radius_about(maps, expanded);
            const bool expand = expanded_value < reflected_value;
            points[worst] = expand ? expanded : reflected;
            values[worst] = expand ? expanded_value : reflected_value;
        } else if (reflected_value < values[second_worst]) {
            points[worst] = reflected;
            values[worst] = reflected_value;
        } else {
            const bool outside = reflected_value < values[worst];
            const glm::dvec3 contracted = at(outside ? -0.5 : 0.5);
            const double contracted_value = radius_about(maps, contracted);
            if (contracted_value < std::min(values[worst], reflected_value)) {
                points[worst] = contracted;
                values[worst] = contracted_value;
            } else {  // shrink towards the best point
                for (std::size_t i = 0; i < 4; ++i) {
                    if (i == best) continue;
                    points[i] = points[best] + 0.5 * (points[i] - points[best]);
                    values[i] = radius_about(maps, points[i]);
                }
            }
        }
    }
    return points[static_cast<std::size_t>(std::min_element(values.begin(), values.end()) -
                                           values.begin())];
}

}  // namespace

void set_ifs_depths(IfsScene& scene, std::optional<int> default_depth,
                    std::optional<int> max_depth) {
    scene.max_depth = max_depth.value_or(kIfsMaxDepth);
    scene.default_depth = default_depth.value_or(scene.max_depth);
    scene.default_depth_from_cost = !default_depth.has_value();
}

void validate_ifs_maps(IfsScene& scene, std::string_view map_word) {
    try {
        check_maps(scene, map_word);
    } catch (const std::runtime_error& error) {
        throw IfsError(error.what());
    }
}

bool is_ifs_file_name(const std::filesystem::path& file) {
    const std::string name = file.filename().string();
    return name.size() > kIfsSuffix.size() &&
           name.compare(name.size() - kIfsSuffix.size(), kIfsSuffix.size(), kIfsSuffix) == 0;
}

IfsScene parse_ifs_json(const std::string& text, const std::string& origin) {
    try {
        return parse_ifs_document(text);
    } catch (const std::runtime_error& error) {
        throw IfsError(origin + ": " + error.what());
    } catch (const json::exception& error) {
        // Not expected (every value's type is checked before it is read); still one line.
        throw IfsError(origin + ": unexpected JSON content (" + std::string(error.what()) + ")");
    }
}

IfsScene read_ifs_file(const std::filesystem::path& file) {
    std::string text;
    try {
        text = scene_json::read_bounded(file, kIfsMaxFileBytes);
    } catch (const std::runtime_error& error) {
        throw IfsError(error.what());
    }
    return parse_ifs_json(text, printable_path(file));
}

// One-sided Jacobi (Hestenes 1958): plane rotations applied to the columns until they are
// mutually orthogonal; their lengths are then the singular values. It diagonalises M^T M without
// forming it, so small singular values keep their relative accuracy.
glm::dvec3 singular_values(const glm::dmat3& m) {
    std::array<glm::dvec3, 3> columns{m[0], m[1], m[2]};
    constexpr std::array<std::pair<int, int>, 3> kPairs{{{0, 1}, {0, 2}, {1, 2}}};
    for (int sweep = 0; sweep < 64; ++sweep) {
        bool rotated = false;
        for (const auto& [p, q] : kPairs) {
            glm::dvec3& a = columns[static_cast<std::size_t>(p)];
            glm::dvec3& b = columns[static_cast<std::size_t>(q)];
            const double alpha = glm::dot(a, a);
            const double beta = glm::dot(b, b);
            const double gamma = glm::dot(a, b);
            if (!(std::abs(gamma) > 1e-16 * std::sqrt(alpha * beta))) continue;
            rotated = true;
            const double zeta = (beta - alpha) / (2.0 * gamma);
            const double t = std::copysign(1.0, zeta) / (std::abs(zeta) + std::hypot(1.0, zeta));
            const double c = 1.0 / std::hypot(1.0, t);
            const double s = c * t;
            const glm::dvec3 old_a = a;
            a = c * old_a - s * b;
            b = s * old_a + c * b;
        }
        if (!rotated) break;
    }
    std::array<double, 3> values{glm::length(columns[0]), glm::length(columns[1]),
                                 glm::length(columns[2])};
    std::sort(values.begin(), values.end(), [](double x, double y) { return x > y; });
    return {values[0], values[1], values[2]};
}

double largest_singular_value(const glm::dmat3& m) { return singular_values(m)[0]; }

// Hart and DeFanti, "Efficient Antialiased Rendering of 3-D Linear Fractals" (SIGGRAPH 1991),
// section 4: a ball B(c, R) holds its images w_i(B) when |w_i(c) - c| + s_i R <= R for every map,
// s_i being w_i's contraction factor, so R(c) = max_i |w_i(c) - c| / (1 - s_i) bounds the
// attractor for any c. c starts at the centroid of the maps' fixed points (the attractor contains
// them) and a simplex search moves it to make R small.
IfsBounds ifs_bounding_sphere(const std::vector<IfsMap>& maps) {
    IfsBounds bounds;
    if (maps.empty()) return {glm::dvec3(0.0), 0.0};
    std::vector<Contraction> contractions;
    glm::dvec3 centroid(0.0);
    for (const IfsMap& map : maps) {
        const double factor = std::max(map.contraction, largest_singular_value(map.linear));
        if (!(factor < 1.0)) {
            return {glm::dvec3(0.0), std::numeric_limits<double>::infinity()};
        }
        contractions.push_back({map.linear, map.offset, factor});
        // w(x) = x at x = (I - L)^-1 t; I - L is invertible when |L| < 1.
        centroid += glm::inverse(glm::dmat3(1.0) - map.linear) * map.offset;
    }
    centroid /= static_cast<double>(maps.size());
    glm::dvec3 centre = centroid;
    double radius = radius_about(contractions, centre);
    // Restarts with a smaller simplex: Nelder-Mead can stall on a ridge of the max.
    for (double size = 0.25 * radius; size > 1e-6 * radius; size *= 0.1) {
        const glm::dvec3 better = minimise_radius(contractions, centre, size);
        const double better_radius = radius_about(contractions, better);
        if (better_radius < radius) {
            centre = better;
            radius = better_radius;
        }
    }
    bounds.centre = centre;
    // A relative 1e-9 more than the bound needs, so rounding in R's arithmetic cannot leave an
    // image of the ball poking out.
    bounds.radius = radius * (1.0 + 1e-9);
    return bounds;
}

}  // namespace fgr
