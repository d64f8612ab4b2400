#version 450
// The terrain's colour in a detail tile's fade band: gpu/fly/fly_terrain_frag.glsl with the
// overview's radiance blended in.
#extension GL_GOOGLE_include_directive : require
#define TS_FLY_FADE 1
#include "gpu/fly/fly_terrain_frag.glsl"
