#version 450
// The HUD's quad: two triangles over its rectangle, given in pixels of the colour target.
layout(push_constant) uniform Hud {
    ivec2 origin;  // top-left pixel of the overlay in the target
    ivec2 size;    // its size in pixels (the used part of the overlay image)
    vec2 target;   // the target's size in pixels
} hud;

void main() {
    const ivec2 corners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
    vec2 p = vec2(hud.origin + corners[gl_VertexIndex] * hud.size);
    // Vulkan's clip space has y down, as the pixel rows are.
    gl_Position = vec4(p / hud.target * 2.0 - 1.0, 0.0, 1.0);
}
