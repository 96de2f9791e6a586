/* sdfwb
name: Capsule
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Upright capsule: every point within 0.36 of the vertical segment from y = -0.56 to y = 0.56.
  The distance to a segment is exact (clamp the projection onto the segment's line), and a
  segment is convex, so subtracting the radius gives the exact signed distance of the capsule.
  Parameters: half length (0-0.58), radius (0.05-0.37).
*/
uniform float halfLength = 0.56;  // @range 0.0 0.58 @step 0.01 @label "Half length"
uniform float radius = 0.36;      // @range 0.05 0.37 @step 0.01 @label "Radius"

float sdf(vec3 p) {
    // Nearest point of the segment: the point itself, with its height clamped to the segment.
    vec3 nearest = vec3(0.0, clamp(p.y, -halfLength, halfLength), 0.0);
    return length(p - nearest) - radius;
}
