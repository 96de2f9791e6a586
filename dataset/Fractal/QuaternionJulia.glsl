/* sdfwb
name: Quaternion Julia
category: Fractal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Quaternion Julia set of z -> z^2 + c with c = (-0.125, -0.256, 0.847, 0.0895), the 3D slice
  through the real axis (x real, y and z the first two imaginary parts, the third one zero), scaled
  by 0.68 to fit the cube, 12 iterations. Squaring a quaternion (a, v) gives (a^2 - |v|^2, 2 a v),
  and its derivative stretches by at most 2|z| in any direction, so the running bound dr -> 2|z| dr
  bounds the orbit's derivative; it is kept from shrinking so orbits that pass near 0 do not
  inflate the estimate inside. The estimate 0.5 r log(r) / dr comes from the last iterate for
  escaped and captured orbits alike (inside the unit sphere its tangent continuation (r - 1) / 2dr,
  which is negative), and the large bailout (256) keeps it consistent from one escape iteration to
  the next, so the field is continuous. Far from the set r log r grows faster than the distance, so
  the field is capped by 0.4 |p| + 0.05 (positive, so the surface is unchanged). Scaled by 0.75:
  measured difference quotients (1e-4 to 0.1 apart, out to |p| = 100) stay below 0.85, so the
  field is a conservative bound in practice; no proof.
*/
float sdf(vec3 p) {
    const float fitScale = 0.68;  // world units per fractal unit
    const float safety = 0.75;    // measured: keeps every difference quotient below 0.85
    const vec4 c = vec4(-0.125, -0.256, 0.847, 0.0895);
    const float bailout = 256.0;
    const int iterations = 12;

    vec4 z = vec4(p / fitScale, 0.0);  // (real, i, j, k)
    float dr = 1.0;
    float r = length(z);
    for (int i = 0; i < iterations && r <= bailout; ++i) {
        dr = max(2.0 * r, 1.0) * dr;
        z = vec4(z.x * z.x - dot(z.yzw, z.yzw), 2.0 * z.x * z.yzw) + c;
        r = length(z);
    }
    float potential = r > 1.0 ? r * log(r) : r - 1.0;
    float estimate = safety * fitScale * 0.5 * potential / dr;
    // Far away r log r outgrows the distance (slope above 1 beyond |p| ~ 3); a gentle positive
    // cone takes over there. It is positive everywhere, so the surface is unchanged.
    return min(estimate, 0.4 * length(p) + 0.05);
}
