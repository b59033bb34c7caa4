// SPDX-License-Identifier: Apache-2.0
// What tests/schemas/check_schemas.py checks the schemas (schemas/*.schema.json) against, from the
// C++ side:
//
//   fgr_schema_samples write DIR   writes one file of each JSON format fgr writes, through fgr's
//                                  own writer, as DIR/<format>.json, <format> naming its schema
//                                  schemas/<format>.schema.json
//   fgr_schema_samples facts       prints the tables and limits the readers enforce (the formula
//                                  library, effects, modes, projections, counts and ranges) as
//                                  JSON, so the script can tell when a schema has fallen behind
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "camera/camera_path_file.hpp"
#include "camera/projection.hpp"
#include "image/display.hpp"
#include "render/path_settings.hpp"
#include "render/renderer.hpp"
#include "render/sample_budget.hpp"
#include "scene/effects.hpp"
#include "scene/formulas/formula_edit.hpp"
#include "scene/formulas/formulas.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene_limits.hpp"
#include "util/atomic_file.hpp"
#include "view_file/view_file.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

CameraPathFile sample_camera_path() {
    CameraPathFile file;
    file.scene = "mandelbulb";
    file.path.name = "recorded";
    file.path.keyframes = {{0.0f, {{2.0, -2.2, 1.2}, {0.0, 0.0, 0.0}, {0, 0, 1}, 60.0f}},
                           {1.0f, {{1.6, -2.6, 1.0}, {0.0, 0.0, 0.1}, {0, 0, 1}, 50.0f}}};
    return file;
}

// A hybrid with a vector parameter, a rotation, its own cameras, a path, a light and an
// environment.
FormulaScene sample_formula_scene() {
    return parse_formula_json(R"({
        "format": "fgr-formula", "version": 1, "id": "sample-hybrid", "name": "Sample hybrid",
        "tags": ["hybrid"],
        "sequence": [{"formula": "mandelbulb", "repeat": 2, "parameters": {"power": 7}},
                     {"formula": "amazing_box", "parameters": {"axis": [0.3, 0.4, 1]}}],
        "cameras": [{"name": "front", "position": [2, -2.2, 1.2], "target": [0, 0, 0]}],
        "environment": "uniform:0.5,0.5,0.6"})",
                              "sample");
}

// One line per format fgr writes: the schema's name without ".schema.json", and fgr's writer
// writing a typical file of it.
struct Sample {
    const char* schema;
    std::function<void(const fs::path&)> write;
};
// A view with every key written: the path tracer's and a stereo projection's too.
ViewFile sample_view() {
    ViewFile view;
    view.scene_id = "mandelbulb";
    view.scene_fingerprint = "0123456789abcdef";
    view.scene_file = "/tmp/mandelbulb.cl";
    view.fgr_version = "0.1.0";
    view.camera.position = {2.0, -2.0, 1.0};
    view.projection.kind = ProjectionKind::StereoTopBottom;
    view.projection.eye_separation = 0.1;
    view.projection.convergence = 3.0;
    view.parameters = {{"colour_mode", ViewParameter::Kind::Choice, "iterations"},
                       {"power", ViewParameter::Kind::Number, "7.5"},
                       {"shadows_on", ViewParameter::Kind::Bool, "true"},
                       {"tint", ViewParameter::Kind::Vector, "0.5,0.25,1"}};
    view.mode = RenderMode::Path;
    view.effects = {"shadows", "fog"};
    ViewPathChoices path;
    path.turbidity = 3.0f;
    path.sun_elevation = 35.0f;
    path.sun_azimuth = 10.0f;
    view.path = path;
    return view;
}

const Sample kSamples[] = {
    {"view", [](const fs::path& file) { write_view_file(file, sample_view()); }},
    {"camera-path",
     [](const fs::path& file) { write_camera_path_file(file, sample_camera_path()); }},
    {"formula",
     [](const fs::path& file) {
         write_text_file_atomically(file, formula_scene_json(sample_formula_scene()));
     }},
};

json formula_facts() {
    json formulas = json::array();
    for (const Formula& formula : formula_library()) {
        json params = json::array();
        for (const FormulaParam& param : formula.params) {
            const bool vector = param.type == ParamType::Vec3;
            params.push_back(
                {{"id", param.id},
                 {"label", param.label},
                 {"description", param.description},
                 {"type", vector ? "vec3" : "float"},
                 // As the reader compares: the float bounds, exactly, as doubles.
                 {"min", static_cast<double>(param.min_value)},
                 {"max", static_cast<double>(param.max_value)},
                 {"default", vector ? json::array({param.default_value[0], param.default_value[1],
                                                   param.default_value[2]})
                                    : json(param.default_value[0])}});
        }
        formulas.push_back({{"name", formula.name},
                            {"title", formula.title},
                            {"summary", formula.summary},
                            {"max_bailout", static_cast<double>(formula.max_bailout)},
                            {"params", params}});
    }
    return formulas;
}

json facts() {
    json effects = json::array();
    for (const EffectSwitch& effect : effect_switches()) effects.push_back(effect.name);
    json modes = json::array();
    for (const RenderModeInfo& mode : render_modes()) modes.push_back(std::string(mode.name));
    json projections = json::array();
    for (const ProjectionKind kind :
         {ProjectionKind::Pinhole, ProjectionKind::Equirectangular, ProjectionKind::Fisheye,
          ProjectionKind::StereoSideBySide, ProjectionKind::StereoTopBottom}) {
        projections.push_back(projection_name(kind));
    }
    json tone_maps = json::array();
    for (const ToneMap tone_map : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        tone_maps.push_back(static_cast<int>(tone_map));
    }
    namespace limits = scene_limits;
    return {
        {"formulas", formula_facts()},
        {"effects", effects},
        {"render_modes", modes},
        {"projections", projections},
        {"tone_maps", tone_maps},
        {"limits",
         {{"id_length", limits::kMaxIdLength},
          {"text_length", limits::kMaxTextLength},
          {"cameras", limits::kMaxCameras},
          {"camera_paths", limits::kMaxCameraPaths},
          {"min_keyframes", limits::kMinKeyframes},
          {"keyframes", limits::kMaxKeyframes},
          {"lights", limits::kMaxLights},
          {"angular_radius_degrees", static_cast<double>(limits::kMaxAngularRadiusDegrees)},
          {"ifs_maps", kIfsMaxMaps},
          {"ifs_depth", kIfsMaxDepth},
          {"formula_slots", kFormulaMaxSlots},
          {"formula_repeat", kFormulaMaxRepeat},
          {"formula_iterations", kFormulaMaxIterations},
          {"formula_bailout", static_cast<double>(kFormulaMaxBailout)},
          {"formula_min_step_factor", kFormulaMinStepFactor},
          {"formula_max_step_factor", kFormulaMaxStepFactor},
          {"formula_min_max_distance", kFormulaMinMaxDistance},
          {"formula_max_max_distance", kFormulaMaxMaxDistance},
          {"bounces", kMaxBounces},
          {"image_side", kMaxTiledImageSide},
          {"samples", kMaxSamples}}},
    };
}

int run(int argc, char** argv) {
    const std::string_view command = argc > 1 ? argv[1] : "";
    if (command == "facts" && argc == 2) {
        fmt::print("{}\n", facts().dump(2));
        return 0;
    }
    if (command == "write" && argc == 3) {
        const fs::path directory = argv[2];
        for (const Sample& sample : kSamples) {
            sample.write(directory / (std::string(sample.schema) + ".json"));
        }
        return 0;
    }
    std::fputs("usage: fgr_schema_samples write DIR | facts\n", stderr);
    return 2;
}

}  // namespace
}  // namespace fgr

int main(int argc, char** argv) {
    try {
        return fgr::run(argc, argv);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "fgr_schema_samples: %s\n", error.what());
        return 1;
    }
}
