// Imitates: the Image tab of a multi-tab Shadertoy whose helpers live in
// its "Common" tab, saved as two files: the Common tab's code in
// lib/shadertoy_common.glsl (hashes, rot2D(), sdBox()/sdRoundBox()/
// sdSphere()/sdCapsule(), opSmoothUnion(), a `#define PI`), brought back
// in front of the Image tab's code by an #include at the top, as
// Shadertoy itself prepends Common to every pass. The Image tab: a tilted
// rounded box with blobs melting into it (positions and sizes from the
// Common tab's hashes), `float map(vec3 p)`, a raymarcher, soft shadows,
// and a fixed IQ-style camera (setCamera(ro, ta, 0.0), focal 2.4) over a
// sky that depends on rd.y only, so the picture can be compared with
// sdfwb's tracer.
//
// Why the audit should find it clean: the rounded box, spheres and
// capsule are exact; rot2D() is a rotation (an isometry); the polynomial
// smooth union is 1-Lipschitz (its gradient is h grad a + (1-h) grad b,
// a convex mix: the terms from h's own gradient cancel) and continuous.
// The hashes only place the blobs, the same everywhere in space, inside
// [-0.8, 0.8] on x and z and [-0.6, 0.7] on y. So: continuous, |grad| <= 1,
// growing outside the cube, no NaN. No iTime anywhere (the Common tab
// cannot use it): not animated.
// expect: entry=map flags=none animated=no
// picture: eye=-1.9,1.3,2.5 target=0,-0.05,0 focal=2.4

#include "lib/shadertoy_common.glsl"

#define BLOBS 5

float map(vec3 p)
{
    // a tilted rounded box...
    vec3 q = p;
    q.xz *= rot2D(PI / 6.0);
    q.xy *= rot2D(0.2);
    float d = sdRoundBox(q, vec3(0.5, 0.3, 0.5), 0.08);

    // ...with blobs melting into it
    for (int i = 0; i < BLOBS; i++)
    {
        vec3 c = (hash31(float(i) + 3.0) - 0.5) * vec3(1.2, 0.8, 1.2);
        float r = 0.1 + 0.08 * hash11(float(i) + 11.0);
        d = opSmoothUnion(d, sdSphere(p - c, r), 0.12);
    }

    // and a chimney on top
    d = opSmoothUnion(d, sdCapsule(p, vec3(0.0, 0.2, 0.0), vec3(0.1, 0.62, 0.1), 0.08), 0.1);
    return d;
}

vec3 calcNormal(vec3 p)
{
    vec2 e = vec2(EPSILON, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

float raymarch(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < 256; i++)
    {
        float h = map(ro + rd * t);
        if (abs(h) < 0.0001 * t) return t;
        t += h;
        if (t > 20.0) break;
    }
    return -1.0;
}

float softShadow(vec3 ro, vec3 rd)
{
    float res = 1.0;
    float t = 0.02;
    for (int i = 0; i < 40; i++)
    {
        float h = map(ro + rd * t);
        res = min(res, 8.0 * h / t);
        t += clamp(h, 0.02, 0.2);
        if (res < 0.001 || t > 3.0) break;
    }
    return clamp(res, 0.0, 1.0);
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
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    vec3 ro = vec3(-1.9, 1.3, 2.5);
    vec3 ta = vec3(0.0, -0.05, 0.0);
    mat3 ca = setCamera(ro, ta, 0.0);
    vec3 rd = ca * normalize(vec3(p, 2.4));

    vec3 col = vec3(0.75, 0.8, 0.9) + 0.15 * rd.y;

    float t = raymarch(ro, rd);
    if (t > 0.0)
    {
        vec3 pos = ro + rd * t;
        vec3 nor = calcNormal(pos);
        vec3 alb = palette(0.5 + 0.6 * pos.y, vec3(0.6, 0.45, 0.15), vec3(0.3, 0.25, 0.1),
                           vec3(1.0), vec3(0.0, 0.1, 0.2));
        vec3 lig = normalize(vec3(-0.3, 0.8, 0.5));
        float dif = clamp(dot(nor, lig), 0.0, 1.0) * softShadow(pos + 0.001 * nor, lig);
        float amb = 0.3 + 0.2 * nor.y;
        vec3 hal = normalize(lig - rd);
        float spe = pow(clamp(dot(nor, hal), 0.0, 1.0), 32.0) * dif;
        col = alb * (1.3 * dif + amb) + 0.3 * spe * alb;
    }

    fragColor = vec4(pow(clamp(col, 0.0, 1.0), vec3(0.4545)), 1.0);
}
