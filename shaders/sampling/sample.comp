// Sampling compute stage: one invocation per sample. The sampler file composed before this
// defines `bool samplePosition(uint index, out vec3 position)`; a false return writes a NaN row.

#undef samplePosition

layout(local_size_x = 64) in;

layout(std430, binding = SDFWB_BINDING_POSITIONS) writeonly buffer sdfwb_Positions { float sdfwb_positions[]; };
layout(std430, binding = SDFWB_BINDING_DISTANCES) writeonly buffer sdfwb_Distances { float sdfwb_distances[]; };
layout(std430, binding = SDFWB_BINDING_GRADIENTS) writeonly buffer sdfwb_Gradients { float sdfwb_gradients[]; };
// Rows with a NaN or infinity in any value written (misses, broken fields), counted here so the
// host does not read every row again.
// The bad rows, and (SDFWB_MESH_COUNT) the mesh walks' counts (mesh_field.glsl) of the chunk.
layout(std430, binding = SDFWB_BINDING_BAD_ROWS) buffer sdfwb_BadRowCount {
    uint sdfwb_badRows;
    uint sdfwb_meshCounts[5];
};

uniform uint sdfwb_chunkCount;  // samples in this chunk
// Callers that need only the field's value (a mesher's lattice, evaluate(gradient=False)) turn
// off the gradient's six extra evaluations and the writes they do not read back.
uniform bool sdfwb_writeGradient = true;
uniform bool sdfwb_writePosition = true;
// Rows of 7 floats (x y z distance gx gy gz) in the positions buffer, as .ply stores them, so the
// host writes the chunk to the file without rearranging it.
uniform bool sdfwb_interleaved = false;
// Floats before row 0 in each of the three arrays (separate layout): a file writer asks for them so
// that each array lies in memory at the same offset modulo a disk block as in its file.
uniform uvec3 sdfwb_arrayShift = uvec3(0u);
// A mesh's own field writes its exact gradient (the closest point's direction: one nearest walk
// and one sign a row instead of seven of each); true: six taps of sdfwb_gradientStep instead.
uniform bool sdfwb_meshGradientTaps = false;

void main() {
    // Chunks past 65,535 groups dispatch their groups in rows (renderer::SampleCompute).
    uint local = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x);
    if (local >= sdfwb_chunkCount) return;
    uint index = sdfwb_chunkFirst + local;
    vec3 position;
    float distance;
    vec3 gradient;
    if (sdfwb_samplePosition(index, position)) {
#if defined(SDFWB_POSITIONS_ONLY)
        // The native CPU engine computes the values at these positions (renderer::SampleCompute).
        distance = 0.0;
        gradient = vec3(0.0);
#else
#if defined(SDFWB_MESH_SURFACE)
        bool taps = sdfwb_meshGradientTaps || sdfwb_tetrahedralGradient;
#else
        bool taps = true;
#endif
        distance = sdfwb_valueAndGradient(position, sdfwb_gradientStep, true, sdfwb_writeGradient, taps, gradient);
#endif
    } else {
        float nan = uintBitsToFloat(0x7fc00000u);
        position = vec3(nan);
        distance = nan;
        gradient = vec3(nan);
    }
    // By the bits (all-ones exponent), which no compiler's fast-math folding can remove.
    const uint exponent = 0x7f800000u;
    bool finite = (floatBitsToUint(distance) & exponent) != exponent;
    if (sdfwb_writePosition) finite = finite && all(notEqual(floatBitsToUint(position) & exponent, uvec3(exponent)));
    if (sdfwb_writeGradient) finite = finite && all(notEqual(floatBitsToUint(gradient) & exponent, uvec3(exponent)));
    if (!finite) atomicAdd(sdfwb_badRows, 1u);
#ifdef SDFWB_MESH_COUNT
    if (sdfwb_meshNearestCount > 0u) atomicAdd(sdfwb_meshCounts[0], sdfwb_meshNearestCount);
    if (sdfwb_meshWindingCount > 0u) atomicAdd(sdfwb_meshCounts[1], sdfwb_meshWindingCount);
    if (sdfwb_meshLatticeCount > 0u) atomicAdd(sdfwb_meshCounts[2], sdfwb_meshLatticeCount);
    if (sdfwb_meshSegmentCount > 0u) atomicAdd(sdfwb_meshCounts[3], sdfwb_meshSegmentCount);
    if (sdfwb_meshCrossedCount > 0u) atomicAdd(sdfwb_meshCounts[4], sdfwb_meshCrossedCount);
#endif
    if (sdfwb_interleaved) {
        uint row = 7u * local;
        sdfwb_positions[row + 0u] = position.x;
        sdfwb_positions[row + 1u] = position.y;
        sdfwb_positions[row + 2u] = position.z;
        sdfwb_positions[row + 3u] = distance;
        sdfwb_positions[row + 4u] = gradient.x;
        sdfwb_positions[row + 5u] = gradient.y;
        sdfwb_positions[row + 6u] = gradient.z;
        return;
    }
    if (sdfwb_writePosition) {
        uint at = sdfwb_arrayShift.x + 3u * local;
        sdfwb_positions[at + 0u] = position.x;
        sdfwb_positions[at + 1u] = position.y;
        sdfwb_positions[at + 2u] = position.z;
    }
    sdfwb_distances[sdfwb_arrayShift.y + local] = distance;
    if (sdfwb_writeGradient) {
        uint at = sdfwb_arrayShift.z + 3u * local;
        sdfwb_gradients[at + 0u] = gradient.x;
        sdfwb_gradients[at + 1u] = gradient.y;
        sdfwb_gradients[at + 2u] = gradient.z;
    }
}
