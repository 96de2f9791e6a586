// Imitates: the first CSG example of most SDF tutorials ("intersection is
// max"): two overlapping spheres intersected into a lens, sdSphere and
// opIntersection helpers, `float sdf(vec3 p)` entry.
//
// Why the audit should find it clean: max of two exact sphere fields is
// continuous and 1-Lipschitz. It has a kink -- the gradient turns abruptly
// on the plane x = 0, where the two spheres' fields are equal, including
// along the lens's sharp rim -- but no jump, no plateau and no NaN; kinks
// are not flagged. Outside, the field grows like the farther sphere's.
// expect: entry=sdf flags=none animated=no

float sdSphere(vec3 p, float r)
{
    return length(p) - r;
}

float opIntersection(float a, float b)
{
    return max(a, b);
}

float sdf(vec3 p)
{
    float a = sdSphere(p - vec3(-0.35, 0.0, 0.0), 0.7);
    float b = sdSphere(p - vec3( 0.35, 0.0, 0.0), 0.7);
    return opIntersection(a, b);
}
