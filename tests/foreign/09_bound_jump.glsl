// Imitates: demoscene / Fragmentarium-era "bounding sphere" early outs:
// `if (r > BOUND) return r - something;` in front of an expensive `de()`,
// with the constant hand-tuned rather than derived (here: pretending the
// object is a ball of radius 0.5 when far away).
//
// Why discontinuous: at |p| = 0.9 the code switches from the detailed
// field (three crossed bars, each 0.7 long and 0.15 thick, plus a centre
// ball) to length(p) - 0.5 = 0.4. The detailed field there is 0.2 on the
// axes (0.9 - 0.7) and about 0.5 on the diagonals; it equals 0.4 only on
// a curve, so the field jumps by up to 0.2 across most of the
// sphere |p| = 0.9, which lies inside the cube. Both pieces are
// 1-Lipschitz and finite; only the switch is wrong.
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
