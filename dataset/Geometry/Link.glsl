/* sdfwb
name: Link
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Chain link standing upright, its plane turned 30 degrees from +X towards +Z. The core
  curve is a stadium (two half circles of radius 0.42 joined by straight runs of length 0.64) and
  the tube radius is 0.16. Clamping the vertical coordinate into the straight run maps a point to
  where it sees a plain circle, and for a convex stadium that gives the exact distance to the curve
  (the straight runs are nearest beside them, the half circles above and below). The radius is
  below the curve's radius of curvature, so subtracting it stays exact inside the tube.
  Parameters: loop radius (0.2-0.42), half straight (0-0.35), tube radius (0.04-0.18).
*/
uniform float loopRadius = 0.42;    // @range 0.2 0.42 @step 0.01 @label "Loop radius"
uniform float halfStraight = 0.32;  // @range 0.0 0.35 @step 0.01 @label "Half straight length"
uniform float tubeRadius = 0.16;    // @range 0.04 0.18 @step 0.01 @label "Tube radius"

float sdf(vec3 p) {
    // Rotate about Y: the link's plane is spanned by `across` and Y, with normal `facing`.
    const vec3 facing = vec3(0.8660254, 0.0, 0.5);
    const vec3 across = vec3(-0.5, 0.0, 0.8660254);
    vec3 local = vec3(dot(p, across), p.y, dot(p, facing));

    // Remove the straight run: inside it the nearest curve point is level with the point.
    vec2 inPlane = vec2(local.x, max(abs(local.y) - halfStraight, 0.0));
    vec2 toCurve = vec2(length(inPlane) - loopRadius, local.z);
    return length(toCurve) - tubeRadius;
}
