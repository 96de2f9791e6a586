// Ambient occlusion from the field itself: compare f at a few points along the normal with their
// distance from the surface; where the field is smaller, other geometry is near.
// f at a point `distance` out along the normal; only a value below `distance` counts. A mesh's
// own field drawn by its walk (SDFWB_MESH_RAYCAST) takes the unsigned distance, from a nearest
// walk bounded by `distance` (no sign walk, and no box farther than that is opened): the points
// lie outside the surface along its normal.
#ifdef SDFWB_MESH_RAYCAST
float sdfwb_occluderDistance(vec3 p, float distance) { return sdfwb_meshDistanceWithin(p, distance); }
#else
float sdfwb_occluderDistance(vec3 p, float distance) { return sdfwb_sdf(p); }
#endif

float sdfwb_ambientOcclusion(vec3 position, vec3 normal) {
    float occlusion = 0.0;
    float weight = 1.0;
    for (int i = 1; i <= 5; ++i) {
        float distance = 0.03 * float(i);
        occlusion += weight * max(distance - sdfwb_occluderDistance(position + normal * distance, distance), 0.0);
        weight *= 0.6;
    }
    return clamp(1.0 - 4.0 * occlusion, 0.15, 1.0);
}
