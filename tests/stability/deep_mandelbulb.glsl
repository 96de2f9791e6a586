// Deep fractal iteration: the textbook power-8 Mandelbulb distance estimate 0.5 r log(r) / dr
// at 64 iterations. Inside the set dr grows by 8 r^7 per iteration and overflows to Inf (the
// estimate becomes 0 there), log(r) of a tiny r is a large negative number: intermediate Inf and
// near-zero values the tracer, normals and samplers must survive.
float sdf(vec3 p) {
    vec3 c = p / 0.8;
    vec3 z = c;
    float dr = 1.0;
    float r = length(z);
    for (int i = 0; i < 64 && r < 2.0; ++i) {
        float theta = acos(clamp(z.y / max(r, 1e-20), -1.0, 1.0)) * 8.0;
        float phi = atan(z.z, z.x) * 8.0;
        float r7 = pow(r, 7.0);
        dr = 8.0 * r7 * dr + 1.0;
        z = r7 * r * vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi)) + c;
        r = length(z);
    }
    return 0.8 * 0.5 * log(max(r, 1e-20)) * r / dr;
}
