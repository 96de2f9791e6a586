// Shadertoy style with iTime (never declared, as Shadertoy code does) and a smooth-min blend:
// stretching one axis makes the field over-estimate (|grad f| = stretch along y).
uniform float blend = 0.1;   // @range 0.0 0.4 @label "Blend radius"
uniform float stretch = 1.0; // @range 0.5 2.0

float opSmoothUnion(float d1, float d2, float k) {
    float h = clamp(0.5 + 0.5 * (d2 - d1) / max(k, 1e-6), 0.0, 1.0);
    return mix(d2, d1, h) - k * h * (1.0 - h);
}

vec2 map(vec3 pos) {
    pos.y *= stretch;
    float wobble = 0.05 * sin(iTime);
    float a = length(pos - vec3(0.35 + wobble, 0.0, 0.0)) - 0.3;
    float b = length(pos + vec3(0.35, 0.0, 0.0)) - 0.3;
    return vec2(opSmoothUnion(a, b, blend), 1.0);
}
