#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""fgr's formula library against Mandelbulber 2: the hit silhouettes and the times.

    bench/compare_formulas_mandelbulber.py [--size WxH] [--rounds N] [--fixtures] [ID ...]

For every case in bench/mandelbulber_formulas.json (or the IDs given) it renders the formula in
Mandelbulber 2 (`--nogui --format png16alpha`: alpha 0 where a ray reached the background) and
in fgr (`--alpha`, no effects) with the same camera, parameters, iterations and bailout, and
prints a Markdown table: the intersection over union of the two silhouettes and each tool's best
whole-process time of --rounds runs (start-up, render and PNG), alternating the tools. Pictures of
the disagreement (white both, red Mandelbulber only, cyan fgr only) land in
bench/results/mandelbulber/ID_diff.png, all of them at half size in silhouettes.png.

--fixtures also writes Mandelbulber's silhouettes at 320x240 into tests/fixtures/mandelbulber/
(ID.png), which tests/scene/test_mandelbulber.cpp compares fgr's renders with in CI (no Mandelbulber
needed there). Needs mandelbulber2 (Debian's package; installed if missing when run as root) and
a built fgr (build/bin/fgr)."""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import silhouette_iou  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FGR = os.path.join(REPO, "build", "bin", "fgr")
CASES = os.path.join(REPO, "bench", "mandelbulber_formulas.json")
RESULTS = os.path.join(REPO, "bench", "results", "mandelbulber")
FIXTURES = os.path.join(REPO, "tests", "fixtures", "mandelbulber")
FIXTURE_SIZE = (320, 240)
# Mandelbulber's fov 1: tan(vertical / 2) = 0.5.
TAN_HALF_VERTICAL = 0.5


def fail(message):
    raise SystemExit(f"compare_formulas_mandelbulber: {message}")


def normalised(v):
    length = math.sqrt(sum(x * x for x in v))
    return [x / length for x in v]


def mandelbulber_camera(eye, target, up):
    """camera_rotation (yaw from +y, pitch, roll) and camera_top for a camera looking at target."""
    direction = normalised([t - e for t, e in zip(target, eye)])
    yaw = math.degrees(math.atan2(-direction[0], direction[1]))
    pitch = math.degrees(math.asin(direction[2]))
    along = sum(u * d for u, d in zip(up, direction))
    top = normalised([u - along * d for u, d in zip(up, direction)])
    return yaw, pitch, top


def view_distance(case):
    """How far rays go in both tools: ten times the camera's distance from its target."""
    return 10 * math.dist(case["eye"], case.get("target", [0, 0, 0]))


def fract_text(case, width, height):
    eye, target, up = case["eye"], case.get("target", [0, 0, 0]), case.get("up", [0, 0, 1])
    yaw, pitch, top = mandelbulber_camera(eye, target, up)
    distance = math.dist(eye, target)
    lines = ["# Mandelbulber settings file", "# version 2.20", "# only modified parameters",
             "[main_parameters]",
             f"camera {eye[0]} {eye[1]} {eye[2]};",
             f"target {target[0]} {target[1]} {target[2]};",
             f"camera_distance_to_target {distance};",
             f"camera_rotation {yaw} {pitch} 0;",
             f"camera_top {top[0]} {top[1]} {top[2]};",
             "fov 1;", f"image_width {width};", f"image_height {height};",
             f"formula_1 {case['mandelbulber_formula']};",
             "use_default_bailout false;", "DE_thresh 1;", "detail_level 1;",
             "ambient_occlusion_enabled false;", "shadows_enabled false;", "glow_enabled false;",
             "basic_fog_enabled false;", "raytraced_reflections false;",
             f"view_distance_max {view_distance(case)};"]
    lines += [f"{line};" for line in case["mandelbulber_main"]]
    lines += ["[fractal_1]"] + [f"{line};" for line in case["mandelbulber_fractal"]]
    return "\n".join(lines) + "\n"


def run_mandelbulber(case, width, height, output, tmp):
    fract = os.path.join(tmp, case["id"] + ".fract")
    with open(fract, "w") as f:
        f.write(fract_text(case, width, height))
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    start = time.monotonic()
    result = subprocess.run(["mandelbulber2", "--nogui", "--format", "png16alpha", "--res",
                             f"{width}x{height}", "-o", output, fract],
                            capture_output=True, text=True, env=env)
    wall_ms = (time.monotonic() - start) * 1000
    if result.returncode != 0 or not os.path.exists(output):
        fail(f"mandelbulber2 failed on {case['id']}:\n{result.stdout}{result.stderr}")
    return wall_ms


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def corner_aligned_target(eye, target, up, width, height):
    """The target that turns fgr's camera half a pixel left and up. Mandelbulber traces a ray
    through each pixel's top-left corner (x / width - 0.5), fgr through its centre; a straight
    edge across the image would otherwise differ by a pixel in half its pixels."""
    direction = [t - e for t, e in zip(target, eye)]
    distance = math.sqrt(sum(x * x for x in direction))
    forward = [x / distance for x in direction]
    right = normalised(cross(forward, up))
    camera_up = cross(right, forward)
    pixel = 2 * TAN_HALF_VERTICAL / height * distance  # a pixel's size at the target
    return [t - 0.5 * pixel * r + 0.5 * pixel * u for t, r, u in zip(target, right, camera_up)]


def fgr_command(case, width, height, output):
    eye, target, up = case["eye"], case.get("target", [0, 0, 0]), case.get("up", [0, 0, 1])
    target = corner_aligned_target(eye, target, up, width, height)
    horizontal_fov = math.degrees(2 * math.atan(TAN_HALF_VERTICAL * width / height))
    command = [FGR, "render", case["fgr_scene"], "--width", str(width), "--height", str(height),
               "--effects", "none", "--alpha", "--eye", ",".join(map(str, eye)),
               "--target", ",".join(map(str, target)), "--up", ",".join(map(str, up)),
               "--fov", repr(horizontal_fov), "--set", f"max_distance={view_distance(case)}",
               "-o", output]
    for setting in case["fgr_set"]:
        command += ["--set", setting]
    return command


def run_fgr(case, width, height, output):
    start = time.monotonic()
    result = subprocess.run(fgr_command(case, width, height, output), capture_output=True,
                            text=True)
    wall_ms = (time.monotonic() - start) * 1000
    if result.returncode != 0:
        fail(f"fgr failed on {case['id']}: {result.stderr.strip()}")
    return wall_ms


def compare(case, width, height, rounds, tmp):
    mandelbulber_png = os.path.join(tmp, case["id"] + "_mandelbulber.png")
    fgr_png = os.path.join(tmp, case["id"] + "_fgr.png")
    run_fgr(case, width, height, fgr_png)  # builds and caches the kernel outside the timing
    best_mandelbulber = best_fgr = math.inf
    for _ in range(rounds):
        best_mandelbulber = min(best_mandelbulber,
                                run_mandelbulber(case, width, height, mandelbulber_png, tmp))
        best_fgr = min(best_fgr, run_fgr(case, width, height, fgr_png))
    _, _, a = silhouette_iou.read_alpha_mask(mandelbulber_png)
    _, _, b = silhouette_iou.read_alpha_mask(fgr_png)
    both = sum(1 for x, y in zip(a, b) if x and y)
    either = sum(1 for x, y in zip(a, b) if x or y)
    os.makedirs(RESULTS, exist_ok=True)
    silhouette_iou.write_diff(os.path.join(RESULTS, case["id"] + "_diff.png"), width, height,
                              a, b)
    return (both / either if either else 1.0), best_mandelbulber, best_fgr, (a, b)


def write_sheet(path, width, height, masks, columns=4):
    """The cases' disagreement pictures at half size, `columns` a row: a 2x2 block shows a
    disagreement if any of its pixels does (so one-pixel fringes stay visible)."""
    tile_w, tile_h = width // 2, height // 2
    rows = (len(masks) + columns - 1) // columns
    sheet_w = columns * tile_w
    pixels = bytearray(sheet_w * rows * tile_h * 3)
    for index, (a, b) in enumerate(masks):
        x0, y0 = (index % columns) * tile_w, (index // columns) * tile_h
        for y in range(tile_h):
            for x in range(tile_w):
                block = [(a[i], b[i]) for i in ((2 * y + dy) * width + 2 * x + dx
                                                 for dy in (0, 1) for dx in (0, 1))]
                pair = next((p for p in block if p[0] != p[1]), block[0])
                at = ((y0 + y) * sheet_w + x0 + x) * 3
                pixels[at:at + 3] = silhouette_iou.DIFF_COLOURS[pair]
    silhouette_iou.write_png(path, sheet_w, rows * tile_h, pixels, channels=3)


def write_fixture(case, tmp):
    width, height = FIXTURE_SIZE
    png = os.path.join(tmp, case["id"] + "_fixture.png")
    run_mandelbulber(case, width, height, png, tmp)
    _, _, mask = silhouette_iou.read_alpha_mask(png)
    os.makedirs(FIXTURES, exist_ok=True)
    silhouette_iou.write_mask(os.path.join(FIXTURES, case["id"] + ".png"), width, height, mask)


def ensure_mandelbulber():
    if shutil.which("mandelbulber2"):
        return
    if os.geteuid() != 0:
        fail("needs mandelbulber2 (apt-get install mandelbulber2)")
    print("installing mandelbulber2 (Debian package)", file=sys.stderr)
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(["apt-get", "install", "-y", "-q", "--no-install-recommends", "mandelbulber2"],
                   check=True, env=env, stdout=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--fixtures", action="store_true")
    parser.add_argument("ids", nargs="*")
    args = parser.parse_args()
    match = re.fullmatch(r"([1-9][0-9]*)x([1-9][0-9]*)", args.size)
    if not match or args.rounds < 1:
        fail("--size must be WxH and --rounds positive")
    width, height = int(match[1]), int(match[2])
    if not os.access(FGR, os.X_OK):
        fail("build fgr first (./build.sh)")
    ensure_mandelbulber()
    cases = json.load(open(CASES))["cases"]
    unknown = set(args.ids) - {case["id"] for case in cases}
    if unknown:
        fail(f"no case {', '.join(sorted(unknown))} in {CASES}")
    cases = [case for case in cases if not args.ids or case["id"] in args.ids]
    print("| formula | fgr scene | Mandelbulber 2 formula | IoU | Mandelbulber 2 ms | fgr ms | "
          "speed-up |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    masks = []
    with tempfile.TemporaryDirectory(prefix="fgr_mandelbulber_") as tmp:
        for case in cases:
            print(f"comparing {case['id']}", file=sys.stderr)
            iou, mandelbulber_ms, fgr_ms, pair = compare(case, width, height, args.rounds, tmp)
            masks.append(pair)
            print(f"| {case['title']} | `{case['fgr_scene']}` | {case['mandelbulber_name']} "
                  f"({case['mandelbulber_formula']}) | {iou:.3f} | {mandelbulber_ms:.0f} | "
                  f"{fgr_ms:.0f} | {mandelbulber_ms / fgr_ms:.1f}x |", flush=True)
            if args.fixtures:
                write_fixture(case, tmp)
    write_sheet(os.path.join(RESULTS, "silhouettes.png"), width, height, masks)


if __name__ == "__main__":
    main()
