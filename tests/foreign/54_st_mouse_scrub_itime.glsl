// Imitates: a whole Shadertoy that lets the viewer nudge its clock with
// the mouse by redefining the time input in terms of itself,
// `#define iTime (iTime + iMouse.x/iResolution.x)`, placed first in the
// file so every later use, the map's included, goes through it: a ringed
// planet with two moons on tilted orbits, `float map(vec3 p)`, a
// tetrahedral calcNormal(), a shadow, a star field behind and a camera
// drifting with (the redefined) iTime.
//
// Issue 47, class 2: a macro named after a Shadertoy input whose body
// reads that input and two more (iMouse, iResolution). The preprocessor
// does not expand iTime again inside its own body, so the body reads
// Shadertoy's input; sdfwb must declare the three inputs and must not
// define an iTime macro of its own over the file's.
//
// Why the audit should find it clean: the planet and the moons are exact
// spheres; the ring is a flat annulus, the exact distance of a revolved
// 2D box (radius 0.42 to 0.62, 0.02 thick), tilted by a rotation; the
// moons' orbits (radius 0.72 and 0.74) are rotations too. The ring clears
// the planet (0.35) and the moons (at least 0.66 from the centre), so the
// union by min() only meets where the two moons pass each other (a crease
// a moment long, read at most ~1.04 by per-axis differences). Continuous,
// finite, within 0.79 of the origin, growing outside: no flag. iTime in
// the map (the moons): animated.
// expect: entry=map flags=none animated=yes

#define iTime (iTime + iMouse.x/iResolution.x)

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, s, -s, c);
}

// a flat ring in the xz plane: radii r0..r1, half thickness h
float sdAnnulus(vec3 p, float r0, float r1, float h)
{
    vec2 q = vec2(abs(length(p.xz) - 0.5 * (r0 + r1)) - 0.5 * (r1 - r0), abs(p.y) - h);
    return length(max(q, 0.0)) + min(max(q.x, q.y), 0.0);
}

vec3 moonPos(float radius, float speed, float tilt, float phase)
{
    float a = speed * iTime + phase;
    vec3 m = vec3(radius * cos(a), 0.0, radius * sin(a));
    m.xy *= rot(tilt);
    return m;
}

float map(vec3 p)
{
    float d = length(p) - 0.35;

    vec3 q = p;
    q.xy *= rot(0.4);
    q.yz *= rot(0.2);
    d = min(d, sdAnnulus(q, 0.42, 0.62, 0.01));

    d = min(d, length(p - moonPos(0.72, 0.8, 0.6, 0.0)) - 0.06);
    d = min(d, length(p - moonPos(0.74, -0.5, -0.3, 2.0)) - 0.045);
    return d;
}

vec3 calcNormal(vec3 p)
{
    const vec2 k = vec2(1.0, -1.0);
    const float h = 0.0004;
    return normalize(k.xyy * map(p + k.xyy * h) + k.yyx * map(p + k.yyx * h) +
                     k.yxy * map(p + k.yxy * h) + k.xxx * map(p + k.xxx * h));
}

float trace(vec3 ro, vec3 rd, float tmax)
{
    float t = 0.0;
    for (int i = 0; i < 150; i++)
    {
        float h = map(ro + rd * t);
        if (h < 0.0003 * (1.0 + t)) return t;
        t += h;
        if (t > tmax) break;
    }
    return -1.0;
}

float stars(vec3 rd)
{
    vec3 c = floor(rd * 180.0);
    float h = fract(sin(dot(c, vec3(12.9898, 78.233, 37.719))) * 43758.5453);
    return smoothstep(0.985, 1.0, h);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;

    float a = 0.15 * iTime;
    vec3 ro = vec3(2.5 * sin(a), 0.7, -2.5 * cos(a));
    vec3 ww = normalize(-ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 1.5 * ww);

    vec3 col = vec3(stars(rd));

    float t = trace(ro, rd, 6.0);
    if (t > 0.0)
    {
        vec3 p = ro + rd * t;
        vec3 n = calcNormal(p);
        vec3 sun = normalize(vec3(1.0, 0.3, -0.4));
        float dif = max(dot(n, sun), 0.0);
        if (trace(p + n * 0.002, sun, 3.0) > 0.0) dif = 0.0;

        vec3 alb = vec3(0.6);
        float r = length(p);
        if (r < 0.36) alb = mix(vec3(0.8, 0.55, 0.3), vec3(0.9, 0.8, 0.6), 0.5 + 0.5 * sin(40.0 * p.y));
        else if (r < 0.64) alb = vec3(0.75, 0.7, 0.6) * (0.7 + 0.3 * sin(90.0 * r));
        col = alb * (0.03 + dif);
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
