// Imitates: a terrain Shadertoy written after Inigo Quilez's article on raymarching terrains: no
// distance anywhere, only a height function of x and z. `castRay` walks the ray in steps that
// grow with the distance (`dt = max(0.004, 0.01 * t)`, taken in the for header), stops at the first
// sample under the terrain (`if (p.y < h)`) and interpolates between the last two samples; normals
// from the height's finite differences, a sky gradient and fog.
//
// Issue 47, a fixed-step march: the loop never steps by a value of its point, so no function is
// marched and no float is a distance. It stops where p.y < h, h computed from the point by
// terrain(): sdfwb's field is p.y - h, negative under the terrain, a height and not a distance.
//
// Why the audit should find it non-conservative and nothing else: |grad (p.y - f)| is
// sqrt(1 + |grad f|^2), and f's slope (up to 0.425 from the first wave and 0.39 from the second)
// is above 0.32, where that passes 1.05, over much of the cube. The field is smooth and finite,
// and it grows without bound above and below the terrain. Nothing reads iTime.
// expect: entry=castRay flags=non-conservative animated=no

float terrain(vec2 q) {
    return 0.25 * sin(1.7 * q.x) * cos(1.3 * q.y) + 0.1 * sin(3.1 * q.x + 2.3 * q.y) - 0.2;
}

vec3 terrainNormal(vec3 p) {
    const float eps = 0.002;
    return normalize(vec3(terrain(p.xz - vec2(eps, 0.0)) - terrain(p.xz + vec2(eps, 0.0)), 2.0 * eps,
                          terrain(p.xz - vec2(0.0, eps)) - terrain(p.xz + vec2(0.0, eps))));
}

bool castRay(vec3 ro, vec3 rd, out float resT) {
    const float mint = 0.01;
    const float maxt = 12.0;
    float dt = 0.004;
    float lh = 0.0;
    float ly = 0.0;
    for (float t = mint; t < maxt; t += dt) {
        vec3 p = ro + rd * t;
        float h = terrain(p.xz);
        if (p.y < h) {
            // between the last sample above the terrain and this one below it
            resT = t - dt + dt * (lh - ly) / (p.y - ly - h + lh);
            return true;
        }
        // farther away, a pixel covers more ground: larger steps
        dt = max(0.004, 0.01 * t);
        lh = h;
        ly = p.y;
    }
    return false;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 0.6, 3.0);
    vec3 ta = vec3(0.0, -0.2, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 1.5 * ww);

    vec3 sky = mix(vec3(0.75, 0.85, 1.0), vec3(0.3, 0.5, 0.85), max(rd.y, 0.0));
    vec3 col = sky;
    float t;
    if (castRay(ro, rd, t)) {
        vec3 p = ro + rd * t;
        vec3 n = terrainNormal(p);
        vec3 sun = normalize(vec3(0.6, 0.5, -0.4));
        vec3 rock = mix(vec3(0.45, 0.35, 0.25), vec3(0.3, 0.5, 0.2), smoothstep(0.6, 0.9, n.y));
        col = rock * (0.25 + 0.75 * max(dot(n, sun), 0.0));
        col = mix(col, sky, 1.0 - exp(-0.08 * t * t));
    }
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
