/* sdfwb
name: Mandelbulb
category: Fractal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: The power-8 Mandelbulb (the triplex power z -> z^8 + c in spherical coordinates, polar axis
  along +Y), scaled by 0.82 to fit the cube, 8 iterations. The estimate is 0.5 r log(r) / dr from
  the last iterate, with dr a running bound on the orbit's derivative; the angle multiplications
  use repeated double-angle formulas, so the loop needs no trigonometry. Escaped and captured
  orbits use the same formula (inside the unit sphere its tangent continuation (r - 1) / 2dr, which
  is negative), so the field is continuous across the escape boundaries. Two changes to the
  textbook dr keep the slope bounded: dr never shrinks (an orbit that passes near 0 would
  otherwise forget its derivative and inflate the estimate inside), and near the poles it includes
  the azimuthal stretch |sin 8 theta / sin theta| of the power map, faded out smoothly for r
  between 0.8 and 1.2 so that escaping orbits stay consistent from one iteration to the next.
  Far from the set r log r grows faster than the distance, so the field is capped by
  0.5 |p| + 0.1; a skin of 0.0005 is subtracted so the flat, barely positive pockets of captured
  orbits count as inside. Scaled by 0.45, measured difference
  quotients (1e-4 to 0.1 apart, uniform and near-surface samples, out to |p| = 100) stay below
  0.9, so it is a conservative bound in practice; no proof.
*/
float sdf(vec3 p) {
    const float fitScale = 0.82;  // world units per fractal unit
    const float safety = 0.45;    // measured: keeps every difference quotient below 0.9
    const float bailout = 4.0;
    const int iterations = 8;

    vec3 c = p / fitScale;
    vec3 z = c;
    float dr = 1.0;
    float r = length(z);
    for (int i = 0; i < iterations && r <= bailout; ++i) {
        // Spherical angles of z as (cos, sin) pairs: theta from +Y, phi around Y from +X.
        float planar = length(z.xz);
        vec2 theta = r > 0.0 ? vec2(z.y, planar) / r : vec2(1.0, 0.0);
        vec2 phi = planar > 0.0 ? vec2(z.x, z.z) / planar : vec2(1.0, 0.0);
        float sinTheta = theta.y;
        // Multiply both angles by 8: three doublings, (cos, sin) -> (cos^2 - sin^2, 2 cos sin).
        for (int k = 0; k < 3; ++k) {
            theta = vec2(theta.x * theta.x - theta.y * theta.y, 2.0 * theta.x * theta.y);
            phi = vec2(phi.x * phi.x - phi.y * phi.y, 2.0 * phi.x * phi.y);
        }
        // The power map stretches by 8 r^7 radially and along theta, and by 8 r^7 |sin 8t / sin t|
        // (up to 8 times more, near the poles) along phi.
        float stretch = sinTheta > 1e-7 ? min(abs(theta.y) / sinTheta, 8.0) : 8.0;
        stretch = mix(max(stretch, 1.0), 1.0, smoothstep(0.8, 1.2, r));
        float r2 = r * r;
        float r4 = r2 * r2;
        dr = max(8.0 * r4 * r2 * r * stretch, 1.0) * dr + 1.0;
        z = r4 * r4 * vec3(theta.y * phi.x, theta.x, theta.y * phi.y) + c;
        r = length(z);
    }
    float potential = r > 1.0 ? r * log(r) : r - 1.0;
    float estimate = safety * fitScale * 0.5 * potential / dr;
    // Far away r log r outgrows the distance (slope above 1 beyond |p| ~ 25); a gentle positive
    // cone takes over there. The small skin moves the surface out by about 0.001 so that the
    // flat, barely positive pockets of captured orbits (r just above 1) fall inside.
    const float skin = 0.0005;
    return min(estimate, 0.5 * length(p) + 0.1) - skin;
}
