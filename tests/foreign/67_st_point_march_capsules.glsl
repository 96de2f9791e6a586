// Imitates: a whole Shadertoy that marches the point itself, as many short shaders do: `vec3 p =
// ro;` before the loop, the scene written inline (a capsule laid across a flattened ball), then
// `if (d < 1e-3) break; p += rd * d;`; mainImage shades by how far p got.
//
// Issue 47, the field written inline with no counter: the point grows by the direction times a
// float the loop computes from the point, so that float is the field, and the body run once at a
// point stops at the step.
//
// Why the audit should find it clean: IQ's capsule is exact; the squashed ball (a sphere scaled by
// 1/0.7 in y, its distance times 0.7) underestimates, and min() of the two stays 1-Lipschitz. Both
// sit inside the cube. Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no

float capsule(vec3 p, vec3 a, vec3 b, float r) {
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h) - r;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.3, 0.8, 2.8);
    vec3 rd = normalize(vec3(uv, -1.6) - vec3(0.0, 0.25, 0.0));
    vec3 p = ro;
    for (int i = 0; i < 100; i++) {
        float d = capsule(p, vec3(-0.6, 0.2, 0.0), vec3(0.6, 0.2, 0.0), 0.15);
        d = min(d, 0.7 * (length(p * vec3(1.0, 1.0 / 0.7, 1.0)) - 0.5));
        if (d < 1e-3) break;
        p += rd * d;
    }
    float travelled = length(p - ro);
    fragColor = vec4(vec3(travelled < 6.0 ? 1.0 - 0.2 * travelled : 0.05), 1.0);
}
