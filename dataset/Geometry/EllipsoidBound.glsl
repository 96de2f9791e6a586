/* sdfwb
name: Ellipsoid Bound
category: Geometry
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Ellipsoid with semi-axes (0.9, 0.58, 0.72). There is no closed form for the distance to an
  ellipsoid, so this is a bound: g(p) = |p / semiAxes| - 1 is zero exactly on the ellipsoid, and its
  gradient has length at most 1 / (smallest semi-axis). Multiplying by the smallest semi-axis makes
  the field 1-Lipschitz, so |f| never exceeds the true distance; it is exact only along the
  shortest axis. Parameters: semi-axes (0.1-0.9 each).
*/
uniform vec3 semiAxes = vec3(0.9, 0.58, 0.72);  // @range 0.1 0.9 @step 0.01 @label "Semi-axes"

float sdf(vec3 p) {
    float smallestSemiAxis = min(semiAxes.x, min(semiAxes.y, semiAxes.z));
    return smallestSemiAxis * (length(p / semiAxes) - 1.0);
}
