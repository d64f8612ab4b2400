#version 450
// The sky behind the terrain: the sky model's radiance (the same table the haze reads) and the
// sun's disc, exposed and curved like the terrain.
#extension GL_GOOGLE_include_directive : require
#include "gpu/fly/fly_frame.glsl"

layout(location = 0) in vec2 v_ndc;
layout(location = 0) out vec4 out_color;

void main() {
    vec3 dir = normalize(frame.camera_forward.xyz + v_ndc.x * frame.camera_right.w * frame.camera_right.xyz -
                         v_ndc.y * frame.camera_up.w * frame.camera_up.xyz);
    vec3 l = sky_radiance(dir);
    if (dot(dir, frame.sun_direction.xyz) > frame.sun_direction.w) l += frame.sun_radiance.rgb;
    out_color = vec4(ts_display(l * frame.sun_radiance.w), 1.0);
}
