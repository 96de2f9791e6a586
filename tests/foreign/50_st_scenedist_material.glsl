// Imitates: a whole "chess piece" Shadertoy of the kind intermediate
// authors write after a tutorial or two: `#define MAT_WOOD 1.0` style
// material ids, `vec2 sceneDist(vec3 p)` answering (distance, material)
// with its own `vec2 opU()` and a smooth variant, a `march()` that returns
// (t, id) and steps by the `.x` of sceneDist, calcNormal() on
// `sceneDist(...).x`, a lookAt camera orbiting with iTime, hard shadows,
// rim light and a ground-free backdrop: a pawn (a rounded base disc, a
// rim, a round-cone body, a gold collar and a ball head).
//
// Issue 47, class 1: the distance function returns a vec2 and is named
// sceneDist; sdfwb must find it from march()'s loop (mainImage -> march,
// and shadow() through its own loop), where `vec2 res = sceneDist(...)`
// and `t += res.x` advance the ray.
//
// Why the audit should find it clean: the pieces are exact distances (a
// rounded cylinder as a revolved rounded rectangle, IQ's round cone, a
// torus, a capped cylinder, a sphere), joined by opSU(), IQ's polynomial
// smooth min on .x (gradient a convex mix of the two: |grad| <= 1,
// continuous), and opU(), a plain min of .x where the collar meets the
// body. The ids jump, but they are not the distance. Everything lies
// within 0.45 of the y axis and -0.65 <= y <= 0.62: the field grows
// outside; no NaN (the round cone's sqrt(1 - b*b) has b = 0.21). The
// camera orbits with iTime (the map does not read it): animated.
// expect: entry=sceneDist flags=none animated=yes

#define MAT_WOOD 1.0
#define MAT_GOLD 2.0

#define STEPS 128
#define FAR 10.0

vec2 opU(vec2 a, vec2 b)
{
    return a.x < b.x ? a : b;
}

// smooth union: IQ's polynomial smin on the distance, the nearer id
vec2 opSU(vec2 a, vec2 b, float k)
{
    float h = clamp(0.5 + 0.5 * (b.x - a.x) / k, 0.0, 1.0);
    return vec2(mix(b.x, a.x, h) - k * h * (1.0 - h), a.x < b.x ? a.y : b.y);
}

// a disc of radius ra, half height h, its edges rounded by rb
float sdRoundDisc(vec3 p, float ra, float h, float rb)
{
    vec2 d = vec2(length(p.xz) - ra + rb, abs(p.y) - h + rb);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0)) - rb;
}

float sdRoundCone(vec3 p, float r1, float r2, float h)
{
    float b = (r1 - r2) / h;
    float a = sqrt(1.0 - b * b);
    vec2 q = vec2(length(p.xz), p.y);
    float k = dot(q, vec2(-b, a));
    if (k < 0.0) return length(q) - r1;
    if (k > a * h) return length(q - vec2(0.0, h)) - r2;
    return dot(q, vec2(a, b)) - r1;
}

float sdTorus(vec3 p, vec2 t)
{
    return length(vec2(length(p.xz) - t.x, p.y)) - t.y;
}

float sdCappedCylinder(vec3 p, float r, float h)
{
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(r, h);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

vec2 sceneDist(vec3 p)
{
    vec2 res = vec2(sdRoundDisc(p - vec3(0.0, -0.59, 0.0), 0.42, 0.06, 0.02), MAT_WOOD);
    res = opSU(res, vec2(sdTorus(p - vec3(0.0, -0.52, 0.0), vec2(0.3, 0.06)), MAT_WOOD), 0.04);
    res = opSU(res, vec2(sdRoundCone(p - vec3(0.0, -0.38, 0.0), 0.24, 0.1, 0.68), MAT_WOOD), 0.08);
    res = opU(res, vec2(sdCappedCylinder(p - vec3(0.0, 0.22, 0.0), 0.19, 0.025), MAT_GOLD));
    res = opSU(res, vec2(length(p - vec3(0.0, 0.42, 0.0)) - 0.2, MAT_WOOD), 0.03);
    return res;
}

vec2 march(vec3 ro, vec3 rd)
{
    float t = 0.0;
    float m = -1.0;
    for (int i = 0; i < STEPS; i++)
    {
        vec2 res = sceneDist(ro + rd * t);
        if (res.x < 0.0005)
        {
            m = res.y;
            break;
        }
        t += res.x;
        if (t > FAR) break;
    }
    return vec2(t, m);
}

vec3 calcNormal(vec3 p)
{
    vec2 e = vec2(0.0005, 0.0);
    return normalize(vec3(sceneDist(p + e.xyy).x - sceneDist(p - e.xyy).x,
                          sceneDist(p + e.yxy).x - sceneDist(p - e.yxy).x,
                          sceneDist(p + e.yyx).x - sceneDist(p - e.yyx).x));
}

float shadow(vec3 ro, vec3 rd)
{
    float t = 0.02;
    for (int i = 0; i < 48; i++)
    {
        float h = sceneDist(ro + rd * t).x;
        if (h < 0.001) return 0.0;
        t += h;
        if (t > 3.0) break;
    }
    return 1.0;
}

mat3 lookAt(vec3 eye, vec3 target)
{
    vec3 f = normalize(target - eye);
    vec3 r = normalize(cross(f, vec3(0.0, 1.0, 0.0)));
    vec3 u = cross(r, f);
    return mat3(r, u, f);
}

vec3 material(float id, vec3 p)
{
    if (id == MAT_GOLD) return vec3(0.9, 0.65, 0.2);
    // wood: rings around the axis
    float rings = 0.5 + 0.5 * sin(60.0 * length(p.xz) + 8.0 * p.y);
    return mix(vec3(0.45, 0.25, 0.12), vec3(0.6, 0.38, 0.2), rings);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;

    float a = 0.4 * iTime;
    vec3 ro = vec3(2.4 * sin(a), 1.0, 2.4 * cos(a));
    vec3 rd = lookAt(ro, vec3(0.0, -0.05, 0.0)) * normalize(vec3(uv, 1.6));

    // backdrop
    vec3 col = mix(vec3(0.18, 0.16, 0.15), vec3(0.35, 0.33, 0.3), uv.y + 0.5);

    vec2 hit = march(ro, rd);
    if (hit.y > 0.0)
    {
        vec3 p = ro + rd * hit.x;
        vec3 n = calcNormal(p);
        vec3 l = normalize(vec3(0.6, 0.9, 0.4));

        float dif = max(dot(n, l), 0.0) * shadow(p + n * 0.002, l);
        float rim = pow(1.0 - max(dot(n, -rd), 0.0), 3.0);
        float spe = pow(max(dot(reflect(rd, n), l), 0.0), hit.y == MAT_GOLD ? 40.0 : 12.0);

        vec3 alb = material(hit.y, p);
        col = alb * (0.2 + 0.9 * dif) + 0.4 * rim + 0.3 * spe * dif;
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
