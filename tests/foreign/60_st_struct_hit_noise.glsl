// Imitates: a generated "studio" Shadertoy as tools and beginners write them: a `struct Hit`
// carrying the distance and a material number out of `Hit map(vec3 p)`, the march reading `h.d`,
// a helper called `noise2` (a free name in GLSL ES, a deprecated built-in of desktop GLSL 4.30
// with another return type, which glslang refuses to see redefined), and a `getMaterial` with an
// `out` parameter. Issue 47's classes: the entry found from the march through a struct member,
// and a built-in's name reused by the file.
//
// Why the audit should find it clean: a ball and a box with rounded edges joined by min(), both
// exact distances (|grad| = 1, continuous), inside the cube (the ball within 0.45 of (0.3, 0.1,
// 0), the box within 0.35 + 0.05 of (-0.35, -0.1, 0)); noise2 only tints the sky. No iTime in
// the map, but mainImage turns the camera with it: animated, as the README's rule says.
// expect: entry=map flags=none animated=yes

float hash(vec2 p) {
    p = fract(p * vec2(234.34, 435.346));
    p += dot(p, p + 34.23);
    return fract(p.x * p.y);
}

float noise2(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    f = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash(i), hash(i + vec2(1.0, 0.0)), f.x), mix(hash(i + vec2(0.0, 1.0)), hash(i + vec2(1.0, 1.0)), f.x), f.y);
}

float sdRoundBox(vec3 p, vec3 b, float r) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

struct Hit {
    float d;
    int mat;
};

Hit map(vec3 p) {
    Hit h;
    h.d = length(p - vec3(0.3, 0.1, 0.0)) - 0.45;
    h.mat = 1;
    float box = sdRoundBox(p - vec3(-0.35, -0.1, 0.0), vec3(0.3), 0.05);
    if (box < h.d) {
        h.d = box;
        h.mat = 2;
    }
    return h;
}

void getMaterial(int id, out vec3 albedo) {
    albedo = id == 1 ? vec3(0.9, 0.3, 0.2) : vec3(0.2, 0.5, 0.9);
}

vec3 calcNormal(vec3 p) {
    const vec2 e = vec2(0.0005, -0.0005);
    return normalize(e.xyy * map(p + e.xyy).d + e.yyx * map(p + e.yyx).d + e.yxy * map(p + e.yxy).d +
                     e.xxx * map(p + e.xxx).d);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float a = 0.3 * iTime;
    vec3 ro = vec3(3.0 * sin(a), 1.0, 3.0 * cos(a));
    vec3 ww = normalize(-ro), uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0))), vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 2.0 * ww);
    vec3 col = vec3(0.6, 0.7, 0.9) - 0.2 * noise2(uv * 8.0);
    float t = 0.0;
    Hit h;
    for (int i = 0; i < 128; i++) {
        h = map(ro + rd * t);
        if (h.d < 0.001 || t > 20.0) break;
        t += h.d;
    }
    if (t < 20.0) {
        vec3 p = ro + rd * t, n = calcNormal(p), albedo;
        getMaterial(h.mat, albedo);
        col = albedo * (0.2 + 0.8 * clamp(dot(n, normalize(vec3(0.5, 0.8, 0.3))), 0.0, 1.0));
    }
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
