// Imitates: a typical beginner Shadertoy ("bouncing ball"), in the
// tutorial style of The Art of Code / many forks: MAX_STEPS, MAX_DIST
// and SURF_DIST #defines, Shadertoy's `iTime` used without a declaration
// (Shadertoy provides it; so does sdfwb), IQ's polynomial smin, a
// `struct Material` with a material() lookup, `vec2 map(vec3 p)` with the
// material id in .y, and GetNormal()/RayMarch() that sdfwb never calls.
//
// Why the audit should find it clean: the ball and the rounded floor slab
// are exact SDFs and IQ's polynomial smin is 1-Lipschitz (its gradient is
// a convex mix of the two gradients), so the distance is continuous with
// |grad| <= 1. iTime only moves the ball's centre (y between -0.25 and
// 0.45, radius 0.25), so the scene stays in the cube at every time.
// expect: entry=map flags=none animated=yes

#define MAX_STEPS 100
#define MAX_DIST 100.
#define SURF_DIST .001

#define MAT_FLOOR 1.
#define MAT_BALL 2.

struct Material {
    vec3 albedo;
    float roughness;
};

Material material(float id) {
    Material m;
    m.albedo = vec3(0.6);
    m.roughness = 0.8;
    if (id > 1.5) {
        m.albedo = vec3(0.9, 0.2, 0.1);
        m.roughness = 0.2;
    }
    return m;
}

float smin(float a, float b, float k) {
    float h = clamp(0.5 + 0.5*(b - a)/k, 0., 1.);
    return mix(b, a, h) - k*h*(1. - h);
}

float sdRoundBox(vec3 p, vec3 b, float r) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.)) + min(max(q.x, max(q.y, q.z)), 0.) - r;
}

vec2 map(vec3 p) {
    float bounce = abs(sin(iTime*3.));
    vec3 ballPos = vec3(0, -.25 + .7*bounce, 0);
    float ball = length(p - ballPos) - .25;

    float ground = sdRoundBox(p - vec3(0, -.65, 0), vec3(.8, .04, .8), .03);

    float d = smin(ball, ground, .15);
    float mat = ball < ground ? MAT_BALL : MAT_FLOOR;
    return vec2(d, mat);
}

float RayMarch(vec3 ro, vec3 rd) {
    float dO = 0.;
    for (int i = 0; i < MAX_STEPS; i++) {
        vec3 p = ro + rd*dO;
        float dS = map(p).x;
        dO += dS;
        if (dO > MAX_DIST || abs(dS) < SURF_DIST) break;
    }
    return dO;
}

vec3 GetNormal(vec3 p) {
    vec2 e = vec2(.001, 0);
    float d = map(p).x;
    vec3 n = d - vec3(
        map(p - e.xyy).x,
        map(p - e.yxy).x,
        map(p - e.yyx).x);
    return normalize(n);
}
