/* sdfwb
name: Triangle
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A thin plate: every point within 0.05 of a tilted triangle that faces the +X side. The
  unsigned distance to a filled triangle is exact (plane distance when the point projects inside,
  else the nearest edge segment), and the triangle is convex, so subtracting the half thickness
  gives the exact signed distance of the rounded plate, inside and outside.
  Parameters: half thickness (0.01-0.1).
*/
uniform float halfThickness = 0.05;  // @range 0.01 0.1 @step 0.005 @label "Half thickness"

float segmentDistance(vec3 p, vec3 a, vec3 b) {
    vec3 ab = b - a;
    float along = clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(p - a - ab * along);
}

float triangleDistance(vec3 p, vec3 a, vec3 b, vec3 c) {
    vec3 normal = cross(b - a, c - a);
    // p projects inside the triangle when it lies on the inner side of all three edges.
    bool projectsInside = dot(cross(normal, b - a), p - a) >= 0.0 &&
                          dot(cross(normal, c - b), p - b) >= 0.0 &&
                          dot(cross(normal, a - c), p - c) >= 0.0;
    if (projectsInside) return abs(dot(normal, p - a)) / length(normal);
    return min(segmentDistance(p, a, b), min(segmentDistance(p, b, c), segmentDistance(p, c, a)));
}

float sdf(vec3 p) {
    const vec3 top = vec3(-0.09, 0.86, -0.18);
    const vec3 lowerLeft = vec3(-0.42, -0.66, 0.85);
    const vec3 lowerRight = vec3(0.62, -0.58, -0.72);
    return triangleDistance(p, top, lowerLeft, lowerRight) - halfThickness;
}
