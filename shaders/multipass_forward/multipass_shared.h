// multipass forward: structs, set-1 bindings and constants shared by C++ and GLSL.
// Included by this pipeline's C++ and GLSL only (never by shared.h); same rules as
// shared.h (TP_STRUCT, static_asserts on the C++ side).
// Everything per light travels in the scene's DrawPush push constant and in specialization
// constants, but for the blended light draws of the GPU's lists, which read their light from
// set 1 (blended_light_draws.h).
#ifndef TP_MULTIPASS_SHARED_H
#define TP_MULTIPASS_SHARED_H
#include "include/shared.h"

// Light passes carry the index of their light in DrawPush.pad0, so one pipeline object
// serves every light and no per-light descriptor set exists.
#define TP_MP_LIGHT_INDEX pad0

// The base pass evaluates up to TP_MP_MAX_BASE_DIRECTIONAL directional lights, named by
// specialization constants (count, then one index each); further directional lights get
// full-screen additive passes like any other light.
#define TP_MP_MAX_BASE_DIRECTIONAL 4
#define TP_MP_SPEC_DIRECTIONAL_COUNT 10
#define TP_MP_SPEC_DIRECTIONAL_FIRST 11 // ids 11 .. 11 + TP_MP_MAX_BASE_DIRECTIONAL - 1

// The light passes (light.frag under TP_MP_LIGHT_PASS) on a GPU with pass statistics: the
// fragments that evaluate their light (a 2x2 quad beyond its range does not) are counted per
// subgroup into TP_MP_LIT_SLOTS words, spread so that the atomics seldom meet, summed on the
// CPU: the light passes' counted work (docs/multipass_forward.md, "Quads beyond a light's
// range").
#define TP_MP_BINDING_LIT 0 // set TP_SET_PASS of the light passes: uint[TP_MP_LIT_SLOTS]
#define TP_MP_LIT_SLOTS 64

#endif
