// Geometry both the tracer and the samplers use, written once: the ray's slab test against the
// [-b, b]^3 box and the tetrahedral gradient's four taps. Composed before the SDF's helpers and
// the stage's own files (TracerComposer, SampleCompute); names carry the reserved prefix.

// Ray against the axis-aligned box [-b, b]^3; returns (tNear, tFar), tNear > tFar when missed.
vec2 sdfwb_intersectBox(vec3 origin, vec3 direction, float b) {
    vec3 inverse = 1.0 / direction;
    vec3 t0 = (vec3(-b) - origin) * inverse;
    vec3 t1 = (vec3(b) - origin) * inverse;
    vec3 tMin = min(t0, t1);
    vec3 tMax = max(t0, t1);
    return vec2(max(max(tMin.x, tMin.y), tMin.z), min(min(tMax.x, tMax.y), tMax.z));
}

// Tap i of the tetrahedral gradient, i = 0..3: (1,-1,-1), (-1,-1,1), (-1,1,-1), (1,1,1). The taps
// sum to zero, so sum_i tap(i) f(p + h tap(i)) / (4 h) is the gradient of a field linear across them.
vec3 sdfwb_tetrahedronTap(int i) {
    return vec3((i == 0 || i == 3) ? 1.0 : -1.0, i >= 2 ? 1.0 : -1.0, (i == 1 || i == 3) ? 1.0 : -1.0);
}
