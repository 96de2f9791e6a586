// Points of a square grid on the cutting plane, for the plane readouts (not a user pattern).
// u_parameters[0] = (origin.xyz, side length), [1] = (axisU.xyz, 0), [2] = (axisV.xyz, 0); the grid
// has u_squareSide x u_squareSide points, row by row, covering origin + [0, side] (axisU, axisV).
bool samplePosition(uint index, out vec3 position) {
    uint n = u_squareSide;
    float u = (float(index % n) + 0.5) / float(n);
    float v = (float(index / n) + 0.5) / float(n);
    position = u_parameters[0].xyz + u_parameters[0].w * (u * u_parameters[1].xyz + v * u_parameters[2].xyz);
    return true;
}
