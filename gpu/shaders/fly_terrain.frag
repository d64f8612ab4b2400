#version 450
// The terrain's colour: gpu/fly/fly_terrain_frag.glsl, without the overview fade.
#extension GL_GOOGLE_include_directive : require
#define TS_FLY_FADE 0
#include "gpu/fly/fly_terrain_frag.glsl"
