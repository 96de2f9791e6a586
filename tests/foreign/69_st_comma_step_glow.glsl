// Imitates: a golfed glow loop as code-golfers write it on Shadertoy: the whole state declared in
// one line before the loop, the field and the step sequenced by the comma operator in one
// statement, `d = ..., t += d;` (as in `e += I, c += e * .35;`), and colour piled up from exp(-d).
// The scene: a box with rounded edges and a ball beside it, both exact distances.
//
// Issue 47, the field written inline where the step shares a statement with other assignments:
// the comma operator's parts are read as statements in their order, so `t += d` is the step.
//
// Why the audit should find it clean: the union (min) of a rounded box (half sides 0.3, radius
// 0.05) and a ball (radius 0.25 at (0.55, 0, 0)) is an exact distance outside and a bound inside.
// Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no

void mainImage(out vec4 o, vec2 u) {
    vec2 r = iResolution.xy, v = (u + u - r) / r.y;
    vec3 c = vec3(0), e = vec3(0, 0, -2.5), k = normalize(vec3(v, 1.5)), q;
    float t = 0., d = 1., b;
    for (int i = 0; i < 80; i++) {
        vec3 p = e + k * t;
        q = abs(p) - .25;
        b = length(max(q, 0.)) + min(max(q.x, max(q.y, q.z)), 0.) - .05;
        d = min(b, length(p - vec3(.55, 0, 0)) - .25), t += d;
        c += vec3(.02, .03, .05) * exp(-d * 40.);
        if (d < 1e-4 || t > 8.) break;
    }
    o = vec4(c, 1);
}
