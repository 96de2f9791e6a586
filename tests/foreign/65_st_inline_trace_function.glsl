// Imitates: a whole Shadertoy that keeps its march in a helper, `float trace(vec3 ro, vec3 rd)`,
// and writes the scene inline in that loop (a rounded box, IQ's formula typed out), returning t
// from inside the loop on a hit and -1. on a miss; mainImage calls trace and shades by the
// normal from screen-space derivatives of the hit point.
//
// Issue 47, the field written inline in a function mainImage calls: the loop is in trace, whose
// parameters (the ray) sdfwb declares as zero, since the point is given; the `return t;` that
// leaves the loop on a hit is dropped from the body run once.
//
// Why the audit should find it clean: IQ's rounded box is an exact distance, centred in the cube.
// Nothing reads iTime.
// expect: entry=trace flags=none animated=no

float trace(vec3 ro, vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < 100; i++) {
        vec3 pos = ro + rd * t;
        vec3 q = abs(pos) - vec3(0.5, 0.35, 0.45);
        float h = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - 0.1;
        if (h < 0.0005) return t;
        if (t > 30.0) break;
        t += h;
    }
    return -1.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(2.0, 1.5, 2.5);
    vec3 w = normalize(-ro);
    vec3 u = normalize(cross(w, vec3(0.0, 1.0, 0.0)));
    vec3 v = cross(u, w);
    vec3 rd = normalize(p.x * u + p.y * v + 2.0 * w);
    float t = trace(ro, rd);
    vec3 col = vec3(0.1);
    if (t > 0.0) {
        vec3 hit = ro + rd * t;
        vec3 n = normalize(cross(dFdx(hit), dFdy(hit)));
        col = vec3(0.5) + 0.5 * n;
    }
    fragColor = vec4(col, 1.0);
}
