// Imitates: a whole Shadertoy written "properly": Shadertoy's
// HW_PERFORMANCE macro guarded for hosts that lack it (#ifndef ...
// #define HW_PERFORMANCE 0), AA chosen from it (#define AA 1 or
// #define AA 2), `struct Ray` / `struct Hit` / `struct Material` passed
// between a castRay(), a getMaterial() and a shade(), `vec2 map(vec3 p)`
// with material ids carried through a smooth union, and a fixed IQ-style camera (setCamera(ro, ta, 0.0),
// focal 2.5) over a constant background, so the picture can be compared
// with sdfwb's tracer: a toy spinning top (a cone-like stack of a capped
// cylinder, a torus rim, a ball and a stem) floating in the cube.
//
// Why the audit should find it clean: the capped cylinders, torus, sphere
// and capsule are exact distances, and opSU() blends them with IQ's
// polynomial smooth min, whose gradient h grad a + (1-h) grad b is a
// convex mix (|grad| <= 1) and which is continuous; the id it carries
// jumps, but it is not the distance. Growing outside the cube (everything
// within |x|, |z| <= 0.6 and -0.75 <= y <= 0.8), no NaN. (The blends also
// round the concave creases, where the audit's per-axis differences over
// a crease would read up to sqrt(2).) No iTime and no
// iMouse: not animated. (The file defines HW_PERFORMANCE itself, so sdfwb
// need not; with it 0 the picture has no AA, AA 1.)
// expect: entry=map flags=none animated=no
// picture: eye=2.1,1.1,2.3 target=0,0,0 focal=2.5

#ifndef HW_PERFORMANCE
#define HW_PERFORMANCE 0
#endif

#if HW_PERFORMANCE==0
#define AA 1
#else
#define AA 2
#endif

#define MAT_BODY 1.0
#define MAT_RIM  2.0
#define MAT_BALL 3.0
#define MAT_STEM 4.0

struct Ray {
    vec3 origin;
    vec3 dir;
};

struct Hit {
    float t;
    float id;
    bool found;
};

struct Material {
    vec3 albedo;
    float shininess;
};

float sdCappedCylinder(vec3 p, float h, float r)
{
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(r, h);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

float sdTorus(vec3 p, vec2 t)
{
    return length(vec2(length(p.xz) - t.x, p.y)) - t.y;
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r)
{
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h) - r;
}

// smooth union of (distance, id) pairs: IQ's polynomial smin on .x, the nearer id
vec2 opSU(vec2 a, vec2 b, float k)
{
    float h = clamp(0.5 + 0.5 * (b.x - a.x) / k, 0.0, 1.0);
    float d = mix(b.x, a.x, h) - k * h * (1.0 - h);
    return vec2(d, a.x < b.x ? a.y : b.y);
}

vec2 map(vec3 p)
{
    // body: three stacked discs, narrowing downwards, blended together
    vec2 res = vec2(sdCappedCylinder(p - vec3(0.0, 0.05, 0.0), 0.12, 0.5), MAT_BODY);
    res = opSU(res, vec2(sdCappedCylinder(p - vec3(0.0, -0.2, 0.0), 0.13, 0.34), MAT_BODY), 0.06);
    res = opSU(res, vec2(sdCappedCylinder(p - vec3(0.0, -0.42, 0.0), 0.1, 0.18), MAT_BODY), 0.06);
    // a rim around the widest disc
    res = opSU(res, vec2(sdTorus(p - vec3(0.0, 0.05, 0.0), vec2(0.5, 0.06)), MAT_RIM), 0.03);
    // the tip
    res = opSU(res, vec2(length(p - vec3(0.0, -0.62, 0.0)) - 0.12, MAT_BALL), 0.04);
    // the stem
    res = opSU(res, vec2(sdCapsule(p, vec3(0.0, 0.1, 0.0), vec3(0.0, 0.72, 0.0), 0.07), MAT_STEM), 0.05);
    return res;
}

Hit castRay(Ray ray)
{
    Hit hit = Hit(0.0, 0.0, false);
    float t = 0.0;
    for (int i = 0; i < 256; i++)
    {
        vec2 h = map(ray.origin + ray.dir * t);
        if (abs(h.x) < 0.0001 * t)
        {
            hit = Hit(t, h.y, true);
            break;
        }
        t += h.x;
        if (t > 20.0) break;
    }
    return hit;
}

vec3 calcNormal(vec3 p)
{
    const vec2 k = vec2(1.0, -1.0);
    const float h = 0.0004;
    return normalize(k.xyy * map(p + k.xyy * h).x + k.yyx * map(p + k.yyx * h).x +
                     k.yxy * map(p + k.yxy * h).x + k.xxx * map(p + k.xxx * h).x);
}

Material getMaterial(float id)
{
    if (id < 1.5) return Material(vec3(0.85, 0.2, 0.1), 16.0);
    if (id < 2.5) return Material(vec3(0.95, 0.75, 0.1), 48.0);
    if (id < 3.5) return Material(vec3(0.3, 0.75, 0.2), 8.0);
    return Material(vec3(0.55, 0.35, 0.2), 4.0);
}

const vec3 BACKGROUND = vec3(0.8, 0.85, 0.95);

vec3 shade(Ray ray, Hit hit)
{
    if (!hit.found) return BACKGROUND;
    vec3 p = ray.origin + ray.dir * hit.t;
    vec3 n = calcNormal(p);
    Material m = getMaterial(hit.id);

    vec3 l = normalize(vec3(0.5, 0.8, 0.4));
    float dif = clamp(dot(n, l), 0.0, 1.0);
    Hit sh = castRay(Ray(p + n * 0.002, l));
    if (sh.found) dif *= 0.2;
    vec3 hv = normalize(l - ray.dir);
    float spe = pow(clamp(dot(n, hv), 0.0, 1.0), m.shininess) * dif;
    float amb = 0.35 + 0.15 * n.y;

    return m.albedo * (dif * vec3(1.2, 1.1, 0.95) + amb) + 0.2 * spe * m.albedo;
}

mat3 setCamera(in vec3 ro, in vec3 ta, float cr)
{
    vec3 cw = normalize(ta - ro);
    vec3 cp = vec3(sin(cr), cos(cr), 0.0);
    vec3 cu = normalize(cross(cw, cp));
    vec3 cv = cross(cu, cw);
    return mat3(cu, cv, cw);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec3 ro = vec3(2.1, 1.1, 2.3);
    vec3 ta = vec3(0.0);
    mat3 ca = setCamera(ro, ta, 0.0);

    vec3 tot = vec3(0.0);
    for (int m = 0; m < AA; m++)
    for (int n = 0; n < AA; n++)
    {
        vec2 o = (vec2(float(m), float(n)) + 0.5) / float(AA) - 0.5;
        vec2 p = (2.0 * (fragCoord + o) - iResolution.xy) / iResolution.y;
        Ray ray = Ray(ro, ca * normalize(vec3(p, 2.5)));
        vec3 col = shade(ray, castRay(ray));
        tot += pow(clamp(col, 0.0, 1.0), vec3(0.4545));
    }
    fragColor = vec4(tot / float(AA * AA), 1.0);
}
