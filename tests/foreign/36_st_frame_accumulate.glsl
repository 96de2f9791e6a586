// Imitates: a whole Shadertoy that accumulates frames for a clean picture:
// a multi-material `vec2 map(vec3 p)` (a ground slab, a block of towers,
// a floating orb; ids 1-4) and a mainImage() that jitters its ray by a
// sub-pixel offset hashed from fragCoord and iFrame, then blends the new
// sample with the previous frame read by texelFetch(iChannel0,
// ivec2(fragCoord), 0) (iChannel0 set to the pass itself), weight
// 1/(iFrame+1). The towers take their heights from the popular
// fract(sin(dot(...))*43758.5453) hash of their cell. The ground is a
// slab, not an infinite plane (see 40_st_clock_overlay.glsl for what a
// plane does to the audit).
//
// Why discontinuous: the 5x5 towers are drawn by limited repetition
// (round(p.xz/0.3), clamped to -2..2) and each cell measures the distance
// to ITS OWN tower only, whose height (0.15 to 0.9) comes from a hash of
// the cell. Identical towers would make that exact, but with different
// heights the neighbour can be nearer: above the tops, on a cell border
// the two sides answer the distances to two towers of different heights,
// a jump of up to the difference of the heights (~0.25 on average), on
// every interior border where the towers are the nearest thing. The jumps
// are all the audit reads: inside each cell the field is an exact box
// distance (|grad| = 1), the slab and the orb are exact, min keeps them
// so, nothing is NaN, and the field grows outward (no plateau). No iTime:
// the accumulation counts frames, not seconds.
// expect: entry=map flags=discontinuous animated=no

#define MAT_GROUND 1.0
#define MAT_TOWER  2.0   // 2 or 3
#define MAT_ORB    4.0

#define CELL 0.3

float hash21(vec2 p)
{
    return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
}

vec2 hash22(vec2 p)
{
    return fract(sin(vec2(dot(p, vec2(127.1, 311.7)), dot(p, vec2(269.5, 183.3)))) * 43758.5453);
}

float sdBox(vec3 p, vec3 b)
{
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

vec2 opU(vec2 a, vec2 b)
{
    return a.x < b.x ? a : b;
}

vec2 map(vec3 p)
{
    // ground
    vec2 res = vec2(sdBox(p - vec3(0.0, -0.85, 0.0), vec3(0.85, 0.05, 0.85)), MAT_GROUND);

    // towers: one per cell of a 5x5 block, of random height
    vec2 id = clamp(round(p.xz / CELL), -2.0, 2.0);
    vec2 q = p.xz - CELL * id;
    float rnd = hash21(id + 7.0);
    float h = 0.15 + 0.75 * rnd;
    float tower = sdBox(vec3(q.x, p.y + 0.8 - 0.5 * h, q.y), vec3(0.09, 0.5 * h, 0.09));
    res = opU(res, vec2(tower, MAT_TOWER + step(0.5, rnd)));

    // the orb
    res = opU(res, vec2(length(p - vec3(0.0, 0.42, 0.0)) - 0.28, MAT_ORB));

    return res;
}

vec3 calcNormal(vec3 p)
{
    const vec2 k = vec2(1.0, -1.0);
    const float h = 0.0005;
    return normalize(k.xyy * map(p + k.xyy * h).x +
                     k.yyx * map(p + k.yyx * h).x +
                     k.yxy * map(p + k.yxy * h).x +
                     k.xxx * map(p + k.xxx * h).x);
}

vec2 castRay(vec3 ro, vec3 rd)
{
    float t = 0.01;
    for (int i = 0; i < 200; i++)
    {
        vec2 h = map(ro + rd * t);
        if (abs(h.x) < 0.0002 * t) return vec2(t, h.y);
        t += 0.8 * h.x;   // the towers' cells do not see their neighbours
        if (t > 30.0) break;
    }
    return vec2(-1.0);
}

float shadow(vec3 ro, vec3 rd)
{
    float res = 1.0;
    float t = 0.02;
    for (int i = 0; i < 48; i++)
    {
        float h = map(ro + rd * t).x;
        res = min(res, 12.0 * h / t);
        t += clamp(h, 0.02, 0.2);
        if (res < 0.001 || t > 4.0) break;
    }
    return clamp(res, 0.0, 1.0);
}

vec3 render(vec3 ro, vec3 rd)
{
    vec3 col = vec3(0.55, 0.65, 0.8) * (1.0 - 0.4 * rd.y);
    vec2 hit = castRay(ro, rd);
    if (hit.x < 0.0) return col;

    vec3 p = ro + rd * hit.x;
    vec3 n = calcNormal(p);
    vec3 alb = vec3(0.4);
    if (hit.y < 1.5)      alb = vec3(0.35, 0.33, 0.3) * (0.8 + 0.2 * mod(floor(p.x * 4.0) + floor(p.z * 4.0), 2.0));
    else if (hit.y < 2.5) alb = vec3(0.7, 0.65, 0.6);
    else if (hit.y < 3.5) alb = vec3(0.3, 0.45, 0.6);
    else                  alb = vec3(0.9, 0.5, 0.2);

    vec3 sun = normalize(vec3(-0.4, 0.7, 0.5));
    float dif = clamp(dot(n, sun), 0.0, 1.0) * shadow(p + n * 0.002, sun);
    float sky = 0.5 + 0.5 * n.y;
    col = alb * (dif * vec3(1.2, 1.05, 0.9) + sky * vec3(0.25, 0.3, 0.4));
    return mix(col, vec3(0.55, 0.65, 0.8), 1.0 - exp(-0.002 * hit.x * hit.x));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    // a new sub-pixel offset every frame
    vec2 jitter = hash22(fragCoord + vec2(0.618, 1.618) * float(iFrame)) - 0.5;
    vec2 p = (2.0 * (fragCoord + jitter) - iResolution.xy) / iResolution.y;

    vec3 ro = vec3(2.4, 1.6, 2.9);
    vec3 ta = vec3(0.0, -0.2, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(p.x * uu + p.y * vv + 2.0 * ww);

    vec3 col = render(ro, rd);
    col = pow(col, vec3(0.4545));

    // accumulate: iChannel0 is this pass's previous frame
    vec3 prev = texelFetch(iChannel0, ivec2(fragCoord), 0).rgb;
    float w = iFrame == 0 ? 1.0 : 1.0 / float(iFrame + 1);
    fragColor = vec4(mix(prev, col, w), 1.0);
}
