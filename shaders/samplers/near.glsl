// near: surface points (as in the surface pattern) moved along the normalised gradient by a
// Gaussian distance (on a mesh's own field: along the face normal of a point drawn on the mesh). Default: mean 0, standard deviation 0.005, clamped to [-0.3, 0.3].
// A mixture (--near-widths W:P,...; up to 4 components) is read from sdfwb_parameters:
// [0] = standard deviations, [1] = cumulative weights (the last is 1; a zero deviation ends the
// list), [2].x = truncation in deviations (0: none; a draw beyond it is drawn again, so the
// distribution is a truly truncated Gaussian, not one with spikes at the bounds).
float sdfwb_nearOffset(uint index) {
    float first = sdfwb_randomGaussian(index, 1000u);
    if (sdfwb_parameters[0].x <= 0.0) return clamp(0.005 * first, -0.3, 0.3);
    float pick = sdfwb_random4(index, 1001u).x;
    float width = sdfwb_parameters[0].x;
    for (int c = 1; c < 4; ++c)
        if (pick >= sdfwb_parameters[1][c - 1] && sdfwb_parameters[0][c] > 0.0) width = sdfwb_parameters[0][c];
    float truncation = sdfwb_parameters[2].x;
    float g = first;
    for (uint k = 1u; truncation > 0.0 && abs(g) > truncation && k < 64u; ++k) g = sdfwb_randomGaussian(index, 1001u + k);
    if (truncation > 0.0) g = clamp(g, -truncation, truncation); // after 64 draws (p < 1e-40 for 1 deviation)
    return width * g;
}

bool samplePosition(uint index, out vec3 position) {
#ifdef SDFWB_MESH_SURFACE
    // A mesh's own field: a point uniform by area on its triangles, moved along its face's normal.
    vec3 point, normal;
    sdfwb_meshSurfacePoint(sdfwb_random4(index, 0u).xyz, point, normal);
    position = point + sdfwb_nearOffset(index) * normal;
    return true;
#else
    vec3 hit;
    bool found = false;
    for (uint attempt = 0u; attempt < 100u && !found; ++attempt) found = sdfwb_traceRandomRay(index, attempt, hit);
    if (!found) return false;
    vec3 gradient = sdfwb_gradientAt(hit, 1e-4);
    float length2 = dot(gradient, gradient);
    vec3 normal = length2 > 0.0 ? gradient * inversesqrt(length2) : vec3(0.0);
    position = hit + sdfwb_nearOffset(index) * normal;
    return true;
#endif
}
