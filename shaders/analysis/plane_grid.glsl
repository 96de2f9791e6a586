// Points of a square grid on the cutting plane, for the plane readouts (not a user pattern).
// sdfwb_parameters[0] = (origin.xyz, side length), [1] = (axisU.xyz, 0), [2] = (axisV.xyz, 0); the grid
// has sdfwb_squareSide x sdfwb_squareSide points, row by row, covering origin + [0, side] (axisU, axisV).
bool samplePosition(uint index, out vec3 position) {
    uint n = sdfwb_squareSide;
    float u = (float(index % n) + 0.5) / float(n);
    float v = (float(index / n) + 0.5) / float(n);
    position = sdfwb_parameters[0].xyz + sdfwb_parameters[0].w * (u * sdfwb_parameters[1].xyz + v * sdfwb_parameters[2].xyz);
    return true;
}
