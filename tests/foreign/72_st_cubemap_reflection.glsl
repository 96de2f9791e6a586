// Imitates: Shadertoy shaders that reflect a cube-map environment (iChannel0 set to one of
// Shadertoy's cube maps, "Uffizi Gallery" or "St Peters Basilica") and texture their objects from a
// 2-D channel: IQ's `map`/`calcNormal`/`castRay` layout, the sky and the reflections read by
// `texture(iChannel0, rd)` and `texture(iChannel0, reflect(rd, nor))`, the albedo by
// `texture(iChannel1, pos.xy)`.
//
// Issue 47, a cube map: a channel read with a direction does not compile as a sampler2D, so the
// shader did not open at all. sdfwb declares iChannel0 a samplerCube (the noise texels, or the
// picked image, on each face) and keeps iChannel1 a sampler2D.
//
// Why the audit should find it clean: the union (min) of a ball (radius 0.4 at (-0.5, 0, 0)) and a
// rounded box (half size 0.25, rounding 0.08, at (0.5, 0, 0)) is an exact distance outside and a
// bound inside. Nothing reads iTime.
// expect: entry=map flags=none animated=no

float sdRoundBox(vec3 p, vec3 b, float r) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float map(in vec3 pos) {
    float ball = length(pos - vec3(-0.5, 0.0, 0.0)) - 0.4;
    float box = sdRoundBox(pos - vec3(0.5, 0.0, 0.0), vec3(0.25), 0.08);
    return min(ball, box);
}

vec3 calcNormal(in vec3 pos) {
    vec2 e = vec2(1.0, -1.0) * 0.5773 * 0.0005;
    return normalize(e.xyy * map(pos + e.xyy) + e.yyx * map(pos + e.yyx) + e.yxy * map(pos + e.yxy) +
                     e.xxx * map(pos + e.xxx));
}

float castRay(in vec3 ro, in vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < 100; i++) {
        float h = map(ro + rd * t);
        if (abs(h) < 0.0001 * t || t > 10.0) break;
        t += h;
    }
    return t;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 0.4, -2.5);
    vec3 rd = normalize(vec3(p, 1.8));
    vec3 col = texture(iChannel0, rd).rgb; // the environment behind the objects
    float t = castRay(ro, rd);
    if (t < 10.0) {
        vec3 pos = ro + rd * t;
        vec3 nor = calcNormal(pos);
        vec3 ref = reflect(rd, nor);
        float fre = pow(clamp(1.0 + dot(nor, rd), 0.0, 1.0), 5.0);
        vec3 albedo = texture(iChannel1, pos.xy * 0.5 + 0.5).rgb;
        col = albedo * 0.3 * (0.5 + 0.5 * nor.y) + mix(0.04, 1.0, fre) * texture(iChannel0, ref).rgb;
    }
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
