#version 450
// y = a * x + y over n floats: the smallest kernel that exercises two storage buffers, push
// constants and a partial last workgroup. Used by the gpu tests and `terrashade devices --test`.
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Xs { float x[]; };
layout(std430, set = 0, binding = 1) buffer Ys { float y[]; };

layout(push_constant) uniform Push {
    float a;
    uint n;
} push;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= push.n) return;
    y[i] = push.a * x[i] + y[i];
}
