// Imitates: IQ's exact sdRoundBox used as a whole scene, in a file that has
// BOTH a Shadertoy-style `float map(vec3 p)` and the `float sdf(vec3 p)`
// entry sdfwb looks for first (sdf wraps map, scaled down to the cube).
//
// Why the audit should find it clean (an exact SDF): IQ's rounded box is
// the exact Euclidean distance to a box with rounded edges, so |grad| = 1
// almost everywhere, the field is continuous, finite and grows outside.
// Uniform scaling, s*f(p/s), keeps it exact.
// expect: entry=sdf flags=none animated=no

float sdRoundBox(vec3 p, vec3 b, float r)
{
    vec3 q = abs(p) - b + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

// the Shadertoy original, in its own units
float map(vec3 p)
{
    return sdRoundBox(p, vec3(1.5, 1.0, 0.75), 0.3);
}

float sdf(vec3 p)
{
    const float s = 0.5;
    return s*map(p/s);
}
