// Imitates: Shadertoy code ported to a host that passes time explicitly
// (`vec2 map(vec3 p, float time)`, as in many three.js / KodeLife ports):
// a rotate() helper, a spinning rounded box inside a tilted ring, and the
// common "never step more than STEP_CAP" line at the end of map() to keep
// fast-moving parts from being overshot.
//
// Why truncated: min(d, STEP_CAP) with STEP_CAP = 0.3 leaves the field at
// exactly 0.3 (|grad| = 0) everywhere more than 0.3 from the surface, over
// most of the outside region out to distance 3, at any time. Rotations are
// isometries, so the rounded box and the torus stay exact; min keeps the
// field continuous and 1-Lipschitz; no NaN. The objects fit the cube
// (rounded box circumradius ~0.48, ring radius 0.7 + 0.06).
// expect: entry=map flags=truncated animated=yes

#define STEP_CAP 0.3

mat3 rotate(vec3 axis, float angle)
{
    axis = normalize(axis);
    float s = sin(angle), c = cos(angle), oc = 1.0 - c;
    return mat3(oc*axis.x*axis.x + c,        oc*axis.x*axis.y - axis.z*s, oc*axis.z*axis.x + axis.y*s,
                oc*axis.x*axis.y + axis.z*s, oc*axis.y*axis.y + c,        oc*axis.y*axis.z - axis.x*s,
                oc*axis.z*axis.x - axis.y*s, oc*axis.y*axis.z + axis.x*s, oc*axis.z*axis.z + c);
}

float sdRoundBox(vec3 p, vec3 b, float r)
{
    vec3 q = abs(p) - b + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float sdTorus(vec3 p, vec2 t)
{
    return length(vec2(length(p.xz) - t.x, p.y)) - t.y;
}

vec2 map(vec3 p, float time)
{
    vec3 q = rotate(vec3(1.0, 1.0, 0.0), time*0.8)*p;
    float box = sdRoundBox(q, vec3(0.3), 0.06);

    vec3 r = rotate(vec3(1.0, 0.0, 0.0), 0.4)*p;
    float ring = sdTorus(r, vec2(0.7, 0.06));

    vec2 res = box < ring ? vec2(box, 1.0) : vec2(ring, 2.0);
    res.x = min(res.x, STEP_CAP);
    return res;
}
