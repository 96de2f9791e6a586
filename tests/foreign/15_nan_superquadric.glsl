// Imitates: forum / blog snippets for "rounded cube via a p-norm" (a
// superellipsoid) adapted from a 2D version, with a `float map(vec3 p)`
// entry and a lengthN() helper. In the original scene the object sat on a
// floor at y = 0, so the author only abs()'d x and z -- y was "always
// positive".
//
// Why NaN: pow(x, 2.5) is undefined for x < 0 and evaluates to NaN on
// GPUs (exp2(2.5 * log2(x)) with log2 of a negative). p.y is passed to
// pow() without abs(), so every point with y < 0 -- half of the cube --
// gets NaN, which nothing afterwards filters out (no min/max that could
// swallow it). Where y >= 0 the field is ||p||_2.5 - 0.6; for a p-norm with
// p >= 2 the Euclidean length of the gradient is <= 1, so that half is
// continuous and 1-Lipschitz: only the nan flag.
// expect: entry=map flags=nan animated=no

const float N = 2.5;

float lengthN(vec3 p, float n)
{
    vec3 a = vec3(abs(p.x), p.y, abs(p.z));   // y >= 0 on the floor anyway
    return pow(pow(a.x, n) + pow(a.y, n) + pow(a.z, n), 1.0/n);
}

float map(vec3 p)
{
    return lengthN(p, N) - 0.6;
}
