// Imitates: a whole Shadertoy in The Art of Code's tutorial layout whose scene takes more than the
// point: `vec2 Scene(vec3 p, vec3 tilt)` (distance and a material id) turned by a tilt that
// mainImage computes from iMouse (the plate at rest until the mouse is pressed) and hands down
// through `RayMarch(ro, rd, tilt)` and `GetNormal(p, tilt)`, which pass it on unchanged. A cake
// stand: a flat plate, a cylinder of cake on it, a ball on top, all turned by the tilt.
//
// Issue 47, class 1 with a parameter after the point: the distance function is Scene, found from
// RayMarch's loop (`dO += dS * 0.8`); its tilt comes from mainImage's code before the call
// (`vec3 tilt = vec3((m.y - 0.5) * 0.6, 0., (m.x - 0.5) * -0.6)`), which sdfwb runs in the field's
// wrapper with mainImage's inputs at rest (iMouse 0: m = 0.5, no tilt).
//
// Why the audit should find it clean: sdCylinder (IQ's capped cylinder) and the sphere are exact,
// the tilt is a rotation (an isometry, here the identity), and min() joins them; everything within
// |x|, |z| <= 0.8, -0.1 <= y <= 0.62, so the field grows outside: no flag. No iTime anywhere:
// not animated.
// expect: entry=Scene flags=none animated=no

#define MAX_STEPS 120
#define MAX_DIST 20.
#define SURF_DIST .001

mat2 Rot(float a) {
    float s = sin(a), c = cos(a);
    return mat2(c, -s, s, c);
}

float sdCylinder(vec3 p, float h, float r) {
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(r, h);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

vec2 Scene(vec3 p, vec3 tilt) {
    p.yz *= Rot(tilt.x);
    p.xy *= Rot(tilt.z);
    float plate = sdCylinder(p - vec3(0., -0.05, 0.), 0.04, 0.8);
    float cake = sdCylinder(p - vec3(0., 0.15, 0.), 0.16, 0.5);
    float ball = length(p - vec3(0., 0.47, 0.)) - 0.15;
    vec2 res = vec2(plate, 1.);
    if (cake < res.x) res = vec2(cake, 2.);
    if (ball < res.x) res = vec2(ball, 3.);
    return res;
}

vec2 RayMarch(vec3 ro, vec3 rd, vec3 tilt) {
    float dO = 0.;
    float mat = 0.;
    for (int i = 0; i < MAX_STEPS; i++) {
        vec3 p = ro + rd * dO;
        vec2 res = Scene(p, tilt);
        float dS = res.x;
        mat = res.y;
        dO += dS * 0.8;
        if (dO > MAX_DIST || abs(dS) < SURF_DIST) break;
    }
    return vec2(dO, mat);
}

vec3 GetNormal(vec3 p, vec3 tilt) {
    float d = Scene(p, tilt).x;
    vec2 e = vec2(.001, 0);
    vec3 n = d - vec3(Scene(p - e.xyy, tilt).x, Scene(p - e.yxy, tilt).x, Scene(p - e.yyx, tilt).x);
    return normalize(n);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (fragCoord - .5 * iResolution.xy) / iResolution.y;
    vec2 m = iMouse.xy / iResolution.xy;
    if (iMouse.z <= 0.) m = vec2(.5);
    vec3 tilt = vec3((m.y - .5) * .6, 0., (m.x - .5) * -.6);

    vec3 ro = vec3(0, 1.6, -2.4);
    vec3 f = normalize(vec3(0, .15, 0) - ro);
    vec3 r = normalize(cross(vec3(0, 1, 0), f));
    vec3 u = cross(f, r);
    vec3 rd = normalize(f * 1.5 + uv.x * r + uv.y * u);

    vec2 res = RayMarch(ro, rd, tilt);
    vec3 col = vec3(.75, .8, .9) - .3 * uv.y;
    if (res.x < MAX_DIST) {
        vec3 p = ro + rd * res.x;
        vec3 n = GetNormal(p, tilt);
        vec3 albedo = res.y < 1.5 ? vec3(.9) : (res.y < 2.5 ? vec3(.8, .5, .3) : vec3(.9, .1, .2));
        col = albedo * (.2 + .8 * clamp(dot(n, normalize(vec3(.4, .9, -.3))), 0., 1.));
    }
    fragColor = vec4(pow(col, vec3(.4545)), 1.);
}
