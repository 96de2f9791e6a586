// Imitates: a whole Shadertoy assembled from pasted pieces: a planet with
// three moons orbiting on inclined paths with iTime, `vec2 map(vec3 p)`
// (material 1 the planet, 2-4 the moons), and a star-field background
// copied from another shader, whose author pinned its twinkle by
// declaring a LOCAL `float iTime = 0.0;` inside stars(), shadowing
// Shadertoy's input in that one function only. map(), moonCentre() and
// mainImage() use the real iTime. A file-scope scan that took that local
// declaration for the file's own iTime would leave the input undeclared
// (the other functions would not compile) and call the file static.
//
// Why the audit should find it clean: the planet and moons are spheres,
// exact, and min() of exact distances is the exact distance to the
// union: continuous, |grad| <= 1, growing outside the cube (orbits of
// radius 0.75, moons of radius <= 0.13: everything within 0.88 of the
// origin at every time), no NaN. The moons move with iTime, so the field
// depends on time: animated.
// expect: entry=map flags=none animated=yes

#define MOONS 3

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, -s, s, c);
}

float hash13(vec3 p)
{
    p = fract(p * 0.1031);
    p += dot(p, p.zyx + 31.32);
    return fract((p.x + p.y) * p.z);
}

// where moon i is now: a circle of radius 0.75, tilted, at its own pace
vec3 moonCentre(int i)
{
    float fi = float(i);
    float a = iTime * (0.6 + 0.25 * fi) + 2.1 * fi;
    vec3 c = vec3(0.75 * cos(a), 0.0, 0.75 * sin(a));
    c.yz *= rot(0.35 + 0.5 * fi);
    c.xy *= rot(0.4 * fi);
    return c;
}

vec2 map(vec3 p)
{
    vec2 res = vec2(length(p) - 0.42, 1.0);
    for (int i = 0; i < MOONS; i++)
    {
        float d = length(p - moonCentre(i)) - (0.09 + 0.02 * float(i));
        if (d < res.x) res = vec2(d, 2.0 + float(i));
    }
    return res;
}

// star field (pasted; its time is pinned so the stars stay still)
vec3 stars(vec3 rd)
{
    float iTime = 0.0;
    vec3 cell = floor(rd * 220.0);
    float h = hash13(cell);
    float twinkle = 0.6 + 0.4 * sin(iTime * 4.0 + 50.0 * h);
    return vec3(step(0.996, h) * twinkle);
}

vec3 calcNormal(vec3 p)
{
    const vec2 e = vec2(0.0005, 0.0);
    return normalize(vec3(map(p + e.xyy).x - map(p - e.xyy).x,
                          map(p + e.yxy).x - map(p - e.yxy).x,
                          map(p + e.yyx).x - map(p - e.yyx).x));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    vec3 ro = vec3(0.0, 0.9, 3.0);
    ro.xz *= rot(0.05 * iTime);
    vec3 ww = normalize(-ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 2.0 * ww);

    vec3 col = stars(rd);

    float t = 0.0;
    vec2 h = vec2(0.0);
    for (int i = 0; i < 128; i++)
    {
        h = map(ro + rd * t);
        if (h.x < 0.0003 * t || t > 10.0) break;
        t += h.x;
    }
    if (t < 10.0)
    {
        vec3 pos = ro + rd * t;
        vec3 nor = calcNormal(pos);
        vec3 sun = normalize(vec3(1.0, 0.3, 0.4));
        vec3 alb = h.y < 1.5 ? vec3(0.2, 0.4, 0.8) : vec3(0.7, 0.68, 0.65);
        col = alb * (0.03 + clamp(dot(nor, sun), 0.0, 1.0));
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
