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
*/
float sdf(vec3 p) {
    const float halfLength = 0.56;  // half the length of the core segment
    const float radius = 0.36;
    // Nearest point of the segment: the point itself, with its height clamped to the segment.
    vec3 nearest = vec3(0.0, clamp(p.y, -halfLength, halfLength), 0.0);
    return length(p - nearest) - radius;
}
