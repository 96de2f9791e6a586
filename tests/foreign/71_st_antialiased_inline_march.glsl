// Imitates: the anti-aliasing loops IQ's shaders wrap around their camera and march
// (`for (int m = 0; m < AA; m++) for (int n = 0; n < AA; n++) { ... }`), here around a march
// written inline in mainImage, with the pixel's offset feeding the ray: a capped cylinder standing
// on a torus, shaded by the step count and averaged over the 2 x 2 samples.
//
// Issue 47, a march nested in other loops: the code before it runs each enclosing loop's first
// pass (m = 0, n = 0), so the ray's variables are declared as the march expects.
//
// Why the audit should find it clean: the union (min) of a capped cylinder (radius 0.2, half
// height 0.35, at (0, 0.1, 0)) and a torus (radii 0.45 and 0.1, at y = -0.25) is an exact distance
// outside and a bound inside. Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no

#define AA 2

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 tot = vec3(0.0);
    for (int m = 0; m < AA; m++)
    for (int n = 0; n < AA; n++) {
        vec2 o = vec2(float(m), float(n)) / float(AA) - 0.5;
        vec2 p2 = (2.0 * (fragCoord + o) - iResolution.xy) / iResolution.y;
        vec3 ro = vec3(0.0, 0.8, -2.4);
        vec3 rd = normalize(vec3(p2.x, p2.y - 0.3, 1.8));
        float t = 0.0;
        int steps = 0;
        for (int i = 0; i < 128; i++) {
            vec3 pos = ro + rd * t;
            vec2 w = abs(vec2(length(pos.xz), pos.y - 0.1)) - vec2(0.2, 0.35);
            float cyl = min(max(w.x, w.y), 0.0) + length(max(w, 0.0));
            vec2 q = vec2(length(pos.xz) - 0.45, pos.y + 0.25);
            float h = min(cyl, length(q) - 0.1);
            steps = i;
            if (abs(h) < 0.0005 * t || t > 8.0) break;
            t += h;
        }
        tot += t < 8.0 ? vec3(1.0 - float(steps) / 128.0) : vec3(0.1, 0.12, 0.15);
    }
    fragColor = vec4(tot / float(AA * AA), 1.0);
}
