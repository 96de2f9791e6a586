// Ambient occlusion from the field itself: compare f at a few points along the normal with their
// distance from the surface; where the field is smaller, other geometry is near.
float sdfwb_ambientOcclusion(vec3 position, vec3 normal) {
    float occlusion = 0.0;
    float weight = 1.0;
    for (int i = 1; i <= 5; ++i) {
        float distance = 0.03 * float(i);
        occlusion += weight * max(distance - sdfwb_sdf(position + normal * distance), 0.0);
        weight *= 0.6;
    }
    return clamp(1.0 - 4.0 * occlusion, 0.15, 1.0);
}
