// Imitates: the many "twisted tower" Shadertoys built on IQ's opTwist:
// a rounded box twisted about y, the twist phase animated with Shadertoy's
// undeclared `iTime`, a rot() helper returning mat2, `vec2 map(vec3 p)`
// with a material id, and a calcNormal() that sdfwb never calls.
//
// Why non-conservative: opTwist turns each horizontal slice by k*y. A
// point at distance t from the axis, measured along a face of the box,
// then moves sideways by k*t per unit of height, so |grad f| reaches
// sqrt(1 + (k t)^2). With k = 6 and t up to 0.3 (the half width) that is
// about 2.1 beside the faces, over a large part of the cube and for any
// iTime (the phase only adds a constant angle). No jumps, no plateau, no
// NaN: rotations and the rounded box are smooth and finite.
// expect: entry=map flags=non-conservative animated=yes

mat2 rot(float a) {
    float c = cos(a), s = sin(a);
    return mat2(c, -s, s, c);
}

float sdRoundBox(vec3 p, vec3 b, float r) {
    vec3 q = abs(p) - b + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

vec3 opTwist(vec3 p, float k) {
    vec2 xz = rot(k*p.y + iTime)*p.xz;
    return vec3(xz.x, p.y, xz.y);
}

vec2 map(vec3 p) {
    vec3 q = opTwist(p, 6.0);
    float tower = sdRoundBox(q, vec3(0.3, 0.8, 0.3), 0.05);
    return vec2(tower, 3.0);
}

vec3 calcNormal(vec3 p) {
    const float h = 0.0001;
    const vec2 k = vec2(1, -1);
    return normalize(k.xyy*map(p + k.xyy*h).x +
                     k.yyx*map(p + k.yyx*h).x +
                     k.yxy*map(p + k.yxy*h).x +
                     k.xxx*map(p + k.xxx*h).x);
}
