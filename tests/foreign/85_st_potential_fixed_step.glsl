// Imitates: an implicit-surface course's Shadertoy (blobs as in Wyvill's soft objects): the object
// is a potential, positive inside and negative outside, the sum of three skeleton points' compact
// falloffs less a threshold. `Trace` starts a little ahead of the eye, walks the ray in fixed steps
// of Epsilon, stops at the first sample where the potential is positive (`if (v > 0.0)`) and counts
// its steps; the normal is the potential's gradient by forward differences.
//
// Issue 47, a fixed-step march of a potential: the loop steps by a constant and stops where
// v = object(p) > 0.0, so sdfwb's field is 0.0 - v: negative inside, zero on the surface the shader
// draws, a level of the potential and not a distance.
//
// Why the audit should find it non-conservative and truncated: the falloff (1 - (r/R)^2)^3 falls
// at up to 1.72 / R per unit (at r = R / sqrt(5)), with R at most 0.9: steeper than 1.05 near each
// blob. Beyond R from every point the potential is 0 and the field a constant 0.45, a plateau
// within distance 3 of the surface. It is smooth (the falloff's first derivative is 0 at r = R)
// and finite. Nothing reads iTime.
// expect: entry=Trace flags=non-conservative,truncated animated=no

const int Steps = 400;
const float Epsilon = 0.01; // the march's step
const float T = 0.45;       // the iso-level
const float rA = 0.5;       // where the march starts
const float rB = 8.0;       // where it gives up

// Compact falloff: 1 at the centre, 0 (with a zero slope) from R on.
float falloff(float r, float R) {
    float x = clamp(r / R, 0.0, 1.0);
    float y = 1.0 - x * x;
    return y * y * y;
}

// A skeleton point c of energy e and radius R.
float point(vec3 p, vec3 c, float e, float R) {
    return e * falloff(length(p - c), R);
}

// The potential field of the object: positive inside.
float object(vec3 p) {
    float v = point(p, vec3(-0.35, 0.0, 0.0), 1.0, 0.9);
    v += point(p, vec3(0.35, 0.1, 0.0), 1.0, 0.8);
    v += point(p, vec3(0.0, -0.25, 0.3), 0.8, 0.7);
    return v - T;
}

vec3 ObjectNormal(vec3 p) {
    float eps = 0.0001;
    float v = object(p);
    vec3 n = vec3(object(vec3(p.x + eps, p.y, p.z)) - v, object(vec3(p.x, p.y + eps, p.z)) - v,
                  object(vec3(p.x, p.y, p.z + eps)) - v);
    return -normalize(n); // the potential grows inward
}

float Trace(vec3 o, vec3 u, out bool h, out int s) {
    h = false;
    float t = rA;
    for (int i = 0; i < Steps; i++) {
        s = i;
        vec3 p = o + t * u;
        float v = object(p);
        if (v > 0.0) {
            h = true;
            break;
        }
        t += Epsilon;
        if (t > rB) break;
    }
    return t;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 pixel = (-iResolution.xy + 2.0 * fragCoord) / iResolution.y;
    vec3 o = vec3(0.0, 0.3, 2.5);
    vec3 u = normalize(vec3(pixel, -1.8));
    bool hit;
    int s;
    float t = Trace(o, u, hit, s);
    vec3 col = vec3(0.8, 0.85, 0.9) - 0.3 * pixel.y;
    if (hit) {
        vec3 n = ObjectNormal(o + t * u);
        float diffuse = 0.5 * (1.0 + dot(n, normalize(vec3(1.0, 1.0, 0.5))));
        col = mix(vec3(0.9, 0.5, 0.2), vec3(1.0, 0.9, 0.6), diffuse) * diffuse;
    }
    col *= 1.0 - 0.3 * float(s) / float(Steps);
    fragColor = vec4(col, 1.0);
}
