// Imitates: a shader written with the opposite sign convention, as some demoscene and fractal
// code is: the field is positive inside the solid and negative outside (`d = r - length(p)`), so
// the march counts its depth down, `z -= d;`, and stops where d climbs above -1e-3. A ball on top
// of a wide slab, the camera slightly above and looking down.
//
// Issue 47, a march backwards: the step `z -= d` makes the field -d, positive outside, so the
// surface and its side come out as in every other file.
//
// Why the audit should find it clean: -d is the union (min) of a ball (radius 0.35 at (0, 0.25, 0))
// and a slab |y + 0.3| < 0.1, both exact distances. Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 0.5, -2.5);
    vec3 rd = normalize(vec3(uv, 1.6) + vec3(0.0, -0.2, 0.0));
    float z = 0.0;
    float d = -1.0;
    for (int i = 0; i < 100; i++) {
        vec3 p = ro + rd * z;
        float ball = 0.35 - length(p - vec3(0.0, 0.25, 0.0));
        float slab = 0.1 - abs(p.y + 0.3);
        d = max(ball, slab);
        if (d > -1e-3 || z > 10.0) break;
        z -= d;
    }
    vec3 col = z < 10.0 ? vec3(0.9, 0.7, 0.5) * (1.0 - z * 0.15) : vec3(0.2, 0.3, 0.4);
    fragColor = vec4(col, 1.0);
}
