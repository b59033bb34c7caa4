// SPDX-License-Identifier: Apache-2.0
/* Menger room: a Menger sponge standing on the floor of a closed room, lit by a lamp under the
 * ceiling. Nothing reaches the room from outside, so every ray ends on a wall, and most of the
 * light a surface receives has bounced off the walls, the floor and the sponge first: the scene
 * where a path tracer's later bounces matter most. Its default mode is the path tracer.
 *
 * Geometry: the sponge is the menger scene's KIFS (scale 3, offset (1, 1, 1), no twist) scaled by
 * `sponge_size` and set on the floor; the room is the inside of an axis-aligned box, whose DE is
 * the distance to its nearest wall (exact inside). Materials: white diffuse walls, floor and
 * ceiling, a red wall on the left and a green one on the right (they tint the light they pass
 * on), a diffuse sponge, and a square lamp panel in the ceiling above the point light. The panel
 * glows with `lamp` (0 by default: an emitter only the paths that happen to hit it find adds
 * fireflies, where the point light is sampled at every bounce). */

#define FGR_KERNEL_API 2

/* The room's inside: x and y in [-ROOM_HALF, ROOM_HALF], z from the floor to the ceiling. */
#define ROOM_HALF 2.5f
#define ROOM_FLOOR (-1.0f)
#define ROOM_CEILING 2.2f
/* Half the side of the lamp panel in the ceiling. */
#define LAMP_HALF 0.45f

inline real room_sponge(vec3 p, PARAMS) {
    const float size = param_sponge_size;
    /* The unit sponge fills [-1, 1]^3: its bottom face rests on the floor. */
    vec3 w = v3_scale(v3_sub(p, v3_splat(0.0f, 0.0f, ROOM_FLOOR + size)), fgr_real(1.0f / size));
    const rotation3 none = rotation_about_axis(v3_splat(0.0f, 0.0f, 1.0f), 0.0f);
    const vec3 offset = v3_splat(1.0f, 1.0f, 1.0f);
    float half_size = 1.0f;
    for (int i = 0; i < param_iterations; ++i) {
        half_size /= 3.0f;
        w = formula_menger_step(w, none, offset, 2.0f * half_size);
    }
    return sd_box(w, v3_splat(half_size, half_size, half_size)) * size;
}

/* Distances to the walls from inside the room: left (-x), right (+x), the rest. */
inline real room_left(vec3 p) { return p.x + ROOM_HALF; }
inline real room_right(vec3 p) { return ROOM_HALF - p.x; }
inline real room_other_walls(vec3 p) {
    return fmin(fmin(p.y + ROOM_HALF, ROOM_HALF - p.y), fmin(p.z - ROOM_FLOOR, ROOM_CEILING - p.z));
}

inline real room_walls(vec3 p) {
    return fmin(fmin(room_left(p), room_right(p)), room_other_walls(p));
}

real scene_de(vec3 p, PARAMS) { return fmin(room_sponge(p, PARAMS_PASS), room_walls(p)); }

/* Which surface a lane's point belongs to: the sponge, else the nearest wall. */
inline mask on_sponge(vec3 p, PARAMS) { return room_sponge(p, PARAMS_PASS) < room_walls(p); }

inline mask in_lamp(vec3 p) {
    return (ROOM_CEILING - p.z < 0.05f) & (fabs(p.x) < LAMP_HALF) & (fabs(p.y) < LAMP_HALF);
}

/* The diffuse colour of the wall nearest to p (walls meet at corners: the nearer one wins). */
inline vec3 wall_colour(vec3 p, PARAMS) {
    const real left = room_left(p), right = room_right(p), other = room_other_walls(p);
    vec3 colour = param_wall_colour;
    colour = v3_select(colour, param_left_colour, (left < right) & (left < other));
    colour = v3_select(colour, param_right_colour, (right <= left) & (right < other));
    return colour;
}

inline vec3 room_albedo(vec3 p, PARAMS) {
    return v3_select(wall_colour(p, PARAMS_PASS), param_sponge_colour, on_sponge(p, PARAMS_PASS));
}

#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) { return room_albedo(p, PARAMS_PASS); }

#define FGR_SCENE_HAS_MATERIAL
material scene_material(vec3 p, PARAMS) {
    const mask lamp = in_lamp(p) & !on_sponge(p, PARAMS_PASS);
    material m;
    m.albedo = v3_select(room_albedo(p, PARAMS_PASS), v3_splat(0.8f, 0.8f, 0.8f), lamp);
    m.specular = v3_splat(0.0f, 0.0f, 0.0f);
    m.roughness = fgr_real(1.0f);
    const float glow = param_lamp;
    m.emission =
        v3_select(v3_splat(0.0f, 0.0f, 0.0f), v3_splat(glow, 0.93f * glow, 0.8f * glow), lamp);
    return m;
}
