#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The JSON Schemas of fgr's file formats (schemas/*.schema.json) against what fgr reads and writes.

  check_schemas.py SOURCE_DIR BUILD_DIR            the test (ctest SchemaCheck)
  check_schemas.py SOURCE_DIR BUILD_DIR --update   rewrites formula.schema.json's formula library
                                                   from the built fgr's (after a formula changes)

It checks that
  1. every schema is a valid draft 2020-12 schema with its file name as "$id", a title and a
     description for every key, that $defs of one name are the same in every schema, and that the
     build tree has them in share/fgr/schemas;
  2. the limits and names the C++ readers enforce (fgr_schema_samples facts) are the schemas': the
     formula library (names, parameters and their ranges, bailout ceilings), effects, modes,
     projections, counts and ranges;
  3. every file fgr ships is valid: the formula and IFS scenes in plugins/, the examples in the
     docs, tests/schemas/examples/, and the headers of the text scenes fgr ships (the new-scene
     template, the docs' ```c blocks that are text scenes);
  4. every file fgr writes is valid: those fgr_schema_samples writes through fgr's writers (its
     "$schema" naming the build tree's copy of the schema), and a part's fgr.part header from
     `fgr render --part`, rendered along the written camera path;
  5. known-bad files fail their schema (a misspelt key, a missing key, a value out of range), and
     fgr refuses the bad scene files too; scene files with keys the valid files leave out pass
     their schema, and fgr takes them.
Needs python3-jsonschema (Debian 12: 4.10).
"""

import copy
import glob
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import urllib.parse
import urllib.request

try:
    import jsonschema
except ImportError:
    sys.exit("check_schemas.py needs jsonschema: apt-get install python3-jsonschema "
             "(./build.sh test installs it)")

DRAFT = "https://json-schema.org/draft/2020-12/schema"

# Each limit a reader enforces, where its schema says it: (schema, JSON pointer, the fact's name
# under "limits" in `fgr_schema_samples facts`).
LIMITS = [
    ("ifs.schema.json", "/properties/maps/maxItems", "ifs_maps"),
    ("ifs.schema.json", "/properties/depth/properties/default/maximum", "ifs_depth"),
    ("ifs.schema.json", "/properties/depth/properties/max/maximum", "ifs_depth"),
    ("formula.schema.json", "/properties/sequence/maxItems", "formula_slots"),
    ("formula.schema.json", "/$defs/slot/properties/repeat/maximum", "formula_repeat"),
    ("formula.schema.json", "/properties/iterations/maximum", "formula_iterations"),
    ("formula.schema.json", "/properties/bailout/maximum", "formula_bailout"),
    ("formula.schema.json", "/properties/step_factor/minimum", "formula_min_step_factor"),
    ("formula.schema.json", "/properties/step_factor/maximum", "formula_max_step_factor"),
    ("formula.schema.json", "/properties/max_distance/minimum", "formula_min_max_distance"),
    ("formula.schema.json", "/properties/max_distance/maximum", "formula_max_max_distance"),
    ("camera-path.schema.json", "/properties/keyframes/minItems", "min_keyframes"),
    ("view.schema.json", "/properties/image/properties/width/maximum", "image_side"),
    ("view.schema.json", "/properties/image/properties/height/maximum", "image_side"),
    ("view.schema.json", "/properties/render/properties/samples/maximum", "samples"),
    ("view.schema.json", "/properties/path/properties/bounces/maximum", "bounces"),
    ("view.schema.json", "/properties/path/properties/roulette_depth/maximum", "bounces"),
    ("view.schema.json", "/properties/scene/properties/id/maxLength", "id_length"),
    ("part-identity.schema.json", "/properties/width/maximum", "image_side"),
    ("part-identity.schema.json", "/properties/height/maximum", "image_side"),
    ("part-identity.schema.json", "/properties/samples/maximum", "samples"),
]
# The scene files' shared parts, checked in each schema that has them.
for _schema in ("ifs.schema.json", "formula.schema.json", "text-scene.schema.json"):
    LIMITS += [
        (_schema, "/$defs/scene_id/maxLength", "id_length"),
        (_schema, "/$defs/camera_name/maxLength", "id_length"),
        (_schema, "/$defs/text/maxLength", "text_length"),
        (_schema, "/$defs/cameras/maxItems", "cameras"),
        (_schema, "/$defs/camera_paths/maxItems", "camera_paths"),
        (_schema, "/$defs/camera_paths/items/properties/keyframes/minItems", "min_keyframes"),
        (_schema, "/$defs/camera_paths/items/properties/keyframes/maxItems", "keyframes"),
        (_schema, "/$defs/lights/maxItems", "lights"),
        (_schema, "/$defs/light/allOf/0/then/properties/angular_radius_degrees/maximum",
         "angular_radius_degrees"),
        (_schema, "/$defs/environment/maxLength", "id_length"),
    ]
# Names the readers take from a C++ table: (schema, JSON pointer to an enum, the fact's name).
NAMES = [
    ("view.schema.json", "/$defs/effect/enum", "effects"),
    ("view.schema.json", "/properties/render/properties/mode/enum", "render_modes"),
    ("view.schema.json", "/properties/camera/properties/projection/enum", "projections"),
    ("part-identity.schema.json", "/properties/identity/properties/mode/enum", "render_modes"),
    ("part-identity.schema.json", "/properties/tone_map/enum", "tone_maps"),
    ("text-scene.schema.json", "/properties/default_mode/enum", "render_modes"),
]
# Documents whose ```json blocks are checked when their "format" is one a schema has.
DOCS = ["README.md", "sdk/README.md", "docs/*.md", "docs/*/*.md"]
# Files fgr ships, each checked against the schema of its "format".
SHIPPED = ["plugins/formulas/*.formula.json", "plugins/ifs/*.ifs.json", "bench/deep_zoom.json",
           "tests/schemas/examples/*.json"]
# Text scenes fgr ships: `fgr new-scene --text`'s template, its placeholders filled as new-scene
# fills them for the id "my-scene".
TEXT_SCENES = ["sdk/template/text_scene.cl"]
TEMPLATE_VALUES = {"@SCENE_ID@": "my-scene", "@SCENE_NAME@": "My Scene"}
TEXT_SCENE_TAG = "fgr-scene"
# The scene a part is rendered of, small: one kernel compile.
PART_SCENE = "mandelbulb"


class Failures:
    def __init__(self):
        self.lines = []

    def add(self, line):
        self.lines.append(line)
        print("FAILED: " + line)


def pointer(document, path):
    """The value at a JSON pointer ("/a/b/0"), or KeyError."""
    value = document
    for token in path.split("/")[1:]:
        token = token.replace("~1", "/").replace("~0", "~")
        value = value[int(token)] if isinstance(value, list) else value[token]
    return value


def validator(schema):
    return jsonschema.Draft202012Validator(schema)


def errors(schema, document):
    return sorted(validator(schema).iter_errors(document), key=lambda e: list(e.path))


def error_text(error):
    where = "/".join(str(p) for p in error.absolute_path) or "top level"
    return f"{where}: {error.message[:200]}"


# --- 1. The schemas themselves --------------------------------------------------------------------

def undescribed_keys(schema, node, where):
    """Keys under "properties" without a "description" (here or in the $defs they refer to)."""
    found = []
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "if":  # conditions select a branch; they describe nothing
                continue
            if key == "properties" and isinstance(value, dict):
                for name, sub in value.items():
                    if sub is True:  # declared in the branch that describes it
                        continue
                    described = isinstance(sub, dict) and "description" in sub
                    if not described and isinstance(sub, dict) and "$ref" in sub:
                        described = "description" in pointer(schema, sub["$ref"][1:])
                    if not described:
                        found.append(f"{where}/properties/{name}")
            found += undescribed_keys(schema, value, f"{where}/{key}")
    elif isinstance(node, list):
        for i, value in enumerate(node):
            found += undescribed_keys(schema, value, f"{where}/{i}")
    return found


def check_schemas(schemas, build_dir, failures):
    for name, schema in schemas.items():
        try:
            jsonschema.Draft202012Validator.check_schema(schema)
        except jsonschema.SchemaError as error:
            failures.add(f"{name} is not a valid draft 2020-12 schema: {error.message}")
            continue
        if schema.get("$schema") != DRAFT:
            failures.add(f"{name}: \"$schema\" must be {DRAFT}")
        if schema.get("$id") != name:
            failures.add(f"{name}: \"$id\" must be its file name")
        for key in ("title", "description"):
            if not schema.get(key):
                failures.add(f"{name} has no {key}")
        for key in undescribed_keys(schema, schema, ""):
            failures.add(f"{name}: {key} has no description")
        # Files that name their schema must be allowed to.
        if schema.get("additionalProperties") is False and "format" in schema["properties"]:
            if "$schema" not in schema["properties"]:
                failures.add(f"{name} refuses \"$schema\"")
    # A $defs name means one thing in every schema.
    seen = {}
    for name, schema in sorted(schemas.items()):
        for key, value in schema.get("$defs", {}).items():
            if key in seen and seen[key][1] != value:
                failures.add(f"$defs/{key} differs between {seen[key][0]} and {name}")
            seen.setdefault(key, (name, value))
    # The build tree's copies, which the "$schema" fgr writes names.
    built_dir = os.path.join(build_dir, "share", "fgr", "schemas")
    built = sorted(os.path.basename(p) for p in glob.glob(os.path.join(built_dir, "*.schema.json")))
    if built != sorted(schemas):
        failures.add(f"{built_dir} holds {built}, not {sorted(schemas)}")
    for name in set(built) & set(schemas):
        with open(os.path.join(built_dir, name), encoding="utf-8") as f:
            if json.load(f) != schemas[name]:
                failures.add(f"{built_dir}/{name} is out of date (build again)")


# --- 2. The C++ tables ----------------------------------------------------------------------------

def float32(value):
    return struct.unpack("f", struct.pack("f", value))[0]


def shortest(value):
    """The shortest decimal that reads back as the same float (0.8, not 0.800000011920929)."""
    for digits in range(1, 10):
        text = "%.*g" % (digits, value)
        if float32(float(text)) == float32(value):
            number = float(text)
            return int(number) if number.is_integer() else number
    return value


def exact(value):
    """A bound as the reader compares it: the float's exact double, an int when it is one."""
    return int(value) if float(value).is_integer() else value


def parameter_schema(param):
    low, high = shortest(param["min"]), shortest(param["max"])
    if param["type"] == "vec3":
        default = [shortest(v) for v in param["default"]]
        number = {"type": "number", "minimum": exact(param["min"]),
                  "maximum": exact(param["max"])}
        return {"description": f"{param['label']}: {param['description']}; [x, y, z], each in "
                               f"[{low}, {high}] (default {default}).",
                "type": "array", "items": number, "minItems": 3, "maxItems": 3,
                "default": default}
    default = shortest(param["default"])
    return {"description": f"{param['label']}: {param['description']}; in [{low}, {high}] "
                           f"(default {default}).",
            "type": "number", "minimum": exact(param["min"]), "maximum": exact(param["max"]),
            "default": default}


def formula_defs(facts):
    """formula.schema.json's $defs that copy the formula library."""
    formulas = facts["formulas"]
    names = {
        "description": "A formula of fgr's library (`fgr list --formulas`).",
        "enum": [f["name"] for f in formulas],
        # Shown by editors that know it (VS Code); validators ignore it.
        "enumDescriptions": [f"{f['title']}: {f['summary']}" for f in formulas],
    }
    slots = []
    for formula in formulas:
        parameters = {p["id"]: parameter_schema(p) for p in formula["params"]}
        slots.append({
            "if": {"properties": {"formula": {"const": formula["name"]}}, "required": ["formula"]},
            "then": {"properties": {"parameters": {
                "description": f"{formula['title']}'s parameters"
                               + (": " + ", ".join(parameters) + "." if parameters
                                  else ": it has none."),
                "properties": parameters, "additionalProperties": False}}},
        })
    ceiling = facts["limits"]["formula_bailout"]
    by_bailout = {}
    for formula in formulas:
        if formula["max_bailout"] < ceiling:
            by_bailout.setdefault(exact(formula["max_bailout"]), []).append(formula["name"])
    caps = []
    for bailout, names_with_it in sorted(by_bailout.items()):
        caps.append({
            "if": {"properties": {"sequence": {"contains": {
                "properties": {"formula": {"enum": names_with_it}}, "required": ["formula"]}}},
                "required": ["sequence"]},
            "then": {"properties": {"bailout": {
                "description": f"At most {shortest(bailout)} with "
                               f"{', '.join(names_with_it)} in the sequence.",
                "maximum": bailout}}},
        })
    return {
        "formula": names,
        "slot_parameters": {"description": "Each formula's parameters and their ranges.",
                            "allOf": slots},
        "bailout_caps": {"description": "The largest bailout each formula takes without "
                                        "overflowing a float.", "allOf": caps},
    }


def check_facts(schemas, facts, failures):
    for schema, path, fact in LIMITS:
        try:
            value = pointer(schemas[schema], path)
        except (KeyError, IndexError, ValueError):
            failures.add(f"{schema} has no {path} (the limit {fact})")
            continue
        if value != exact(facts["limits"][fact]):
            failures.add(f"{schema}{path} is {value}; fgr's limit {fact} is "
                         f"{facts['limits'][fact]}")
    for schema, path, fact in NAMES:
        try:
            value = pointer(schemas[schema], path)
        except (KeyError, IndexError, ValueError):
            failures.add(f"{schema} has no {path} (the names {fact})")
            continue
        if sorted(value) != sorted(facts[fact]):
            failures.add(f"{schema}{path} is {value}; fgr's {fact} are {facts[fact]}")
    defs = schemas["formula.schema.json"]["$defs"]
    for key, value in formula_defs(facts).items():
        if defs.get(key) != value:
            failures.add(f"formula.schema.json $defs/{key} is not the formula library's: run "
                         f"tests/schemas/check_schemas.py SOURCE_DIR BUILD_DIR --update")


# --- 3. and 4. Valid files ------------------------------------------------------------------------

def schema_of_format(schemas):
    by_format = {}
    for name, schema in schemas.items():
        const = schema.get("properties", {}).get("format", {}).get("const")
        if const:
            by_format[const] = name
    return by_format


def json_blocks(markdown):
    return re.findall(r"^```json\n(.*?)^```", markdown, flags=re.M | re.S)


def text_scene_header(text):
    """The JSON header of a text scene's source, parsed; None when it has none."""
    match = re.match(r"\s*/\*\s*" + TEXT_SCENE_TAG + r"\s(.*?)\*/", text, flags=re.S)
    return json.loads(match.group(1)) if match else None


def read_text_scene(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    for placeholder, value in TEMPLATE_VALUES.items():
        text = text.replace(placeholder, value)
    return text


def text_scene_file(header):
    """A text scene with `header` and a ball for its source, as a file's text."""
    return ("/* " + TEXT_SCENE_TAG + "\n" + json.dumps(header, indent=1) + "\n*/\n"
            "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }\n")


def check_valid(schemas, name, document, what, failures):
    found = errors(schemas[name], document)
    for error in found:
        failures.add(f"{what} fails {name}: {error_text(error)}")
    return not found


def check_shipped(source_dir, schemas, failures):
    by_format = schema_of_format(schemas)
    checked = 0
    for pattern in SHIPPED:
        for path in sorted(glob.glob(os.path.join(source_dir, pattern))):
            with open(path, encoding="utf-8") as f:
                document = json.load(f)
            name = by_format.get(document.get("format"))
            if name is None:
                failures.add(f"{path}: no schema for its format {document.get('format')!r}")
                continue
            check_valid(schemas, name, document, path, failures)
            checked += 1
    for pattern in DOCS:
        for path in sorted(glob.glob(os.path.join(source_dir, pattern))):
            with open(path, encoding="utf-8") as f:
                blocks = json_blocks(f.read())
            for i, block in enumerate(blocks):
                try:
                    document = json.loads(block)
                except json.JSONDecodeError:
                    continue  # an excerpt, not a file
                name = by_format.get(document.get("format")) if isinstance(document, dict) else None
                if name:
                    check_valid(schemas, name, document, f"{path} json block {i + 1}", failures)
                    checked += 1
            # Text scenes among the code examples: their headers.
            with open(path, encoding="utf-8") as f:
                code_blocks = re.findall(r"^```c\n(.*?)^```", f.read(), flags=re.M | re.S)
            for i, block in enumerate(code_blocks):
                header = text_scene_header(block)
                if header is not None:
                    check_valid(schemas, "text-scene.schema.json", header,
                                f"{path} text scene in c block {i + 1}", failures)
                    checked += 1
    for pattern in TEXT_SCENES:
        for path in sorted(glob.glob(os.path.join(source_dir, pattern))):
            header = text_scene_header(read_text_scene(path))
            if header is None:
                failures.add(f"{path} has no text scene header")
                continue
            check_valid(schemas, "text-scene.schema.json", header, path, failures)
            checked += 1
    print(f"{checked} shipped files and examples checked")
    if checked < 40:
        failures.add(f"only {checked} shipped files found: are the globs right?")


def exr_string_attribute(path, wanted):
    """A string attribute of an OpenEXR file's (single-part) header."""
    with open(path, "rb") as f:
        data = f.read(1 << 20)
    if data[:4] != b"\x76\x2f\x31\x01":
        raise ValueError(f"{path} is not an OpenEXR file")
    at = 8
    while data[at] != 0:
        end = data.index(b"\0", at)
        name = data[at:end].decode()
        type_end = data.index(b"\0", end + 1)
        kind = data[end + 1:type_end].decode()
        (size,) = struct.unpack("<i", data[type_end + 1:type_end + 5])
        value = data[type_end + 5:type_end + 5 + size]
        if name == wanted and kind == "string":
            return value.decode("utf-8")
        at = type_end + 5 + size
    raise KeyError(f"{path} has no string attribute {wanted}")


def run(command, environment, what):
    result = subprocess.run(command, env=environment, capture_output=True, text=True, timeout=300)
    if result.returncode != 0:
        raise RuntimeError(f"{what} failed ({result.returncode}): {result.stderr.strip()[-2000:]}")
    return result


def check_written(build_dir, schemas, work, environment, written, failures):
    """The files fgr's writers write, kept in `written` by schema name for the bad cases."""
    written_dir = os.path.join(work, "written")
    os.makedirs(written_dir)
    run([os.path.join(build_dir, "bin", "fgr_schema_samples"), "write", written_dir], environment,
        "fgr_schema_samples write")
    schema_dir = os.path.realpath(os.path.join(build_dir, "share", "fgr", "schemas"))
    for path in sorted(glob.glob(os.path.join(written_dir, "*.json"))):
        name = os.path.basename(path)[:-len(".json")] + ".schema.json"
        if name not in schemas:
            failures.add(f"fgr_schema_samples wrote {path}, which has no schema {name}")
            continue
        with open(path, encoding="utf-8") as f:
            document = json.load(f)
        check_valid(schemas, name, document, f"written {os.path.basename(path)}", failures)
        # "$schema" finds the schema: the build tree's copy, as a file:// URI.
        reference = document.get("$schema", "")
        parsed = urllib.parse.urlparse(reference)
        local = urllib.request.url2pathname(parsed.path)
        if parsed.scheme != "file" or local != os.path.join(schema_dir, name):
            failures.add(f"written {os.path.basename(path)}: \"$schema\" {reference!r} is not "
                         f"the file:// URI of {os.path.join(schema_dir, name)}")
        written[name] = document
    print(f"{len(written)} written files checked: {', '.join(sorted(written))}")
    if "camera-path.schema.json" not in written:
        failures.add("fgr_schema_samples wrote no camera path")
        return
    # A part, rendered along the written camera path (which fgr must read back, "$schema" and all).
    part = os.path.join(work, "part.exr")
    run([os.path.join(build_dir, "bin", "fgr"), "render", PART_SCENE, "--part", "-o", part,
         "--width", "32", "--height", "24", "--camera-path",
         os.path.join(written_dir, "camera-path.json"), "--time", "0.5"],
        environment, "fgr render --part")
    header = json.loads(exr_string_attribute(part, "fgr.part"))
    check_valid(schemas, "part-identity.schema.json", header, "the written part's fgr.part",
                failures)
    written["part-identity.schema.json"] = header


# --- 5. Known-bad files ---------------------------------------------------------------------------

def parent_of(document, path):
    parent_path, _, last = path.rpartition("/")
    parent = pointer(document, parent_path) if parent_path else document
    return parent, (int(last) if isinstance(parent, list) else last)


def renamed(path, new_key):
    """The key at `path` misspelt as `new_key`."""
    def change(document):
        parent, key = parent_of(document, path)
        parent[new_key] = parent.pop(key)
    return change


def setting(path, value):
    def change(document):
        parent, key = parent_of(document, path)
        parent[key] = value
    return change


def removing(path):
    def change(document):
        parent, key = parent_of(document, path)
        del parent[key]
    return change


# Common mistakes, each a change to a valid file of the schema (what fgr writes, else what it
# ships) that the schema must refuse, as fgr's reader does. The scene files' are also given to fgr,
# which must refuse each.
BAD = {
    "camera-path.schema.json": [
        ("a misspelt key", renamed("/keyframes", "keyframe")),
        ("a misspelt keyframe key", renamed("/keyframes/1/fov", "fvo")),
        ("a keyframe without its target", removing("/keyframes/0/target")),
        ("an fov of 180", setting("/keyframes/1/fov", 180)),
        ("one keyframe", removing("/keyframes/1")),
        ("version 2", setting("/version", 2)),
        ("a \"$schema\" that is not a string", setting("/$schema", 3)),
    ],
    "ifs.schema.json": [
        ("a misspelt key", renamed("/maps", "map")),
        ("a misspelt map key", renamed("/maps/0/translate", "translat")),
        ("no id", removing("/id")),
        ("an id with capitals", setting("/id", "Sierpinski")),
        ("a colour above 1", setting("/maps/0/colour", [1.5, 0, 0])),
        ("a depth above 24", setting("/depth", {"default": 6, "max": 25})),
        ("no maps", setting("/maps", [])),
        ("a matrix with a scale",
         setting("/maps/0/matrix", [[0.5, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, 0.5, 0]])),
        ("a box leaf without max", setting("/leaf", {"shape": "box", "min": [-1, -1, -1]})),
        ("a spot light", setting("/lights", [{"type": "spot", "position": [0, 0, 1]}])),
        ("a camera name with a space", setting("/cameras/0/name", "front view")),
        ("an environment map file", setting("/environment", "studio.hdr")),
    ],
    "formula.schema.json": [
        ("a misspelt key", renamed("/iterations", "iteration")),
        ("an unknown formula", setting("/sequence/0/formula", "mandelbub")),
        ("a power of 17", setting("/sequence/0/parameters/power", 17)),
        ("a misspelt parameter", renamed("/sequence/0/parameters/power", "pwer")),
        ("a vector of two", setting("/sequence/1/parameters/axis", [0.3, 0.4])),
        ("no sequence", removing("/sequence")),
        ("a repeat of 65", setting("/sequence/0/repeat", 65)),
        ("a step factor of 0.01", setting("/step_factor", 0.01)),
        ("a bailout of 100 with a Mandelbulb", setting("/bailout", 100)),
        ("an unknown distance", setting("/distance", "exponential")),
        ("a tag with capitals", setting("/tags", ["Hybrid"])),
        ("a negative uniform environment", setting("/environment", "uniform:-1")),
    ],
    "part-identity.schema.json": [
        ("no identity", removing("/identity")),
        ("an identity without its kernel", removing("/identity/kernel")),
        ("tone map 7", setting("/tone_map", 7)),
        ("a region of three numbers", setting("/region", [0, 0, 32])),
        ("a width of 0", setting("/width", 0)),
        ("samples of 4097", setting("/samples", 4097)),
    ],
    "view.schema.json": [
        ("a misspelt key", renamed("/camera", "camrea")),
        ("a misspelt render key", renamed("/render/samples", "sample")),
        ("a scene id with capitals", setting("/scene/id", "Mandelbulb")),
        ("an fov of 180", setting("/camera/fov", 180)),
        ("a bit depth of 12", setting("/image/bit_depth", 12)),
        ("a misspelt layer", setting("/image/layers", "albedo,nromal")),
        ("no samples", setting("/render/samples", 0)),
        ("an unknown projection", setting("/camera/projection", "orthographic")),
        ("2000 bounces", setting("/path/bounces", 2000)),
        ("an unknown effect", setting("/render/effects", ["shadow"])),
        ("a colour of two numbers", setting("/parameters/colour", [1, 0.5])),
    ],
    "text-scene.schema.json": [
        ("a misspelt key", renamed("/parameters", "parameter")),
        ("a parameter without its id", removing("/parameters/0/id")),
        ("an unknown parameter type", setting("/parameters/3/type", "color")),
        ("an id with capitals", setting("/id", "My-Scene")),
        ("an unknown effect", setting("/effects", ["shadow"])),
        ("an unknown render mode", setting("/default_mode", "fast")),
        ("a misspelt march key", renamed("/march/max_steps", "max_step")),
        ("a step factor of 0", setting("/march/step_factor", 0)),
        ("a spot light", setting("/lights", [{"type": "spot", "position": [0, 0, 1]}])),
        ("a camera name with a space", setting("/cameras/0/name", "front view")),
        ("an unknown colour mode", setting("/colour_modes", ["rainbow"])),
        ("a scale of 0", setting("/scale", 0)),
        ("an environment map file", setting("/environment", "studio.hdr")),
    ],
}
# Keys that the bases leave out, each a change to the same valid file that the schema and fgr must
# both take (a new id for each, so that none is skipped as a duplicate).
GOOD = {
    "ifs.schema.json": [
        ("an environment of its own", setting("/environment", "studio")),
    ],
    "formula.schema.json": [
        ("a uniform environment", setting("/environment", "uniform:0.5")),
    ],
    "text-scene.schema.json": [
        ("an environment of its own", setting("/environment", "uniform:0.5,0.5,0.6")),
    ],
}
# The valid file each format's bad cases break, where it is not the one fgr_schema_samples writes:
# one with every key the cases change.
BAD_BASES = {
    "ifs.schema.json": "plugins/ifs/sierpinski.ifs.json",
    "view.schema.json": "tests/schemas/examples/mandelbulb.fgrview.json",
    "text-scene.schema.json": "sdk/template/text_scene.cl",  # its header
}
# Scene files fgr finds in a plugin folder by their names' endings.
SCENE_SUFFIXES = {"ifs.schema.json": ".ifs.json", "formula.schema.json": ".formula.json",
                  "text-scene.schema.json": ".cl"}


def write_scene_file(path, name, document):
    with open(path, "w", encoding="utf-8") as f:
        if name == "text-scene.schema.json":
            f.write(text_scene_file(document))
        else:
            json.dump(document, f)


def check_good(name, base, schemas, accepted_dir, scene_files, failures):
    """GOOD's cases of `name`: each valid, and written to `accepted_dir` for fgr to take."""
    for i, (what, change) in enumerate(GOOD.get(name, [])):
        document = copy.deepcopy(base)
        change(document)
        document["id"] = f"accepted-{len(scene_files)}"
        check_valid(schemas, name, document, f"{name}, {what}", failures)
        path = os.path.join(accepted_dir, f"good-{i}{SCENE_SUFFIXES[name]}")
        write_scene_file(path, name, document)
        scene_files.append((path, what, document["id"]))


def check_bad(source_dir, build_dir, schemas, written, work, environment, failures):
    refused_dir = os.path.join(work, "refused")
    accepted_dir = os.path.join(work, "accepted")
    os.makedirs(refused_dir)
    os.makedirs(accepted_dir)
    scene_files = []
    accepted_files = []
    cases = 0
    for name in sorted(schemas):
        if name not in BAD:
            failures.add(f"{name} has no known-bad cases (BAD in {os.path.basename(__file__)})")
            continue
        base = written.get(name)
        if name in BAD_BASES and BAD_BASES[name].endswith(".cl"):
            base = text_scene_header(read_text_scene(os.path.join(source_dir, BAD_BASES[name])))
        elif name in BAD_BASES:
            with open(os.path.join(source_dir, BAD_BASES[name]), encoding="utf-8") as f:
                base = json.load(f)
        if base is None:
            failures.add(f"no valid {name} file to break")
            continue
        if errors(schemas[name], base):
            failures.add(f"the file broken for {name}'s bad cases is not valid itself")
            continue
        check_good(name, base, schemas, accepted_dir, accepted_files, failures)
        for i, (what, change) in enumerate(BAD[name]):
            document = copy.deepcopy(base)
            try:
                change(document)
            except (KeyError, IndexError) as error:
                failures.add(f"{name}, {what}: the change does not apply ({error!r})")
                continue
            cases += 1
            if not errors(schemas[name], document):
                failures.add(f"{name} accepts {what}")
            if name in SCENE_SUFFIXES:
                path = os.path.join(refused_dir, f"bad-{i}{SCENE_SUFFIXES[name]}")
                write_scene_file(path, name, document)
                scene_files.append((path, what))
    print(f"{cases} known-bad files and {len(accepted_files)} good ones checked")
    # fgr refuses the bad scene files too: `fgr list` skips each with a warning naming it; and
    # takes the good ones.
    result = run([os.path.join(build_dir, "bin", "fgr"), "list"],
                 dict(environment, FGR_PLUGIN_PATH=os.pathsep.join([refused_dir, accepted_dir])),
                 "fgr list")
    for path, what in scene_files:
        if f"skipping plugin {path}:" not in result.stderr + result.stdout:
            failures.add(f"fgr does not refuse {os.path.basename(path)} ({what})")
    for path, what, scene_id in accepted_files:
        if (f"skipping plugin {path}:" in result.stderr + result.stdout or
                not re.search(rf"\b{scene_id}\b", result.stdout)):
            failures.add(f"fgr does not take {os.path.basename(path)} ({what})")


# --- The test -------------------------------------------------------------------------------------

def load_schemas(source_dir):
    schemas = {}
    for path in sorted(glob.glob(os.path.join(source_dir, "schemas", "*.schema.json"))):
        with open(path, encoding="utf-8") as f:
            schemas[os.path.basename(path)] = json.load(f)
    return schemas


def facts_of(build_dir, environment):
    result = run([os.path.join(build_dir, "bin", "fgr_schema_samples"), "facts"], environment,
                 "fgr_schema_samples facts")
    return json.loads(result.stdout)


def update(source_dir, build_dir):
    path = os.path.join(source_dir, "schemas", "formula.schema.json")
    with open(path, encoding="utf-8") as f:
        schema = json.load(f)
    schema["$defs"].update(formula_defs(facts_of(build_dir, dict(os.environ))))
    with open(path, "w", encoding="utf-8") as f:
        f.write(json.dumps(schema, indent=2, ensure_ascii=False) + "\n")
    print(f"wrote {path}")


def main(argv):
    if len(argv) == 4 and argv[3] == "--update":
        update(argv[1], argv[2])
        return 0
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    source_dir, build_dir = (os.path.realpath(a) for a in argv[1:3])
    failures = Failures()
    schemas = load_schemas(source_dir)
    print(f"schemas: {', '.join(schemas)}")
    with tempfile.TemporaryDirectory(prefix="fgr_schema_check_") as work:
        # Hermetic: a kernel cache, plugin folder and home of the test's own (the drivers' caches
        # come from ctest's environment).
        environment = dict(os.environ, FGR_CACHE_DIR=os.path.join(work, "cache"),
                           HOME=os.path.join(work, "home"))
        environment.pop("FGR_PLUGIN_PATH", None)
        check_schemas(schemas, build_dir, failures)
        check_shipped(source_dir, schemas, failures)
        written = {}
        try:
            check_facts(schemas, facts_of(build_dir, environment), failures)
            check_written(build_dir, schemas, work, environment, written, failures)
        except RuntimeError as error:  # a program that failed: what it said
            failures.add(str(error))
        try:
            check_bad(source_dir, build_dir, schemas, written, work, environment, failures)
        except RuntimeError as error:
            failures.add(str(error))
    if failures.lines:
        print(f"{len(failures.lines)} problem(s)")
        return 1
    print("every schema agrees with fgr")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
