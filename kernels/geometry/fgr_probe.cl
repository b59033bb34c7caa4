// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: probes that evaluate the scene's DE and normals at given points, for
 * tests and for the host's tools (the DE at the camera decides auto precision). They share the
 * image layout macros of fgr_camera.cl; their planes (FGR_PROBE_*_PLANE) and arguments
 * (FGR_PROBE_ARG_*) are shared with the host (shared/fgr_layout_planes.h,
 * shared/fgr_layout_arguments.h). */

/* A probe's points: planes x, y, z of floats, then x, y, z of what those miss of the host's double
 * points, which double lanes add back (float lanes cannot use them). */
inline vec3 load_probe_point(__global const float* points, int plane_size, int packet) {
    __global const float* hi = points + FGR_PROBE_POINT_PLANE * plane_size;
    vec3 p = v3(fgr_load(packet, hi), fgr_load(packet, hi + plane_size),
                fgr_load(packet, hi + 2 * plane_size));
#ifdef FGR_DOUBLE
    __global const float* rest = points + FGR_PROBE_POINT_REST_PLANE * plane_size;
    p = v3_add(p, v3(fgr_load(packet, rest), fgr_load(packet, rest + plane_size),
                     fgr_load(packet, rest + 2 * plane_size)));
#endif
    return p;
}

/* Evaluates the scene's DE at `count` points (see load_probe_point; padded to whole packets):
 * used by tests to compare the kernel's DE with a host implementation, and by tools that need the
 * distance at a point (e.g. camera speed). */
__kernel void fgr_probe_de(__global const float* points, int plane_size, int packet_count,
                           __global float* out, PARAMS) {
    const int packet = get_global_id(0);
    if (packet >= packet_count) return;
    vec3 p = load_probe_point(points, plane_size, packet);
    fgr_store(scene_de(p, PARAMS_PASS), packet, out);
}

/* The surface normal the shading uses at each point (planes x, y, z in and out), with stencil
 * size eps: lets tests check normals are finite and unit length wherever rays can hit. */
__kernel void fgr_probe_normal(__global const float* points, int plane_size, int packet_count,
                               __global float* out, PARAMS, float eps) {
    const int packet = get_global_id(0);
    if (packet >= packet_count) return;
    vec3 p = load_probe_point(points, plane_size, packet);
    vec3 n = estimate_normal(p, fgr_real(eps), PARAMS_PASS);
    fgr_store(n.x, packet, out);
    fgr_store(n.y, packet, out + plane_size);
    fgr_store(n.z, packet, out + 2 * plane_size);
}

/* scene_de_pair over pairs of packets: packet i as the first of a pair with the packet half the
 * packets on (modulo their count) as the second, so that every packet is the first of one pair
 * and the second of another, far from it (plane 0: its DE as the first, plane 1: as the second).
 * `fgr check` compares both with scene_de. */
__kernel void fgr_probe_de_pair(__global const float* points, int plane_size, int packet_count,
                                __global float* out, PARAMS) {
    const int packet = get_global_id(0);
    if (packet >= packet_count) return;
    const int partner = (packet + max(packet_count / 2, 1)) % packet_count;
    real first, second;
    scene_de_pair(load_probe_point(points, plane_size, packet),
                  load_probe_point(points, plane_size, partner), &first, &second, PARAMS_PASS);
    fgr_store(first, packet, out);
    fgr_store(second, partner, out + plane_size);
}
