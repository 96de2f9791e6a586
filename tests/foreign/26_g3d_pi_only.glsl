// Imitates: an original sdf-explorer scene that looks like plain GLSL
// (vec3, no Point3/float3/lerp/saturate, no includes) but still leans on
// the host's predefined `pi` -- once, deep inside a helper, where it is
// easy to miss. A gear: a disc with teeth repeated around the y axis.
//
// Why the audit should find it clean: the angular repetition is a
// piecewise rotation; each tooth is centred on its sector's mid-line and
// mirror-symmetric about it, so neighbouring sectors agree on the seams
// (continuous, 1-Lipschitz). The 2D profile (disc with a bore, union teeth
// via min/max) is extruded with IQ's exact extrusion, which keeps the
// Lipschitz constant 1. Bounded, finite.
// expect: entry=sdf flags=none animated=no

float box2(vec2 p, vec2 b) {
    vec2 d = abs(p) - b;
    return length(max(d, 0.0)) + min(max(d.x, d.y), 0.0);
}

// Folds the plane into one of n sectors, the first one centred on +x.
vec2 sectorFold(vec2 q, float n) {
    float r = length(q);
    float a = atan(q.y, q.x);
    float width = 2.0 * pi / n;
    a = mod(a + 0.5 * width, width) - 0.5 * width;
    return r * vec2(cos(a), sin(a));
}

float gearProfile(vec2 q) {
    float disc = length(q) - 0.55;
    float bore = 0.15 - length(q);
    vec2 f = sectorFold(q, 14.0);
    float tooth = box2(f - vec2(0.6, 0.0), vec2(0.1, 0.05));
    return max(min(disc, tooth), bore);
}

float extrude(float d2, float y, float h) {
    vec2 w = vec2(d2, abs(y) - h);
    return min(max(w.x, w.y), 0.0) + length(max(w, 0.0));
}

float sdf(vec3 p) {
    return extrude(gearProfile(p.xz), p.y, 0.08);
}
