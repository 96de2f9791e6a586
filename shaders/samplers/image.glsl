// image: a regular lattice over the square [-1,1]^2 in the z = 0 plane, ends included, in image
// order (rows from y = +1 down to y = -1, x left to right), so the first n^2 distances reshape
// into an n x n picture. The first N points of the rounded-up n x n lattice.
bool samplePosition(uint index, out vec3 position) {
    uint n = sdfwb_squareSide;
    uint column = index % n;
    uint row = index / n;
    position = vec3(sdfwb_latticeCoordinate(column, n), -sdfwb_latticeCoordinate(row, n), 0.0);
    return true;
}
