// Imitates: macro-heavy Shadertoy / demoscene code: MAX_STEPS, MAX_DIST,
// EPS, PI, TAU as #defines, a rot(a) macro returning mat2, function-like
// macros for primitives and the smooth min (SPHERE, BOX, SMIN), #ifdef
// switches and an #if on a macro value; `vec2 map(vec3 p)` with a material
// id, plus a raymarch()/calcNormal() pair that sdfwb never calls. The
// "squash" trick scales a coordinate before calling a primitive without
// correcting the distance, as in many quick animations.
//
// Why non-conservative: the body is SPHERE(p * SQUASH, r) with SQUASH =
// (2, 1, 1): stretching x by 2 makes the gradient along x twice as large,
// so |grad f| reaches 2 on the body's sides (x direction) and is above 1.05
// wherever the body's gradient has a noticeable x component. Everything
// else (rotated box, smooth min) is 1-Lipschitz; the field is
// continuous, finite and bounded.
// expect: entry=map flags=non-conservative animated=no

#define MAX_STEPS 128
#define MAX_DIST 40.
#define EPS 1e-4
#define PI 3.14159265359
#define TAU (2.*PI)

#define USE_SMOOTH_UNION
#define SQUASH vec3(2., 1., 1.)

#define rot(a) mat2(cos(a), -sin(a), sin(a), cos(a))
#define SPHERE(p, r) (length(p) - (r))
#define BOX(p, b) (length(max(abs(p) - (b), 0.)) + min(max(max(abs(p).x - (b).x, abs(p).y - (b).y), abs(p).z - (b).z), 0.))
#define SMIN(a, b, k) (min(a, b) - pow(max((k) - abs((a) - (b)), 0.), 2.) * .25 / (k))

#if MAX_STEPS > 64
#define DETAIL 1.
#else
#define DETAIL 0.
#endif

vec2 map(vec3 p) {
    // squashed ball on top
    float body = SPHERE((p - vec3(0., .2, 0.)) * SQUASH, .45);

    // a box turned by 45 degrees underneath
    vec3 q = p - vec3(0., -.35, 0.);
    q.xz *= rot(TAU / 8.);
    float plinth = BOX(q, vec3(.3, .15, .3));

#ifdef USE_SMOOTH_UNION
    float d = SMIN(body, plinth, .05 + .05 * DETAIL);
#else
    float d = min(body, plinth);
#endif

    return vec2(d, body < plinth ? 1. : 2.);
}

float raymarch(vec3 ro, vec3 rd) {
    float t = 0.;
    for (int i = 0; i < MAX_STEPS; i++) {
        float h = map(ro + rd * t).x;
        if (h < EPS || t > MAX_DIST) break;
        t += h;
    }
    return t;
}

vec3 calcNormal(vec3 p) {
    vec2 e = vec2(EPS, 0.);
    return normalize(vec3(map(p + e.xyy).x - map(p - e.xyy).x,
                          map(p + e.yxy).x - map(p - e.yxy).x,
                          map(p + e.yyx).x - map(p - e.yyx).x));
}
