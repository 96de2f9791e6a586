/* sdfwb
name: Mandelbox
category: Fractal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Mandelbox with scale 2 (Tom Lowe's map: a box fold, a sphere fold with minimum radius 0.5 and
  fixed radius 1, then z -> 2 z + c), 12 iterations; the set spans about [-6, 6]^3 and is scaled by
  0.13. The box fold is a reflection and the sphere fold an inversion (stretching by
  fixedR^2 / r^2) or a uniform scale, so the running factor dr bounds the orbit's derivative.
  Every point is iterated the same fixed number of times (no bailout, nothing can overflow), so
  |z| / dr is continuous; the surface is its level 0.002, a thin skin around the points where the
  estimate vanishes (bounded orbits give values near zero, so the solid body is negative, and the
  skin keeps the flat near-zero values of the body's interior on the negative side). The
  estimate is not a proven bound; scaled by 0.7, measured difference quotients (1e-4 to 0.1 apart,
  uniform and near-surface samples) stay below 0.85, so it is conservative in practice.
*/
float sdf(vec3 p) {
    const float fitScale = 0.13;       // world units per fractal unit
    const float safety = 0.7;          // measured: keeps every difference quotient below 0.85
    const float foldScale = 2.0;
    const float minRadius2 = 0.25;     // inside this radius the sphere fold is a uniform scale
    const float fixedRadius2 = 1.0;    // between the radii it is an inversion
    const int iterations = 12;
    const float skin = 0.002;          // the surface is where the estimate equals this (world units)

    vec3 c = p / fitScale;
    vec3 z = c;
    float dr = 1.0;
    for (int i = 0; i < iterations; ++i) {
        // Box fold: reflect each coordinate back across the faces of [-1, 1]^3 (an isometry).
        z = clamp(z, -1.0, 1.0) * 2.0 - z;
        // Sphere fold: scales by fixedR^2 / minR^2 inside minR, inverts between minR and fixedR.
        float r2 = dot(z, z);
        float stretch = r2 < minRadius2 ? fixedRadius2 / minRadius2
                                        : (r2 < fixedRadius2 ? fixedRadius2 / r2 : 1.0);
        z *= stretch;
        dr *= stretch;
        z = foldScale * z + c;
        dr = dr * abs(foldScale) + 1.0;
    }
    return safety * (fitScale * length(z) / dr - skin);
}
