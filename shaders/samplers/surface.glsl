// surface: points on the zero level set, found by tracing random rays (a random target in the
// cube, seen from a random direction). Up to 100 rays per sample; when all miss, the row is NaN.
bool samplePosition(uint index, out vec3 position) {
    for (uint attempt = 0u; attempt < 100u; ++attempt)
        if (sdfwb_traceRandomRay(index, attempt, position)) return true;
    return false;
}
