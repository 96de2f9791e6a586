/* sdfwb
name: Round Box
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Box with rounded edges and corners, half extents (0.85, 0.55, 0.65), rounding radius 0.15.
  Built as the exact distance to a core box shrunk by the rounding radius, minus that radius.
  The rounded box is the core box grown by a ball, and growing a convex solid by a ball shifts
  its exact signed distance by the ball radius, inside as well as outside, so the field stays exact.
  Parameters: half width (0.2-0.85), half height (0.2-0.55), half depth (0.2-0.65),
  rounding (0-0.2).
*/
uniform float halfWidth = 0.85;   // @range 0.2 0.85 @step 0.01 @label "Half width (X)"
uniform float halfHeight = 0.55;  // @range 0.2 0.55 @step 0.01 @label "Half height (Y)"
uniform float halfDepth = 0.65;   // @range 0.2 0.65 @step 0.01 @label "Half depth (Z)"
uniform float rounding = 0.15;    // @range 0.0 0.2 @step 0.01 @label "Rounding radius"

float sdf(vec3 p) {
    vec3 halfSize = vec3(halfWidth, halfHeight, halfDepth);
    // Exact signed distance to the core box; q is the overshoot past each face.
    vec3 q = abs(p) - (halfSize - rounding);
    float outsideCore = length(max(q, 0.0));
    float insideCore = min(max(q.x, max(q.y, q.z)), 0.0);
    return outsideCore + insideCore - rounding;
}
