// Imitates: tutorial / forum code that makes an ellipsoid by scaling the
// sphere formula, `length(p/r) - 1.0`, without IQ's correction (his
// article shows why that is not a distance), next to an exact sdTorus;
// `float sdf(vec3 p)` entry, sdEllipsoid()/sdTorus() helpers.
//
// Why non-conservative: grad of length(p/r) is (p/r^2)/|p/r|; along the
// axis with the smallest radius (0.25, the y axis) its length is 1/0.25 = 4,
// and since every radius is <= 0.8 it is >= 1/0.8 = 1.25 everywhere the
// ellipsoid term is the nearer one. Continuous and finite (the only singular point is the centre,
// a single point), and it grows outside, so no other flag.
// expect: entry=sdf flags=non-conservative animated=no

float sdEllipsoid(vec3 p, vec3 r)
{
    return length(p/r) - 1.0;   // "good enough"
}

float sdTorus(vec3 p, vec2 t)
{
    vec2 q = vec2(length(p.xz) - t.x, p.y);
    return length(q) - t.y;
}

float sdf(vec3 p)
{
    float body = sdEllipsoid(p - vec3(0.0, 0.2, 0.0), vec3(0.8, 0.25, 0.5));
    float ring = sdTorus(p - vec3(0.0, -0.45, 0.0), vec2(0.45, 0.08));
    return min(body, ring);
}
