// Imitates: an IQ-layout whole Shadertoy whose map takes the scene's animation as arguments
// instead of reading globals: `float sceneSDF(in vec3 pos, in float grow, in vec3 offset)`, a
// rounded box that breathes and a ball that bobs, marched in `castRay(ro, rd, grow, offset)`
// with IQ's `t += h` and `h < 0.0001 * t`, normals by his tetrahedron taps. mainImage computes
// grow and offset from iTime before it casts.
//
// Issue 47, class 1 with parameters after the point: the field is sceneSDF, found from castRay's
// loop; its two parameters (a float and a vec3, so not the `(vec3, float time)` form) come from
// mainImage's code before the cast, which reads iTime: sdfwb runs that code in the field's
// wrapper at the sampler's time.
//
// Why the audit should find it clean: IQ's sdRoundBox and the sphere are exact and min() joins
// them; at every time the box stays within 0.5 and the ball within 0.85 of the origin, so the
// field grows outside the cube: no flag. iTime moves the field: animated.
// expect: entry=sceneSDF flags=none animated=yes

float sdRoundBox(vec3 p, vec3 b, float r) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float sceneSDF(in vec3 pos, in float grow, in vec3 offset) {
    float box = sdRoundBox(pos, vec3(0.25 + 0.1 * grow), 0.05);
    float ball = length(pos - offset) - 0.2;
    return min(box, ball);
}

float castRay(in vec3 ro, in vec3 rd, in float grow, in vec3 offset) {
    float t = 0.0;
    for (int i = 0; i < 100; i++) {
        float h = sceneSDF(ro + rd * t, grow, offset);
        if (abs(h) < 0.0001 * t || t > 20.0) break;
        t += h;
    }
    return t;
}

vec3 calcNormal(in vec3 pos, in float grow, in vec3 offset) {
    vec2 e = vec2(1.0, -1.0) * 0.5773 * 0.0005;
    return normalize(e.xyy * sceneSDF(pos + e.xyy, grow, offset) + e.yyx * sceneSDF(pos + e.yyx, grow, offset) +
                     e.yxy * sceneSDF(pos + e.yxy, grow, offset) + e.xxx * sceneSDF(pos + e.xxx, grow, offset));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float grow = 0.5 + 0.5 * sin(iTime);
    vec3 offset = vec3(0.6, 0.1 + 0.15 * sin(1.7 * iTime), 0.0);

    vec3 ro = vec3(2.2, 1.4, 2.2);
    vec3 ww = normalize(-ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(p.x * uu + p.y * vv + 2.0 * ww);

    float t = castRay(ro, rd, grow, offset);
    vec3 col = vec3(0.7, 0.75, 0.85) - 0.2 * rd.y;
    if (t < 20.0) {
        vec3 pos = ro + rd * t;
        vec3 nor = calcNormal(pos, grow, offset);
        col = vec3(0.8, 0.6, 0.4) * (0.25 + 0.75 * clamp(dot(nor, normalize(vec3(0.6, 0.7, 0.4))), 0.0, 1.0));
    }
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
