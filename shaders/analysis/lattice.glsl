// Grid points of blocks of cells (the mesher), generated here instead of uploaded: sample i is
// point i % P of block i / P, a block being the (B+1)^3 grid points from its first corner.
//   sdfwb_inputs: per block, the grid index of its first point (3 floats, exact integers)
//   sdfwb_parameters[0] = (grid origin, B), [1] = (grid step, n): indices past n are clamped to n
// B = 0: each sample is one grid point of its own (a list of points), and the host uploads the
// list chunk by chunk (row 0 of the buffer is the chunk's first sample), not whole for each chunk.
// The position is computed as origin + index * step in float32, the same for every block that
// shares a point, so shared points get the same value.
layout(std430, binding = SDFWB_BINDING_INPUTS) readonly buffer sdfwb_Inputs { float sdfwb_inputs[]; };

bool samplePosition(uint index, out vec3 position) {
    uint side = uint(sdfwb_parameters[0].w) + 1u;
    uint perBlock = side * side * side;
    uint block = index / perBlock, local = index - block * perBlock;
    if (side == 1u) block = index - sdfwb_chunkFirst;
    vec3 offset = vec3(float(local % side), float((local / side) % side), float(local / (side * side)));
    vec3 first = vec3(sdfwb_inputs[3u * block], sdfwb_inputs[3u * block + 1u], sdfwb_inputs[3u * block + 2u]);
    vec3 gridIndex = min(first + offset, vec3(sdfwb_parameters[1].w));
    position = sdfwb_parameters[0].xyz + gridIndex * sdfwb_parameters[1].xyz;
    return true;
}
