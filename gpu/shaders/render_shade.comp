#version 450
// The per-frame relight (core/render/transfer.hpp's shade_transfer on the GPU): per texel and
// RGB channel the 16-term dot product of its transfer vector with the lighting SH. NaN T gives
// NaN radiance. Each invocation shades four consecutive texels with vec4 loads and stores (a
// quarter of the load instructions and invocations, which is what llvmpipe pays for); the
// planes of T are padded to a multiple of four texels for that.
#extension GL_EXT_control_flow_attributes : require
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Transfer { vec4 transfer[]; };  // [i][quad]
layout(std430, set = 0, binding = 1) readonly buffer Light { vec4 light[]; };        // [i] = (r, g, b, 0)
layout(std430, set = 0, binding = 2) writeonly buffer Radiance { vec4 rgb[]; };      // [texel][rgb], 3 vec4 per quad

layout(push_constant) uniform Push {
    uint quads;         // ceil(texels / 4)
    uint plane_quads;   // quads per coefficient plane of T (its padded stride / 4)
} p;

void main() {
    uint q = gl_GlobalInvocationID.x;
    if (q >= p.quads) return;
    vec4 r = vec4(0.0), g = vec4(0.0), b = vec4(0.0);
    [[unroll]] for (int i = 0; i < 16; ++i) {
        vec4 c = transfer[uint(i) * p.plane_quads + q];
        vec4 l = light[i];  // one load per coefficient, not three
        r += c * l.r;
        g += c * l.g;
        b += c * l.b;
    }
    // Texels 4q .. 4q+3 as r g b r g b ...: twelve floats, three vec4.
    rgb[3u * q] = vec4(r.x, g.x, b.x, r.y);
    rgb[3u * q + 1u] = vec4(g.y, b.y, r.z, g.z);
    rgb[3u * q + 2u] = vec4(b.z, r.w, g.w, b.w);
}
