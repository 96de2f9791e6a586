// Imitates: Shadertoy heightfield code that turns a closed-form height into
// a "distance" by `p.y - height(p.xz)`, here the height of a spherical cap
// (a dome) sqrt(R*R - x*x - z*z), with `float sdf(vec3 p)` and a terrain()
// helper, no clamp on the sqrt argument.
//
// Why NaN: outside the dome's footprint (x*x + z*z > R*R, R = 0.6) the sqrt
// argument is negative and sqrt() gives NaN, and the NaN reaches the
// return value directly (no min/max that could swallow it): about 72% of
// the cube. Why also non-conservative: inside the footprint the field is
// y - sqrt(R^2 - rho^2), whose gradient has length sqrt(1 + rho^2/h^2);
// it exceeds 1.05 wherever rho > 0.3 h and grows without bound towards
// the rim (h -> 0). Continuous where it is finite.
// expect: entry=sdf flags=nan,non-conservative animated=no

#define R 0.6

float terrain(vec2 xz)
{
    return sqrt(R*R - dot(xz, xz));   // height of the cap above y = 0
}

float sdf(vec3 p)
{
    return p.y - terrain(p.xz);
}
