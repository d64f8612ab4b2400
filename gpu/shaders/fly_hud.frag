#version 450
// The HUD: its texel under this pixel, one overlay texel per frame pixel (the CPU already
// scaled the font), blended with its straight alpha by the pipeline.
layout(set = 0, binding = 0) uniform sampler2D overlay;
layout(push_constant) uniform Hud {
    ivec2 origin;
    ivec2 size;
    vec2 target;
} hud;
layout(location = 0) out vec4 out_color;

void main() {
    ivec2 t = clamp(ivec2(gl_FragCoord.xy) - hud.origin, ivec2(0), hud.size - 1);
    out_color = texelFetch(overlay, t, 0);
}
