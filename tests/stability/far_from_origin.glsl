// Evaluation far from the origin: a sphere of radius 0.5 modelled in coordinates shifted by 1e4
// (as a scene placed far out in world space would be). float32 spaces numbers near 1e4 by
// 2^-10 ~ 0.001, so every value carries rounding noise of that size: the precision floor.
// `precise` on every step keeps the compiler from cancelling the shift algebraically: Mesa does
// it when `world` alone is precise, NVIDIA's compiler (driver 580) when `local` is not.
float sdf(vec3 p) {
    precise vec3 world = p + vec3(10000.0, 0.0, 0.0);
    vec3 centre = vec3(10000.0, 0.0, 0.0);
    precise vec3 local = world - centre;
    precise float distance = length(local) - 0.5;
    return distance;
}
