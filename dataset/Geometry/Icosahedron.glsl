/* sdfwb
name: Icosahedron
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Regular icosahedron with vertices at the cyclic permutations of (0, +-1, +-phi), scaled so the
  outermost vertices sit at 0.92 on the axes. It is symmetric in the three coordinate planes, so
  after folding into the positive octant the nearest boundary point lies on one of four faces: the
  face centred in the octant and the three faces that straddle its coordinate planes. Outside,
  the field is the least exact distance to those triangles; inside, the nearest face plane of the
  convex solid. Both are exact.
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

// Signed distance to the plane of a face of a solid centred on the origin (outward positive).
float facePlane(vec3 p, vec3 a, vec3 b, vec3 c) {
    vec3 normal = normalize(cross(b - a, c - a));
    if (dot(normal, a) < 0.0) normal = -normal;
    return dot(normal, p - a);
}

float sdf(vec3 p) {
    const float goldenRatio = 1.6180340;
    const float scale = 0.92 / goldenRatio;
    // The six vertices that bound the positive octant's faces.
    const vec3 vy = vec3(0.0, 1.0, goldenRatio) * scale;         // (0, 1, phi)
    const vec3 vyMirror = vec3(0.0, -1.0, goldenRatio) * scale;  // its mirror in y
    const vec3 vx = vec3(1.0, goldenRatio, 0.0) * scale;         // (1, phi, 0)
    const vec3 vxMirror = vec3(-1.0, goldenRatio, 0.0) * scale;
    const vec3 vz = vec3(goldenRatio, 0.0, 1.0) * scale;         // (phi, 0, 1)
    const vec3 vzMirror = vec3(goldenRatio, 0.0, -1.0) * scale;

    vec3 q = abs(p);
    // Faces: the octant face, and the faces straddling y = 0, x = 0 and z = 0.
    float deepest = max(max(facePlane(q, vy, vx, vz), facePlane(q, vy, vyMirror, vz)),
                        max(facePlane(q, vx, vxMirror, vy), facePlane(q, vz, vzMirror, vx)));
    if (deepest <= 0.0) return deepest;  // inside: the nearest face plane

    return min(min(triangleDistance(q, vy, vx, vz), triangleDistance(q, vy, vyMirror, vz)),
               min(triangleDistance(q, vx, vxMirror, vy), triangleDistance(q, vz, vzMirror, vx)));
}
