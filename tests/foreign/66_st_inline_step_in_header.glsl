// Imitates: a compact whole Shadertoy that advances its march in the for loop's header,
// `for (int i = 0; i < 90; i++, t += d)`, with the torus written inline and `d` declared before
// the loop; the loop breaks on a hit and mainImage shades by the step count.
//
// Issue 47, the field written inline with the step in the loop's header: the body run once ends
// with the step's value.
//
// Why the audit should find it clean: the torus (radii 0.6 and 0.22) is an exact distance,
// centred in the cube. Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 1.2, -2.2);
    vec3 rd = normalize(vec3(uv.x, uv.y - 0.45, 1.0));
    float t = 0.0, d = 1.0;
    int steps = 0;
    for (int i = 0; i < 90; i++, t += d) {
        vec3 p = ro + t * rd;
        vec2 q = vec2(length(p.xz) - 0.6, p.y);
        d = length(q) - 0.22;
        steps = i;
        if (d < 0.001) break;
    }
    fragColor = vec4(vec3(1.0 - float(steps) / 90.0), 1.0);
}
