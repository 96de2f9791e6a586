// Imitates: the bounding-volume optimisation recommended in IQ's articles
// and used in many Shadertoys: test a cheap bound first and skip the
// detailed (here: carved) part far away -- written the careful way, with
// an `sdScene(vec3 p)` entry as in some tutorials.
//
// Why the audit should find it clean (continuous despite the early
// return): the object is a ball of radius 0.6 with three grooves carved by
// max(ball, -cutters). The cutters are clipped to radius 0.75, so for
// |p| >= 0.75 the carving term is <= 0 < |p| - 0.6 and the detailed field
// EQUALS length(p) - 0.6. The early return at |p| > 0.9 therefore returns
// exactly what the full code would: no jump at the switch. Ball, slabs,
// min and max are all 1-Lipschitz.
// expect: entry=sdScene flags=none animated=no

const float BALL_R = 0.6;
const float CUT_R = 0.75;    // cutters live inside this radius
const float SKIP_R = 0.9;    // beyond this the carving cannot matter

float smax(float a, float b)
{
    return max(a, b);
}

float grooves(vec3 p)
{
    vec3 a = abs(p) - 0.04;
    float slabs = min(a.x, min(a.y, a.z));
    return max(slabs, length(p) - CUT_R);
}

float sdScene(vec3 p)
{
    float r = length(p);
    float ball = r - BALL_R;
    if (r > SKIP_R) return ball;      // same value the carved field has here
    return smax(ball, -grooves(p));
}
