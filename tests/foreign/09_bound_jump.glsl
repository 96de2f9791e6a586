// Imitates: demoscene / Fragmentarium-era "bounding sphere" early outs:
// `if (r > BOUND) return r - something;` in front of an expensive `de()`,
// with the constant hand-tuned rather than derived (here: pretending the
// object is a ball of radius 0.5 when far away).
//
// Why discontinuous: at |p| = 0.9 the code switches from the detailed
// field (three crossed bars reaching 0.7 from the centre, 0.3 thick, plus
// a centre ball) to length(p) - 0.5 = 0.4. The detailed field there ranges
// from about 0.17 (near the bar ends) to about 0.52 (on the diagonals) and
// equals 0.4 only on curves, so the field jumps, by up to ~0.23, across
// almost all of the sphere |p| = 0.9, which lies inside the cube. Both
// pieces are 1-Lipschitz and finite; only the switch is wrong.
// expect: entry=de flags=discontinuous animated=no

#define BOUND 0.9

float sdBox(vec3 p, vec3 b)
{
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

float de(vec3 p)
{
    float r = length(p);
    if (r > BOUND) return r - 0.5;   // far away: "it's roughly a ball"

    float d = sdBox(p, vec3(0.7, 0.15, 0.15));
    d = min(d, sdBox(p, vec3(0.15, 0.7, 0.15)));
    d = min(d, sdBox(p, vec3(0.15, 0.15, 0.7)));
    d = min(d, r - 0.3);
    return d;
}
