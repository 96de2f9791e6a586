/* sdfwb
name: Tetrahedron
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Regular tetrahedron with edge 1.6, standing on a horizontal face with its apex up and one
  face turned to +X. Outside, the field is the least exact distance to the four triangular faces;
  inside, the distance to the boundary of a convex solid is the distance to the nearest face plane.
  Both are exact, and they meet continuously at zero on the surface.
*/
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

// Signed distance to the plane of face (a, b, c), positive on the side away from `inner`.
float facePlane(vec3 p, vec3 a, vec3 b, vec3 c, vec3 inner) {
    vec3 normal = normalize(cross(b - a, c - a));
    if (dot(normal, a - inner) < 0.0) normal = -normal;
    return dot(normal, p - a);
}

float sdf(vec3 p) {
    // Edge 1.6: height 1.6 * sqrt(2/3) = 1.3064, base circumradius 1.6 / sqrt(3) = 0.9238.
    // The base triangle has a vertex towards -X and its opposite edge towards +X; everything is
    // shifted by +0.231 in x so the bounding box is centred on the origin.
    const vec3 apex = vec3(0.2309, 0.6532, 0.0);
    const vec3 back = vec3(-0.6928, -0.6532, 0.0);
    const vec3 frontLeft = vec3(0.6928, -0.6532, 0.8);
    const vec3 frontRight = vec3(0.6928, -0.6532, -0.8);
    const vec3 solidCentre = vec3(0.2309, -0.3266, 0.0);

    float deepest = max(max(facePlane(p, apex, frontLeft, frontRight, solidCentre),
                            facePlane(p, apex, back, frontLeft, solidCentre)),
                        max(facePlane(p, apex, frontRight, back, solidCentre),
                            facePlane(p, back, frontRight, frontLeft, solidCentre)));
    if (deepest <= 0.0) return deepest;  // inside: the nearest face plane

    return min(min(triangleDistance(p, apex, frontLeft, frontRight),
                   triangleDistance(p, apex, back, frontLeft)),
               min(triangleDistance(p, apex, frontRight, back),
                   triangleDistance(p, back, frontRight, frontLeft)));
}
