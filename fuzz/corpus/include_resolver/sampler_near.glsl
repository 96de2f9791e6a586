// near: surface points (as in the surface pattern) moved along the normalised gradient by a
// Gaussian distance of mean 0 and standard deviation 0.005, clamped to [-0.3, 0.3].
bool samplePosition(uint index, out vec3 position) {
    vec3 hit;
    for (uint attempt = 0u; attempt < 100u; ++attempt) {
        if (!traceRandomRay(index, attempt, hit)) continue;
        vec3 gradient = gradientAt(hit, 1e-4);
        float length2 = dot(gradient, gradient);
        vec3 normal = length2 > 0.0 ? gradient * inversesqrt(length2) : vec3(0.0);
        float offset = clamp(0.005 * randomGaussian(index, 1000u), -0.3, 0.3);
        position = hit + offset * normal;
        return true;
    }
    return false;
}
