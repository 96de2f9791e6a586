// Sampling compute stage: one invocation per sample. The sampler file composed before this
// defines `bool samplePosition(uint index, out vec3 position)`; a false return writes a NaN row.

layout(local_size_x = 64) in;

layout(std430, binding = SDFWB_BINDING_POSITIONS) writeonly buffer Positions { float positions[]; };
layout(std430, binding = SDFWB_BINDING_DISTANCES) writeonly buffer Distances { float distances[]; };
layout(std430, binding = SDFWB_BINDING_GRADIENTS) writeonly buffer Gradients { float gradients[]; };

uniform uint u_chunkFirst;  // global index of this chunk's first sample
uniform uint u_chunkCount;  // samples in this chunk

void main() {
    uint local = gl_GlobalInvocationID.x;
    if (local >= u_chunkCount) return;
    uint index = u_chunkFirst + local;
    vec3 position;
    float distance;
    vec3 gradient;
    if (samplePosition(index, position)) {
        distance = map(position);
        gradient = gradientAt(position, u_gradientStep);
    } else {
        float nan = uintBitsToFloat(0x7fc00000u);
        position = vec3(nan);
        distance = nan;
        gradient = vec3(nan);
    }
    positions[3u * local + 0u] = position.x;
    positions[3u * local + 1u] = position.y;
    positions[3u * local + 2u] = position.z;
    distances[local] = distance;
    gradients[3u * local + 0u] = gradient.x;
    gradients[3u * local + 1u] = gradient.y;
    gradients[3u * local + 2u] = gradient.z;
}
