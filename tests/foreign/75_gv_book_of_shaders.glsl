// Author: sdfwb corpus (written for the tests, in the style of The Book of Shaders)
// Title: bobbing pearl in a rocking ring
//
// Imitates: a shader written for The Book of Shaders' editor and run with glslViewer, the two
// sharing one dialect: `#ifdef GL_ES` / `precision mediump float;` / `#endif` (WebGL needs the
// precision, desktop GL has no GL_ES), the host's inputs declared by the file under the u_
// names (`uniform vec2 u_resolution; uniform vec2 u_mouse; uniform float u_time;`, the mouse in
// pixels), glslViewer's `varying vec2 v_texcoord;` (declared, unused), and a plain
// `void main()` writing gl_FragColor from gl_FragCoord. No mainImage: the host calls main. The
// shader carries its own sphere tracer in main: a look-at camera that orbits with u_mouse, a
// loop `float d = getDist(p); ... t += d;`, getNormal() by central differences, a diffuse key
// light, a soft shadow and a rim term.
//
// Host support: sdfwb treats the host's `void main()` as Shadertoy's mainImage, and u_time as
// the time. The distance function has no conventional name (`getDist`), so the entry is the
// function main's own march steps by, as for issue 47's class 1.
//
// Why the audit should find it clean: a ball (exact) bobbing on y by 0.15 sin(1.3 u_time), a
// torus (exact) turned about z by 0.4 sin(u_time) (a rotation, an isometry) and a cylinder stub
// (exact), joined by IQ's polynomial smooth minimum, whose gradient h grad a + (1 - h) grad b is
// a convex mix of unit vectors: |grad| <= 1, continuous. Everything lies within |x|, |z| <= 0.8,
// -0.7 <= y <= 0.6, so the field grows outside it; no NaN. u_time is in the field: animated.
// expect: entry=getDist flags=none animated=yes

#ifdef GL_ES
precision mediump float;
#endif

uniform vec2 u_resolution;
uniform vec2 u_mouse;
uniform float u_time;

varying vec2 v_texcoord;

#define MAX_STEPS 120
#define MAX_DIST 20.0
#define SURF_DIST 0.0005

mat2 rotate2d(float _angle) {
    return mat2(cos(_angle), -sin(_angle),
                sin(_angle), cos(_angle));
}

float sphereDist(vec3 p, float r) {
    return length(p) - r;
}

float torusDist(vec3 p, vec2 t) {
    vec2 q = vec2(length(p.xz) - t.x, p.y);
    return length(q) - t.y;
}

float cylinderDist(vec3 p, float h, float r) {
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(r, h);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

// polynomial smooth min (k = blend radius)
float smoothMin(float a, float b, float k) {
    float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return mix(b, a, h) - k * h * (1.0 - h);
}

float getDist(vec3 p) {
    // the pearl bobs up and down
    vec3 pearlPos = p - vec3(0.0, 0.15 * sin(u_time * 1.3), 0.0);
    float pearl = sphereDist(pearlPos, 0.32);

    // the ring rocks around the z axis
    vec3 ringPos = p;
    ringPos.xy = rotate2d(0.4 * sin(u_time)) * ringPos.xy;
    float ring = torusDist(ringPos, vec2(0.62, 0.08));

    // a short stand below
    float stand = cylinderDist(p - vec3(0.0, -0.55, 0.0), 0.15, 0.22);

    float d = smoothMin(pearl, ring, 0.12);
    d = smoothMin(d, stand, 0.1);
    return d;
}

vec3 getNormal(vec3 p) {
    vec2 e = vec2(0.001, 0.0);
    vec3 n = getDist(p) - vec3(getDist(p - e.xyy),
                               getDist(p - e.yxy),
                               getDist(p - e.yyx));
    return normalize(n);
}

float softShadow(vec3 ro, vec3 rd, float k) {
    float res = 1.0;
    float t = 0.02;
    for (int i = 0; i < 48; i++) {
        float h = getDist(ro + rd * t);
        res = min(res, k * h / t);
        t += clamp(h, 0.01, 0.2);
        if (res < 0.001 || t > 4.0) break;
    }
    return clamp(res, 0.0, 1.0);
}

mat3 lookAt(vec3 eye, vec3 target) {
    vec3 f = normalize(target - eye);
    vec3 r = normalize(cross(f, vec3(0.0, 1.0, 0.0)));
    vec3 u = cross(r, f);
    return mat3(r, u, f);
}

void main() {
    vec2 st = (gl_FragCoord.xy - 0.5 * u_resolution.xy) / u_resolution.y;
    vec2 mouse = u_mouse / u_resolution;

    // orbit the camera with the mouse (glslViewer reports it in pixels)
    float yaw = 0.6 + 6.2831 * mouse.x;
    float pitch = 0.35 + 0.6 * mouse.y;
    vec3 eye = 3.2 * vec3(sin(yaw) * cos(pitch), sin(pitch), cos(yaw) * cos(pitch));
    vec3 rd = lookAt(eye, vec3(0.0)) * normalize(vec3(st, 1.6));

    // sphere tracing
    float t = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        vec3 p = eye + rd * t;
        float d = getDist(p);
        if (d < SURF_DIST || t > MAX_DIST) break;
        t += d;
    }

    vec3 color = mix(vec3(0.92, 0.9, 0.85), vec3(0.55, 0.62, 0.75), st.y + 0.5);
    if (t < MAX_DIST) {
        vec3 p = eye + rd * t;
        vec3 n = getNormal(p);
        vec3 light = normalize(vec3(0.6, 0.9, 0.4));
        float dif = clamp(dot(n, light), 0.0, 1.0);
        dif *= softShadow(p + n * 0.002, light, 8.0);
        float rim = pow(1.0 - clamp(dot(n, -rd), 0.0, 1.0), 3.0);
        vec3 albedo = p.y > -0.38 ? vec3(0.95, 0.88, 0.8) : vec3(0.35, 0.3, 0.28);
        color = albedo * (0.2 + 0.8 * dif) + 0.25 * rim;
    }

    color = pow(color, vec3(0.4545));
    gl_FragColor = vec4(color, 1.0);
}
