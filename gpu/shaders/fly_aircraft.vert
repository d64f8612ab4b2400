#version 450
// The aircraft's triangles (3 vertices each from the Aircraft buffer), placed by the model ->
// eye-relative transform, lowered by the same curvature drop as the terrain under it.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/fly/cdlod_shared.h"
#include "gpu/fly/fly_frame.glsl"

layout(push_constant) uniform Placement { mat4 model_to_eye_relative; } placement;

layout(location = 0) out vec3 v_normal;  // ENU
layout(location = 1) out vec3 v_color;
layout(location = 2) out vec3 v_rel;     // eye-relative metres before the curvature drop (the spheres' frame)
layout(location = 3) out vec2 v_self_sky;  // the sky share its own spheres leave: normal's side, other side

void main() {
    vec4 p = aircraft[3 * gl_VertexIndex];
    vec3 n = aircraft[3 * gl_VertexIndex + 1].xyz;
    vec3 rel = (placement.model_to_eye_relative * vec4(p.xyz, 1.0)).xyz;
    v_rel = rel;
    rel.z -= ts_curvature_drop(dot(rel.xy, rel.xy));
    gl_Position = frame.view_projection * vec4(rel, 1.0);
    v_normal = normalize(mat3(placement.model_to_eye_relative) * n);
    v_color = aircraft[3 * gl_VertexIndex + 2].rgb;
    v_self_sky = vec2(aircraft[3 * gl_VertexIndex + 1].w, aircraft[3 * gl_VertexIndex + 2].w);
}
