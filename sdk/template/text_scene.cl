/* fgr-scene
{
  "id": "@SCENE_ID@",
  "name": "@SCENE_NAME@",
  "description": "a bumpy ball: the text scene fgr new-scene --text starts from",
  "parameters": [
    {"id": "radius", "label": "Radius", "group": "Shape", "min": 0.25, "max": 1.5, "default": 1,
     "description": "radius of the ball"},
    {"id": "bumps", "label": "Bump height", "group": "Shape", "min": 0, "max": 0.25,
     "default": 0.08, "description": "height of the sine bumps on the ball"},
    {"id": "frequency", "label": "Bump frequency", "group": "Shape", "min": 1, "max": 24,
     "default": 9, "description": "bumps per radian along each axis"},
    {"id": "tint", "type": "colour", "label": "Tint", "group": "Colour",
     "default": [0.95, 0.55, 0.25], "description": "colour of the bumps' tops"}
  ],
  "cameras": [
    {"name": "front", "position": [0, -3.6, 1.4], "target": [0, 0, 0], "fov": 50},
    {"name": "close", "position": [0.6, -1.5, 0.9], "target": [0, 0, 0.2], "fov": 50}
  ],
  "camera_paths": [
    {"name": "orbit", "keyframes": [
      {"time": 0, "position": [0, -3.6, 1.4], "target": [0, 0, 0], "fov": 50},
      {"time": 2, "position": [3.6, 0, 1.4], "target": [0, 0, 0], "fov": 50},
      {"time": 4, "position": [0, 3.6, 1.4], "target": [0, 0, 0], "fov": 50},
      {"time": 6, "position": [-3.6, 0, 1.4], "target": [0, 0, 0], "fov": 50},
      {"time": 8, "position": [0, -3.6, 1.4], "target": [0, 0, 0], "fov": 50}]}
  ],
  "lights": [
    {"type": "directional", "direction": [0.6, -0.5, 0.8], "colour": [1, 0.95, 0.85],
     "intensity": 1.1},
    {"type": "directional", "direction": [-0.7, 0.4, 0.2], "colour": [0.4, 0.5, 0.8],
     "intensity": 0.35}
  ],
  "effects": ["shadows", "ambient_occlusion"],
  "march": {"max_steps": 160, "max_distance": 12, "hit_threshold": 1, "iterations": 8,
            "step_factor": 1}
}
*/

/* @SCENE_NAME@ (@SCENE_ID@): a text scene, one file fgr reads as it is, no compiler needed. The
 * comment above describes the scene (every key is in fgr's SDK guide, "A scene in ten lines of
 * text"); the rest of the file is its OpenCL C source. Render it with
 *     fgr render @SCENE_ID@.cl -o @SCENE_ID@.png
 * and edit it in `fgr view @SCENE_ID@.cl`, which reloads it on every save (a version that does not
 * compile shows the compiler's message, file and line, and keeps the last working one on screen).
 *
 * fgr evaluates many rays at once, so `real` is a float or a vector of floats and `vec3` holds
 * one of them per axis; write the maths once with the v3_* helpers. The kernel library (sd_*
 * primitives, op_* combinators, fold_* folds, orbit traps and palettes) is available here. */

/* The kernel library version this source is written for: fgr shows it that version's names. */
#define FGR_KERNEL_API 3

/* A lower bound on the distance from p to the surface: the ball of radius param_radius, pushed
 * in and out by sine bumps. Each parameter of the header is param_<id> here. */
real scene_de(vec3 p, PARAMS) {
    real ball = sd_sphere(p, param_radius);
    return op_displace_sine(ball, p, param_bumps, param_frequency);
}

/* Albedo in linear RGB: the tint on the bumps' tops, fading to white in the hollows. */
#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    real wave =
        sin(param_frequency * p.x) * sin(param_frequency * p.y) * sin(param_frequency * p.z);
    real t = clamp(0.5f + 1.5f * wave, 0.0f, 1.0f);
    vec3 white = v3_splat(0.9f, 0.9f, 0.88f);
    return v3_add(v3_scale(white, 1.0f - t), v3_scale(param_tint, t));
}
