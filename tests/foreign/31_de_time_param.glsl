// Imitates: Fragmentarium / Processing-port style distance estimators with
// time passed as a parameter: `float de(vec3 p, float time)`, a mat2 rot()
// helper, a carousel of balls made with an atan/mod angular fold, and a
// central column.
//
// Why the audit should find it clean: rot() is an isometry; the angular
// fold is a piecewise rotation and each ball sits on its sector's
// mid-line (mirror-symmetric), so sectors agree on the seams: continuous
// and 1-Lipschitz. time only turns the carousel and moves the balls up and
// down by the same amount (it does not depend on p), so every time gives
// such a field. min keeps it so. Bounded inside the cube.
// expect: entry=de flags=none animated=yes

const float PI = 3.14159265;

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, s, -s, c);
}

vec2 fold(vec2 q, float n)
{
    float w = 2.0*PI/n;
    float a = mod(atan(q.y, q.x) + 0.5*w, w) - 0.5*w;
    return length(q)*vec2(cos(a), sin(a));
}

float de(vec3 p, float time)
{
    vec3 q = p;
    q.xz = rot(0.7*time)*q.xz;
    q.xz = fold(q.xz, 6.0);
    q.y -= 0.2*sin(time);
    float balls = length(q - vec3(0.6, 0.0, 0.0)) - 0.15;

    vec2 c = abs(vec2(length(p.xz), p.y)) - vec2(0.12, 0.7);
    float column = min(max(c.x, c.y), 0.0) + length(max(c, 0.0));

    return min(balls, column);
}
