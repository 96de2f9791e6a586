// common_names.glsl -- a stress test for name clashes, written for sdfwb's
// tests in the general style of Shadertoy code (IQ, The Art of Code,
// hg_sdf, Fragmentarium habits mixed together). It DEFINES, as #define
// macros (object-like and function-like), global consts, globals, uniforms,
// structs and functions, the identifiers that public SDF code uses most
// often: map, scene, calcNormal, raymarch, march, trace, hash, noise, fbm,
// rot, smin, smax, opU, sdBox, sdSphere, iTime, time, PI, TAU, EPS,
// MAX_STEPS, Material, Hit, Ray, de, DE, fold, palette, shadow, ao, camera,
// render, mainImage, resolution, mouse, col, ro, rd, p, t, d, h, k, ... so
// whatever sdfwb composes around a user file must not collide with them.
// No GLSL built-in is redefined, and nothing starts with gl_ or sdfwb_.
//
// Why clean: the entry is sdf(), which calls scene() -> map(): a torus and
// a box that do not touch, joined with opU (min of exact SDFs), so the
// field is exact, continuous and finite, bounded inside the cube. No
// uniform, global variable or iTime enters it.
// expect: entry=sdf flags=none animated=no

// ---- object-like macros ----
#define MAX_STEPS 100
#define MAX_DIST 50.0
#define SURF_DIST 0.001
#define EPS 0.0005
#define EPSILON 1e-4
#define PI 3.14159265
#define TAU (2.0*PI)
#define PHI 1.61803399
#define AA 1
#define ZERO (min(int(iTime), 0))
#define HASHSCALE1 0.1031
#define FAR MAX_DIST
#define time iTime
#define lightDir normalize(light)
#define frac fract

// ---- function-like macros ----
#define saturate(x) clamp(x, 0.0, 1.0)
#define lerp(a, b, x) mix(a, b, x)
#define rot(a) mat2(cos(a), -sin(a), sin(a), cos(a))
#define normal(q) calcNormal(q)
#define sq(x) ((x)*(x))
#define DE(q) de(q)
#define R(q, a) q = cos(a)*q + sin(a)*vec2(q.y, -q.x)

// ---- uniforms ----
uniform vec2 resolution;
uniform vec4 mouse;
uniform float zoom;
uniform vec3 cameraPos;

// ---- global consts ----
const float iTime = 0.0;
const float eps = 1e-4;
const float k = 0.1;
const vec3 light = vec3(2.0, 3.0, -1.5);
const int iterations = 8;
const float scale = 2.0;

// ---- globals (written by the rendering helpers) ----
vec3 ro;
vec3 rd;
vec3 p;
vec3 pos;
vec3 col;
vec3 color;
vec3 position;
vec3 direction;
float t;
float d;
float h;
float dist;
int steps;

// ---- structs ----
struct Ray {
    vec3 ro;
    vec3 rd;
};

struct Hit {
    float t;
    float d;
    float id;
    vec3 pos;
};

struct Material {
    vec3 albedo;
    float roughness;
    float metallic;
};

struct Camera {
    vec3 eye;
    vec3 target;
    float fov;
};

struct Scene {
    Camera cam;
    vec3 sun;
    float fogDensity;
};

// ---- hashing and noise ----
float hash(float n) {
    return fract(sin(n)*43758.5453123);
}

float hash(vec2 q) {
    vec3 p3 = fract(vec3(q.xyx)*HASHSCALE1);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y)*p3.z);
}

vec3 hash3(vec3 q) {
    q = vec3(dot(q, vec3(127.1, 311.7, 74.7)),
             dot(q, vec3(269.5, 183.3, 246.1)),
             dot(q, vec3(113.5, 271.9, 124.6)));
    return fract(sin(q)*43758.5453123);
}

float rand(vec2 co) {
    return fract(sin(dot(co, vec2(12.9898, 78.233)))*43758.5453);
}

float noise(vec3 x) {
    vec3 i = floor(x);
    vec3 f = fract(x);
    f = f*f*(3.0 - 2.0*f);
    float n = i.x + i.y*57.0 + 113.0*i.z;
    return mix(mix(mix(hash(n + 0.0), hash(n + 1.0), f.x),
                   mix(hash(n + 57.0), hash(n + 58.0), f.x), f.y),
               mix(mix(hash(n + 113.0), hash(n + 114.0), f.x),
                   mix(hash(n + 170.0), hash(n + 171.0), f.x), f.y), f.z);
}

float fbm(vec3 x) {
    float v = 0.0;
    float a = 0.5;
    for (int i = ZERO; i < 5; i++) {
        v += a*noise(x);
        x *= 2.03;
        a *= 0.5;
    }
    return v;
}

// ---- transforms ----
mat2 rot2D(float a) {
    float c = cos(a), s = sin(a);
    return mat2(c, -s, s, c);
}

vec3 rotate(vec3 q, vec3 axis, float angle) {
    axis = normalize(axis);
    return mix(dot(axis, q)*axis, q, cos(angle)) + cross(axis, q)*sin(angle);
}

vec3 opRep(vec3 q, vec3 c) {
    return mod(q + 0.5*c, c) - 0.5*c;
}

vec3 fold(vec3 q) {
    if (q.x + q.y < 0.0) q.xy = -q.yx;
    if (q.x + q.z < 0.0) q.xz = -q.zx;
    if (q.y + q.z < 0.0) q.zy = -q.yz;
    return q;
}

vec3 boxFold(vec3 z, float limit) {
    return clamp(z, -limit, limit)*2.0 - z;
}

vec3 sphereFold(vec3 z, inout float dz) {
    float r2 = dot(z, z);
    float factor = r2 < 0.25 ? 4.0 : (r2 < 1.0 ? 1.0/r2 : 1.0);
    dz *= factor;
    return z*factor;
}

// ---- primitives and operators ----
float sdSphere(vec3 q, float r) {
    return length(q) - r;
}

float sdBox(vec3 q, vec3 b) {
    vec3 e = abs(q) - b;
    return length(max(e, 0.0)) + min(max(e.x, max(e.y, e.z)), 0.0);
}

float sdTorus(vec3 q, vec2 tr) {
    return length(vec2(length(q.xz) - tr.x, q.y)) - tr.y;
}

float sdPlane(vec3 q, vec3 n, float offset) {
    return dot(q, n) + offset;
}

float sdCapsule(vec3 q, vec3 a, vec3 b, float r) {
    vec3 pa = q - a, ba = b - a;
    float s = saturate(dot(pa, ba)/dot(ba, ba));
    return length(pa - ba*s) - r;
}

float smin(float a, float b, float kk) {
    float hh = max(kk - abs(a - b), 0.0)/kk;
    return min(a, b) - hh*hh*kk*0.25;
}

float smax(float a, float b, float kk) {
    return -smin(-a, -b, kk);
}

vec2 opU(vec2 a, vec2 b) {
    return a.x < b.x ? a : b;
}

float opS(float a, float b) {
    return max(-a, b);
}

float opI(float a, float b) {
    return max(a, b);
}

// ---- the scene ----
vec2 map(vec3 q) {
    vec2 res = vec2(sdTorus(q, vec2(0.5, 0.15)), 1.0);
    res = opU(res, vec2(sdBox(q - vec3(0.0, 0.45, 0.0), vec3(0.2)), 2.0));
    return res;
}

float scene(vec3 q) {
    return map(q).x;
}

// the entry; its parameter hides the global p declared above
float sdf(vec3 p) {
    return scene(p);
}

// a Mandelbox-like estimator that nothing uses for the shape
float de(vec3 q) {
    vec3 z = q;
    float dz = 1.0;
    for (int i = 0; i < iterations; i++) {
        z = boxFold(z, 1.0);
        z = sphereFold(z, dz);
        z = scale*z + q;
        dz = dz*abs(scale) + 1.0;
    }
    return length(z)/abs(dz);
}

vec3 gradient(vec3 q) {
    vec2 e = vec2(eps, 0.0);
    return vec3(scene(q + e.xyy) - scene(q - e.xyy),
                scene(q + e.yxy) - scene(q - e.yxy),
                scene(q + e.yyx) - scene(q - e.yyx))/(2.0*eps);
}

vec3 calcNormal(vec3 q) {
    return normalize(gradient(q));
}

Material material(float id) {
    Material m;
    m.albedo = id < 1.5 ? vec3(0.8, 0.3, 0.2) : vec3(0.2, 0.4, 0.8);
    m.roughness = 0.5;
    m.metallic = 0.0;
    return m;
}

// ---- marching ----
Hit raymarch(Ray ray) {
    Hit hit = Hit(0.0, 0.0, -1.0, ray.ro);
    for (int i = ZERO; i < MAX_STEPS; i++) {
        hit.pos = ray.ro + ray.rd*hit.t;
        vec2 m = map(hit.pos);
        hit.d = m.x;
        hit.id = m.y;
        if (abs(m.x) < SURF_DIST || hit.t > FAR) break;
        hit.t += m.x;
    }
    if (hit.t > FAR) hit.id = -1.0;
    return hit;
}

float march(vec3 o, vec3 dir) {
    float tt = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        float s = scene(o + dir*tt);
        if (s < EPS) break;
        tt += s;
        if (tt > MAX_DIST) break;
    }
    return tt;
}

float trace(vec3 o, vec3 dir) {
    return march(o, dir);
}

bool intersect(Ray ray, out Hit hit) {
    hit = raymarch(ray);
    return hit.id > 0.0;
}

// ---- shading ----
vec3 palette(float x, vec3 a, vec3 b, vec3 c, vec3 dd) {
    return a + b*cos(TAU*(c*x + dd));
}

float shadow(vec3 o, vec3 dir) {
    float tt = 0.02;
    for (int i = 0; i < MAX_STEPS && tt < 5.0; i++) {
        float s = scene(o + dir*tt);
        if (s < EPSILON) return 0.0;
        tt += s;
    }
    return 1.0;
}

float softshadow(vec3 o, vec3 dir, float mint, float maxt, float w) {
    float res = 1.0;
    float tt = mint;
    for (int i = 0; i < 64 && tt < maxt; i++) {
        float s = scene(o + dir*tt);
        res = min(res, s/(w*tt));
        tt += clamp(s, 0.005, 0.5);
        if (res < -1.0) break;
    }
    res = max(res, -1.0);
    return 0.25*(1.0 + res)*(1.0 + res)*(2.0 - res);
}

float calcAO(vec3 q, vec3 n) {
    float occ = 0.0;
    float sca = 1.0;
    for (int i = ZERO; i < 5; i++) {
        float hr = 0.01 + 0.12*float(i)/4.0;
        occ += (hr - scene(q + n*hr))*sca;
        sca *= 0.95;
    }
    return saturate(1.0 - 3.0*occ);
}

float ao(vec3 q, vec3 n) {
    return calcAO(q, n);
}

vec3 lighting(vec3 q, vec3 n, vec3 v, Material m) {
    vec3 ldir = lightDir;
    float diff = saturate(dot(n, ldir))*softshadow(q, ldir, 0.02, 5.0, 0.1);
    float spec = pow(saturate(dot(reflect(-ldir, n), v)), lerp(64.0, 8.0, m.roughness));
    float amb = 0.2*ao(q, n);
    return m.albedo*(diff + amb) + vec3(spec)*(1.0 - m.roughness);
}

vec3 shade(Hit hit, vec3 v) {
    vec3 n = normal(hit.pos);
    return lighting(hit.pos, n, v, material(hit.id));
}

mat3 camera(vec3 eye, vec3 target, float roll) {
    vec3 cw = normalize(target - eye);
    vec3 cp = vec3(sin(roll), cos(roll), 0.0);
    vec3 cu = normalize(cross(cw, cp));
    vec3 cv = cross(cu, cw);
    return mat3(cu, cv, cw);
}

Ray getRay(vec2 uv, Camera c) {
    mat3 m = camera(c.eye, c.target, 0.0);
    Ray ray;
    ray.ro = c.eye;
    ray.rd = m*normalize(vec3(uv, 1.0/tan(0.5*c.fov)));
    return ray;
}

vec3 render(Ray ray) {
    col = vec3(0.7, 0.8, 0.9) - 0.3*ray.rd.y;
    Hit hit;
    if (intersect(ray, hit)) {
        col = shade(hit, -ray.rd);
        col = mix(col, vec3(0.7, 0.8, 0.9), 1.0 - exp(-0.01*hit.t*hit.t));
    }
    return col;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0*fragCoord - resolution)/resolution.y;
    Scene sc;
    sc.cam = Camera(cameraPos + vec3(0.0, 0.5, -3.0)*max(zoom, 1.0), vec3(0.0), 0.9);
    sc.sun = lightDir;
    sc.fogDensity = 0.01;
    float spin = time + mouse.x*0.01;
    vec2 e2 = sc.cam.eye.xz;
    R(e2, spin);
    sc.cam.eye.xz = e2*rot(0.0)*rot2D(0.0);
    ro = sc.cam.eye;
    Ray ray = getRay(uv, sc.cam);
    rd = ray.rd;
    color = render(ray);
    color = pow(color, vec3(0.4545));
    color += 0.02*palette(hash(uv), vec3(0.5), vec3(0.5), vec3(1.0), vec3(0.0, 0.33, 0.67))*rand(uv)*AA;
    color += 0.0*(fbm(color) + hash3(color).x + sq(frac(PHI)) + de(ro) + DE(rd) + trace(ro, rd));
    color += 0.0*(sdSphere(ro, 1.0) + sdPlane(ro, vec3(0, 1, 0), 1.0) + sdCapsule(ro, vec3(0), vec3(1), 0.1));
    color += 0.0*(smax(1.0, 2.0, k) + opS(1.0, 2.0) + opI(1.0, 2.0) + opRep(ro, vec3(1)).x + fold(rd).x);
    color += 0.0*(rotate(rd, vec3(0, 1, 0), 1.0).x + shadow(ro, rd) + smin(1.0, 2.0, k));
    pos = ro; position = ro; direction = rd; p = ro;
    t = 0.0; d = 0.0; h = 0.0; dist = 0.0; steps = 0;
    fragColor = vec4(color, 1.0);
}
