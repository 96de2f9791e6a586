// near: surface points (as in the surface pattern) moved along the normalised gradient by a
// Gaussian distance of mean 0 and standard deviation 0.005, clamped to [-0.3, 0.3].
bool samplePosition(uint index, out vec3 position) {
    vec3 hit;
    for (uint attempt = 0u; attempt < 100u; ++attempt) {
        if (!sdfwb_traceRandomRay(index, attempt, hit)) continue;
        vec3 gradient = sdfwb_gradientAt(hit, 1e-4);
        float length2 = dot(gradient, gradient);
        vec3 normal = length2 > 0.0 ? gradient * inversesqrt(length2) : vec3(0.0);
        float offset = clamp(0.005 * sdfwb_randomGaussian(index, 1000u), -0.3, 0.3);
        position = hit + offset * normal;
        return true;
    }
    return false;
}
