#version 450
// Writes a value fixed at pipeline creation (specialization constant 0) into every element,
// with a workgroup size also fixed there (constant 1): the ComputePipeline specialization path.
layout(local_size_x_id = 1) in;
layout(constant_id = 0) const uint kValue = 1;

layout(std430, set = 0, binding = 0) writeonly buffer Out { uint values[]; };
layout(push_constant) uniform Push { uint n; } push;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i < push.n) values[i] = kValue + (gl_WorkGroupSize.x == 32u ? 0u : 1000000u);
}
