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
