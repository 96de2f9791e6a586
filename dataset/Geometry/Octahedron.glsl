/* sdfwb
name: Octahedron
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Regular octahedron with its six vertices on the axes at distance 0.92. Folding into the
  positive octant (the shape is symmetric in all three coordinate planes) leaves a single face,
  the triangle between the three positive vertices. The exact distance to that triangle, signed by
  the face plane, is the exact distance everywhere (inside a convex solid the nearest boundary
  point lies on the nearest face plane). Not the cheaper plane-only bound, which is only
  conservative outside. Parameters: vertex distance (0.1-0.95).
*/
uniform float vertexDistance = 0.92;  // @range 0.1 0.95 @step 0.01 @label "Vertex distance"

float segmentDistance(vec3 p, vec3 a, vec3 b) {
    vec3 ab = b - a;
    float along = clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(p - a - ab * along);
}

// Unsigned distance to a filled triangle: the plane distance when p projects inside it,
// otherwise the distance to the nearest edge.
float triangleDistance(vec3 p, vec3 a, vec3 b, vec3 c) {
    vec3 normal = cross(b - a, c - a);
    bool projectsInside = dot(cross(normal, b - a), p - a) >= 0.0 &&
                          dot(cross(normal, c - b), p - b) >= 0.0 &&
                          dot(cross(normal, a - c), p - c) >= 0.0;
    if (projectsInside) return abs(dot(normal, p - a)) / length(normal);
    return min(segmentDistance(p, a, b), min(segmentDistance(p, b, c), segmentDistance(p, c, a)));
}

float sdf(vec3 p) {
    vec3 q = abs(p);
    // Signed distance to the plane x + y + z = vertexDistance.
    float plane = (q.x + q.y + q.z - vertexDistance) * 0.57735027;
    if (plane <= 0.0) return plane;
    return triangleDistance(q, vec3(vertexDistance, 0.0, 0.0), vec3(0.0, vertexDistance, 0.0),
                            vec3(0.0, 0.0, vertexDistance));
}
