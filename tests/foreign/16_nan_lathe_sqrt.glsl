// Imitates: Shadertoy "lathe" / surface-of-revolution code that turns a
// 2D profile into a solid with `length(p.xz) - profile(p.y)`, the profile
// written in closed form with a sqrt and no clamp on its argument (an
// onion-dome / pear shape), `float sdf(vec3 p)` and a profile() helper.
//
// Why NaN: profile(y) = 0.9 sqrt(y + 0.6) (0.5 - y) takes the sqrt of a
// negative number for y < -0.6, and the NaN reaches the return value
// directly (no min/max that could swallow it): the bottom 20% of the cube.
// Why also non-conservative: the field is a radius minus a profile, so
// |grad f| = sqrt(1 + profile'(y)^2). profile' grows without bound towards
// the tip at y = -0.6 (the sqrt's slope), and above the top (y > 0.5,
// where the profile goes negative) it is about -0.94 or steeper, so
// |grad f| exceeds 1.05 in large regions. Continuous where finite; above
// and around the shape the field grows.
// expect: entry=sdf flags=nan,non-conservative animated=no

float profile(float y)
{
    return 0.9*sqrt(y + 0.6)*(0.5 - y);
}

float sdf(vec3 p)
{
    return length(p.xz) - profile(p.y);
}
