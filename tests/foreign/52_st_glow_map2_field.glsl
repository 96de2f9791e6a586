// Imitates: a whole "glowing core" Shadertoy: a gimbal of three nested
// rings turning on their pivots with iTime around an energy ball that is
// drawn only as glow. Two distance functions, as such shaders grow them:
// `float field(vec3 p)`, the solid rings, which the march steps by and
// the normals and the soft shadow use, and `float map2(vec3 p)`, the core
// (a pulsing ball), which only a second, fixed-step loop reads to
// accumulate glow along the whole ray (`glow += ... map2(...)`,
// `s += .05`): the core is never hit, only seen through.
//
// Issue 47, class 1: no conventional name, and two functions of a vec3
// called in loops from mainImage. The march's is unambiguous from the
// loops: in march(), `float d = field(ro + rd*t)` and `t += d` advance the
// ray (softShadow's loop too); in glowAlong(), map2's result only feeds
// `glow` while `s` grows by a constant. The entry is field.
//
// Why the audit should find it clean: each ring is an exact torus, and
// each is turned by a rotation (a gimbal nests them: the middle ring's
// frame is the outer ring's turned again); rotations are isometries.
// Rings of radii 0.72, 0.54, 0.36 and tubes 0.07, 0.06, 0.05 lie in
// disjoint shells about the origin (0.65-0.79, 0.48-0.60, 0.31-0.41), so
// they never touch, whatever iTime; joined by min(): exact outside,
// continuous, |grad| <= 1 (across the medial surfaces between rings the
// per-axis differences stay under 1.05). Within 0.79 of the origin, the
// field grows outside; no NaN. iTime in the map: animated.
// expect: entry=field flags=none animated=yes

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, s, -s, c);
}

// a ring in the xy plane: radius R, tube r
float ring(vec3 p, float R, float r)
{
    return length(vec2(length(p.xy) - R, p.z)) - r;
}

float field(vec3 p)
{
    float t = iTime;

    // outer ring: pivots on the x axis
    p.yz *= rot(0.7 * t);
    float d = ring(p, 0.72, 0.07);

    // middle ring: pivots on the outer ring's y axis
    p.xz *= rot(1.1 * t);
    d = min(d, ring(p, 0.54, 0.06));

    // inner ring: pivots on the middle ring's x axis
    p.yz *= rot(1.7 * t + 1.0);
    d = min(d, ring(p, 0.36, 0.05));

    return d;
}

// the energy core: only ever seen as glow
float map2(vec3 p)
{
    return length(p) - (0.14 + 0.03 * sin(5.0 * iTime));
}

float march(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < 160; i++)
    {
        float d = field(ro + rd * t);
        if (d < 0.0005 * (1.0 + t) || t > 8.0) break;
        t += d;
    }
    return t;
}

float glowAlong(vec3 ro, vec3 rd, float tmax)
{
    float glow = 0.0;
    for (float s = 0.0; s < 8.0; s += 0.05)
    {
        if (s > tmax) break;
        float c = map2(ro + rd * s);
        glow += 0.05 / (1.0 + 400.0 * c * c);
    }
    return glow;
}

vec3 calcNormal(vec3 p)
{
    vec2 e = vec2(0.0007, 0.0);
    return normalize(vec3(field(p + e.xyy) - field(p - e.xyy),
                          field(p + e.yxy) - field(p - e.yxy),
                          field(p + e.yyx) - field(p - e.yyx)));
}

float softShadow(vec3 ro, vec3 rd)
{
    float res = 1.0;
    float t = 0.02;
    for (int i = 0; i < 40; i++)
    {
        float h = field(ro + rd * t);
        res = min(res, 10.0 * h / t);
        t += clamp(h, 0.01, 0.2);
        if (res < 0.001 || t > 3.0) break;
    }
    return clamp(res, 0.0, 1.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    vec3 ro = vec3(0.0, 0.6, -2.8);
    vec3 ww = normalize(-ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 2.0 * ww);

    vec3 col = vec3(0.02, 0.01, 0.04);

    float t = march(ro, rd);
    if (t < 8.0)
    {
        vec3 p = ro + rd * t;
        vec3 n = calcNormal(p);

        // the core lights the rings from inside; a dim key light from above
        vec3 toCore = -normalize(p);
        float core = max(dot(n, toCore), 0.0) / (1.0 + 4.0 * dot(p, p));
        core *= softShadow(p + n * 0.003, toCore);
        vec3 key = normalize(vec3(0.3, 1.0, -0.4));
        float dif = max(dot(n, key), 0.0);

        col = vec3(0.35, 0.3, 0.28) * (0.08 + 0.3 * dif) + vec3(1.0, 0.55, 0.2) * 1.6 * core;
    }

    col += vec3(1.0, 0.5, 0.15) * glowAlong(ro, rd, t);

    col = 1.0 - exp(-col * 1.5);
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
