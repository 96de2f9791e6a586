// Sphere-tracing cost per pixel: steps / budget through a blue-cyan-yellow-red ramp; pixels that
// ran out of steps (misses at the budget) are magenta.
vec3 sdfwb_stepsColor(sdfwb_Hit hit) {
    float x = clamp(float(hit.steps) / float(sdfwb_maxSteps), 0.0, 1.0);
    if (!hit.found && hit.steps >= sdfwb_maxSteps) return vec3(1.0, 0.0, 1.0);
    vec3 low = vec3(0.05, 0.1, 0.45), mid = vec3(0.1, 0.75, 0.8), high = vec3(1.0, 0.85, 0.1), top = vec3(0.85, 0.1, 0.05);
    // The budget is often 10x the typical count: stretch the low end.
    float s = sqrt(x);
    return s < 0.33 ? mix(low, mid, s / 0.33) : s < 0.66 ? mix(mid, high, (s - 0.33) / 0.33) : mix(high, top, (s - 0.66) / 0.34);
}
