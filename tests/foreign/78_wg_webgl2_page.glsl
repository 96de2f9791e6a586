#version 300 es
precision highp float;

// Imitates: the fragment shader of a hand-written WebGL2 page (a <script type="x-shader/x-fragment">
// block a page's JavaScript compiles and feeds): `#version 300 es` and `precision highp float;`
// first, the page's uniforms declared by the shader itself under Shadertoy's names because the
// author ported from there (`uniform vec3 iResolution; uniform float iTime; uniform vec4 iMouse;`),
// its own output `out vec4 fragColor;`, and `void main()` reading gl_FragCoord: a fixed-step
// budget sphere tracer, IQ's tetrahedral normal, a key light with a soft shadow, a sky fill and
// a fog, the camera turning slowly with iTime and dragged with iMouse.
//
// Host support: sdfwb treats `void main()` as Shadertoy's mainImage, and the shader's own
// declarations of iResolution, iTime and iMouse as the inputs it already provides (not declared
// twice). The entry is `scene`, a conventional name.
//
// Why the audit should find it clean: a rounded box (IQ's exact sdRoundBox, a pedestal) with a
// groove cut along its top by max(pedestal, -slot), the slot an exact capsule (max keeps
// |grad| <= 1 and continuity), a ball above it, and a ring (an exact torus stood on its edge
// around the ball, its foot in the groove) are joined by IQ's quadratic smooth minimum, whose
// gradient is (1 - h/2) grad a + (h/2) grad b: a convex mix, |grad| <= 1, continuous.
// Everything lies within |x| <= 0.7, -0.6 <= y <= 0.65, |z| <= 0.45: the field grows outside; no
// NaN. The field is static, but iTime appears in the file outside comments
// (main turns the camera with it), and sdfwb decides animation from the text: animated.
// expect: entry=scene flags=none animated=yes

uniform vec3 iResolution;
uniform float iTime;
uniform vec4 iMouse;

out vec4 fragColor;

const int MAX_STEPS = 160;
const float MAX_DIST = 12.0;

float sdRoundBox(vec3 p, vec3 b, float r) {
    vec3 q = abs(p) - b + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float sdTorus(vec3 p, vec2 t) {
    vec2 q = vec2(length(p.xz) - t.x, p.y);
    return length(q) - t.y;
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r) {
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h) - r;
}

float smin(float a, float b, float k) {
    float h = max(k - abs(a - b), 0.0) / k;
    return min(a, b) - h * h * k * 0.25;
}

float scene(vec3 p) {
    // pedestal with a slot for the ring
    float pedestal = sdRoundBox(p - vec3(0.0, -0.45, 0.0), vec3(0.55, 0.12, 0.35), 0.04);
    float slot = sdCapsule(p, vec3(-0.5, -0.33, 0.0), vec3(0.5, -0.33, 0.0), 0.09);
    pedestal = max(pedestal, -slot);

    // a ball floating in the ring
    float ball = length(p - vec3(0.0, 0.0, 0.0)) - 0.24;

    // a ring standing on its edge, in the slot
    vec3 q = p - vec3(0.0, 0.08, 0.0);
    float ring = sdTorus(q.xzy, vec2(0.5, 0.06));

    float d = smin(pedestal, ball, 0.1);
    d = smin(d, ring, 0.05);
    return d;
}

vec3 calcNormal(vec3 p) {
    const float h = 0.0005;
    const vec2 k = vec2(1.0, -1.0);
    return normalize(k.xyy * scene(p + k.xyy * h) +
                     k.yyx * scene(p + k.yyx * h) +
                     k.yxy * scene(p + k.yxy * h) +
                     k.xxx * scene(p + k.xxx * h));
}

float softShadow(vec3 ro, vec3 rd) {
    float res = 1.0, t = 0.01;
    for (int i = 0; i < 64; i++) {
        float h = scene(ro + rd * t);
        res = min(res, 10.0 * h / t);
        t += clamp(h, 0.005, 0.1);
        if (res < 0.002 || t > 3.0) break;
    }
    return clamp(res, 0.0, 1.0);
}

float raymarch(vec3 ro, vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        float d = scene(ro + rd * t);
        if (abs(d) < 0.0002 * t || t > MAX_DIST) break;
        t += d;
    }
    return t;
}

void main() {
    vec2 p = (2.0 * gl_FragCoord.xy - iResolution.xy) / iResolution.y;

    float yaw = 0.55 + 0.15 * iTime;
    if (iMouse.z > 0.0) yaw = 6.2831 * iMouse.x / iResolution.x;
    vec3 ro = vec3(3.0 * sin(yaw), 1.3, 3.0 * cos(yaw));
    vec3 ta = vec3(0.0, -0.1, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(p.x * uu + p.y * vv + 2.0 * ww);

    vec3 sky = vec3(0.6, 0.72, 0.9) - 0.3 * rd.y;
    vec3 col = sky;
    float t = raymarch(ro, rd);
    if (t < MAX_DIST) {
        vec3 pos = ro + rd * t;
        vec3 nor = calcNormal(pos);
        vec3 lig = normalize(vec3(-0.4, 0.8, 0.5));
        float dif = clamp(dot(nor, lig), 0.0, 1.0) * softShadow(pos + nor * 0.003, lig);
        float fill = 0.5 + 0.5 * nor.y;
        vec3 mate = pos.y < -0.3 ? vec3(0.3, 0.22, 0.16) : vec3(0.75, 0.7, 0.6);
        col = mate * (1.3 * dif * vec3(1.0, 0.95, 0.85) + 0.3 * fill * sky);
        col = mix(col, sky, 1.0 - exp(-0.02 * t * t));
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
