// Evaluation far from the origin: a sphere of radius 0.5 modelled in coordinates shifted by 1e4
// (as a scene placed far out in world space would be). float32 spaces numbers near 1e4 by
// 2^-10 ~ 0.001, so every value carries rounding noise of that size: the precision floor.
// `precise` keeps the compiler from cancelling the shift algebraically (Mesa would).
float sdf(vec3 p) {
    precise vec3 world = p + vec3(10000.0, 0.0, 0.0);
    vec3 centre = vec3(10000.0, 0.0, 0.0);
    return length(world - centre) - 0.5;
}
