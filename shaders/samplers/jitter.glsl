// jitter: the grid pattern with each point moved uniformly within +-half a lattice cell on each
// axis, so points may fall up to half a cell outside the [-1,1]^3 cube.
bool samplePosition(uint index, out vec3 position) {
    uint n = sdfwb_cubeSide;
    vec3 lattice = vec3(sdfwb_latticeCoordinate(index % n, n), sdfwb_latticeCoordinate((index / n) % n, n), sdfwb_latticeCoordinate(index / (n * n), n));
    float cell = n > 1u ? 2.0 / float(n - 1u) : 2.0;
    position = lattice + (sdfwb_random4(index, 0u).xyz - 0.5) * cell;
    return true;
}
