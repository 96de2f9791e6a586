// Short straight runs of points for the precision-floor measurement (not a user pattern): every
// 16 consecutive indices walk from a random point of the cube along a random direction in steps
// of sdfwb_parameters[0].x. A smooth field is a near-quadratic along 16 such points; what a quadratic
// cannot fit is rounding noise in the SDF's own arithmetic.
bool samplePosition(uint index, out vec3 position) {
    uint line = index / 16u;
    float k = float(index % 16u);
    position = sdfwb_randomInCube(line, 0u) * 0.9 + k * sdfwb_parameters[0].x * sdfwb_randomDirection(line, 1u);
    return true;
}
