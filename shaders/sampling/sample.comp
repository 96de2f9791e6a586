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

void sdfwb_addMeshCounts() {
#ifdef SDFWB_MESH_COUNT
    if (sdfwb_meshNearestCount > 0u) atomicAdd(sdfwb_meshCounts[0], sdfwb_meshNearestCount);
    if (sdfwb_meshWindingCount > 0u) atomicAdd(sdfwb_meshCounts[1], sdfwb_meshWindingCount);
    if (sdfwb_meshLatticeCount > 0u) atomicAdd(sdfwb_meshCounts[2], sdfwb_meshLatticeCount);
    if (sdfwb_meshSegmentCount > 0u) atomicAdd(sdfwb_meshCounts[3], sdfwb_meshSegmentCount);
    if (sdfwb_meshCrossedCount > 0u) atomicAdd(sdfwb_meshCounts[4], sdfwb_meshCrossedCount);
#endif
}

#ifdef SDFWB_SORT_ROWS
// A mesh's own field on the GLSL engine (issue 46): neighbouring invocations that walk the
// hierarchy from far-apart points diverge, so the chunk's rows are evaluated grouped by the cell of
// a lattice over the mesh they lie in, cells in Morton order, and each row's results are written
// at its own place. renderer::SampleCompute dispatches this program five times a chunk, with
// sdfwb_sortPass 1 to 5:
//   1 each row's position (the sampler's) and cell; each cell's rows counted
//   2 (SDFWB_SORT_PARTS invocations) the counts of each part of the cells added up
//   3 (the same) each cell's first slot: the rows of the cells before it
//   4 each row takes the next slot of its cell
//   5 the slots in order: each row's value and gradient, written at the row's place
// A row's results depend on its position only, so they are the one-pass program's whatever the
// order within a cell (the same program: SampleCompute's tests compare the two bit for bit).
// sdfwb_sortWords: the parts' sums, the cells' counts (then first slots), then a word a row (its
// cell; the top bit when the sampler missed), a row a slot, and three words a row (position).
layout(std430, binding = SDFWB_BINDING_SORT) buffer sdfwb_Sort { uint sdfwb_sortWords[]; };
uniform uint sdfwb_sortPass = 0u; // 0: one pass in the sampler's order
uniform uint sdfwb_sortBits = 1u; // a cell's Morton code: this many bits an axis
uniform vec4 sdfwb_sortCube;      // the cube the cells divide: low corner and side
uniform uint sdfwb_sortCapacity;  // rows the buffer's regions have room for

uint sdfwb_sortSpread(uint v) { // bits 0..9 of v to bits 0, 3, 6, ...
    v = (v | (v << 16u)) & 0x030000ffu;
    v = (v | (v << 8u)) & 0x0300f00fu;
    v = (v | (v << 4u)) & 0x030c30c3u;
    v = (v | (v << 2u)) & 0x09249249u;
    return v;
}

uint sdfwb_sortCell(vec3 p) {
    const uint exponent = 0x7f800000u;
    if (any(equal(floatBitsToUint(p) & exponent, uvec3(exponent)))) return 0u;
    float side = float(1u << sdfwb_sortBits);
    vec3 at = clamp(floor((p - sdfwb_sortCube.xyz) / sdfwb_sortCube.w * side), vec3(0.0), vec3(side - 1.0));
    uvec3 c = uvec3(at);
    return sdfwb_sortSpread(c.x) | (sdfwb_sortSpread(c.y) << 1u) | (sdfwb_sortSpread(c.z) << 2u);
}

// Passes 2 and 3: part `part` of the cells.
void sdfwb_sortScan(uint part) {
    if (part >= SDFWB_SORT_PARTS) return;
    uint cells = 1u << (3u * sdfwb_sortBits);
    uint size = (cells + SDFWB_SORT_PARTS - 1u) / SDFWB_SORT_PARTS;
    uint from = min(part * size, cells), to = min(from + size, cells);
    if (sdfwb_sortPass == 2u) {
        uint sum = 0u;
        for (uint c = from; c < to; ++c) sum += sdfwb_sortWords[SDFWB_SORT_PARTS + c];
        sdfwb_sortWords[part] = sum;
        return;
    }
    uint next = 0u;
    for (uint k = 0u; k < part; ++k) next += sdfwb_sortWords[k];
    for (uint c = from; c < to; ++c) {
        uint rows = sdfwb_sortWords[SDFWB_SORT_PARTS + c];
        sdfwb_sortWords[SDFWB_SORT_PARTS + c] = next;
        next += rows;
    }
}
#endif

void main() {
    // Chunks past 65,535 groups dispatch their groups in rows (renderer::SampleCompute).
    uint local = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x);
#ifdef SDFWB_CHAIN_PASSES
    if (sdfwb_chainTo < int(sdfwb_kSteps)) { // a pass of the chains before their last: no row yet
        vec3 unplaced;
        if (local < sdfwb_chunkCount) sdfwb_samplePosition(sdfwb_chunkFirst + local, unplaced);
        sdfwb_addMeshCounts();
        return;
    }
#endif
#ifdef SDFWB_SORT_ROWS
    if (sdfwb_sortPass == 2u || sdfwb_sortPass == 3u) {
        sdfwb_sortScan(local);
        return;
    }
#endif
    if (local >= sdfwb_chunkCount) return;
    vec3 position;
    float distance;
    vec3 gradient;
    bool placed;
#ifdef SDFWB_SORT_ROWS
    uint keys = SDFWB_SORT_PARTS + (1u << (3u * sdfwb_sortBits));
    uint slots = keys + sdfwb_sortCapacity;
    uint places = slots + sdfwb_sortCapacity;
    if (sdfwb_sortPass == 1u) {
        placed = sdfwb_samplePosition(sdfwb_chunkFirst + local, position);
        uint cell = sdfwb_sortCell(position);
        sdfwb_sortWords[keys + local] = cell | (placed ? 0u : 0x80000000u);
        sdfwb_sortWords[places + 3u * local] = floatBitsToUint(position.x);
        sdfwb_sortWords[places + 3u * local + 1u] = floatBitsToUint(position.y);
        sdfwb_sortWords[places + 3u * local + 2u] = floatBitsToUint(position.z);
        atomicAdd(sdfwb_sortWords[SDFWB_SORT_PARTS + cell], 1u);
        sdfwb_addMeshCounts(); // a sampler that evaluates the field (metropolis) walks here
        return;
    }
    if (sdfwb_sortPass == 4u) {
        uint cell = sdfwb_sortWords[keys + local] & 0x7fffffffu;
        sdfwb_sortWords[slots + atomicAdd(sdfwb_sortWords[SDFWB_SORT_PARTS + cell], 1u)] = local;
        return;
    }
    if (sdfwb_sortPass == 5u) {
        local = sdfwb_sortWords[slots + local];
        placed = (sdfwb_sortWords[keys + local] & 0x80000000u) == 0u;
        position = uintBitsToFloat(uvec3(sdfwb_sortWords[places + 3u * local], sdfwb_sortWords[places + 3u * local + 1u],
                                         sdfwb_sortWords[places + 3u * local + 2u]));
    } else
#endif
        placed = sdfwb_samplePosition(sdfwb_chunkFirst + local, position);
    if (placed) {
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
    sdfwb_addMeshCounts();
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
