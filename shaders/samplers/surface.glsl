// surface: points on the zero level set, found by tracing random rays (a random target in the
// cube, seen from a random direction). Up to 100 rays per sample; when all miss, the row is NaN.
// A mesh's own field (SDFWB_MESH_SURFACE) takes points uniform by area on its triangles instead.
bool samplePosition(uint index, out vec3 position) {
#ifdef SDFWB_MESH_SURFACE
    // A mesh's own field: points uniform by area on its triangles (as mesh_to_sdf and DeepSDF take them).
    vec3 normal;
    sdfwb_meshSurfacePoint(sdfwb_random4(index, 0u).xyz, position, normal);
    return true;
#else
    for (uint attempt = 0u; attempt < 100u; ++attempt)
        if (sdfwb_traceRandomRay(index, attempt, position)) return true;
    return false;
#endif
}
