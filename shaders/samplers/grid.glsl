// grid: a regular axis-aligned lattice over the cube [-1,1]^3, ends included. With n the
// smallest side such that n^3 >= N, sample i is lattice point (i mod n, i/n mod n, i/n^2),
// x fastest: the first N points of the rounded-up lattice.
bool samplePosition(uint index, out vec3 position) {
    uint n = sdfwb_cubeSide;
    position = vec3(sdfwb_latticeCoordinate(index % n, n), sdfwb_latticeCoordinate((index / n) % n, n), sdfwb_latticeCoordinate(index / (n * n), n));
    return true;
}
