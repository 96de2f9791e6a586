// Imitates: forum / blog snippets for "rounded cube via a p-norm" (a
// superellipsoid) adapted from a 2D version, with a `float map(vec3 p)`
// entry and a lengthN() helper. In the original scene the object sat on a
// floor at y = 0, so the author only abs()'d x and z -- y was "always
// positive".
//
// Why NaN: a softening term sqrt(y) added last; sqrt of a negative is NaN on
// IEEE hardware (llvmpipe, NVIDIA; GLSL leaves it undefined; pow() of a
// negative base would not do: Mesa returns it finite). p.y goes into it
// without abs(), so every point with y < 0 -- half of the cube --
// gets NaN, which nothing afterwards filters out (no min/max that could
// swallow it). Where y >= 0 the field is ||p||_2.5 - 0.6; for a p-norm with
// p >= 2 the Euclidean length of the gradient is <= 1, but the 0.001*sqrt(y)
// term has slope 0.0005/sqrt(y): |grad f| passes 1.05 in a layer about 2e-6
// thick above y = 0. The audit's 99.9th-percentile estimate cannot see it, so
// it gives only the nan flag (a known miss: tests/foreign/README.md).
// expect: entry=map flags=nan animated=no

const float N = 2.5;

float lengthN(vec3 p, float n)
{
    vec3 a = vec3(abs(p.x), p.y, abs(p.z));   // y >= 0 on the floor anyway
    vec3 b = pow(abs(a), vec3(n));
    // the floor contact 'softening', written for y >= 0: sqrt(y) below the shape
    return pow(b.x + b.y + b.z, 1.0/n) + 0.001 * sqrt(a.y);
}

float map(vec3 p)
{
    return lengthN(p, N) - 0.6;
}
