// SPDX-License-Identifier: Apache-2.0
/* fgr: the light lists the render modes read from a __constant float buffer, each light a fixed
 * number of floats at these offsets (see fgr_layout_types.h for how this header is shared). */
#ifndef FGR_LAYOUT_LIGHTS_H
#define FGR_LAYOUT_LIGHTS_H

/* A light's kind, as a float at its FGR_LIGHT_KIND or FGR_PATH_LIGHT_KIND. (The plugin ABI's
 * fgr_light_type has the same values under the names FGR_LIGHT_DIRECTIONAL and FGR_LIGHT_POINT,
 * which the host sees too.) */
#define FGR_LIGHT_KIND_DIRECTIONAL 0
#define FGR_LIGHT_KIND_POINT 1

/* A scene light of the shaded and brute modes (fgr_shade.cl; host/render/modes/mode_registry.cpp
 * writes them), FGR_LIGHT_FLOATS floats each. */
#define FGR_LIGHT_KIND 0   /* FGR_LIGHT_KIND_DIRECTIONAL or FGR_LIGHT_KIND_POINT */
#define FGR_LIGHT_VECTOR 1 /* 3: towards a directional light (unit), or a point light's place */
#define FGR_LIGHT_COLOUR 4 /* 3: r, g, b */
#define FGR_LIGHT_INTENSITY 7
#define FGR_LIGHT_FLOATS 8

/* A light of the path tracer (fgr_mode_path.cl; host/render/modes/path_mode.cpp writes them: the
 * scene's and the sky's sun), FGR_PATH_LIGHT_FLOATS floats each. */
#define FGR_PATH_LIGHT_KIND 0     /* FGR_LIGHT_KIND_DIRECTIONAL or FGR_LIGHT_KIND_POINT */
#define FGR_PATH_LIGHT_VECTOR 1   /* 3: as FGR_LIGHT_VECTOR */
#define FGR_PATH_LIGHT_RADIANCE 4 /* 3: a disc's radiance; a point light's intensity, W/sr-like */
#define FGR_PATH_LIGHT_COS_MAX 7  /* cosine of a disc's angular radius; 1: a delta light */
#define FGR_PATH_LIGHT_FLOATS 8

#endif /* FGR_LAYOUT_LIGHTS_H */
