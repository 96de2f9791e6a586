// Imitates: Shadertoy "infinite grid of balls" code with IQ's opRep
// (mod(p + 0.5*c, c) - 0.5*c), a Dave-Hoskins-like hash of the cell id for
// the material, `vec2 map(vec3 p)`, and a raymarch() that is never called.
//
// Why the audit should find it clean: the ball (radius 0.15) fits inside
// its 0.5-wide cell and is centred, so the copies seen from both sides of
// a cell face agree there (mod repetition of a centred, mirror-symmetric
// shape is continuous) and the field is 1-Lipschitz. The endless lattice is
// intersected with a box (max, still 1-Lipschitz) so only the 27 balls in
// |p| < 0.75 remain and the field grows outside the cube. The hash only
// changes the material id in .y.
// expect: entry=map flags=none animated=no

#define CELL 0.5

float hash(vec3 p)
{
    p = fract(p*0.1031);
    p += dot(p, p.zyx + 31.32);
    return fract((p.x + p.y)*p.z);
}

float sdBox(vec3 p, vec3 b)
{
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

vec3 opRep(in vec3 p, in vec3 c)
{
    return mod(p + 0.5*c, c) - 0.5*c;
}

vec2 map(vec3 p)
{
    vec3 id = floor((p + 0.5*CELL)/CELL);
    vec3 q = opRep(p, vec3(CELL));
    float d = length(q) - 0.15;
    d = max(d, sdBox(p, vec3(0.75)));
    return vec2(d, 1.0 + floor(4.0*hash(id)));
}

float raymarch(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < 128; i++)
    {
        float h = map(ro + rd*t).x;
        if (h < 0.0005*t) return t;
        t += h;
        if (t > 50.0) break;
    }
    return -1.0;
}
