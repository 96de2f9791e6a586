/* sdfwb
name: Dodecahedron
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Regular dodecahedron with vertices (+-1, +-1, +-1) and the cyclic permutations of
  (0, +-1/phi, +-phi), scaled so the outermost vertices sit at 0.92 on the axes. It is symmetric
  in the three coordinate planes, so after folding into the positive octant the nearest boundary
  point lies on one of the three pentagons whose normals are (0, phi, 1), (1, 0, phi) and
  (phi, 1, 0). Outside, the field is the least exact distance to those pentagons; inside, the
  nearest face plane of the convex solid. Both are exact.
*/
float segmentDistance(vec3 p, vec3 a, vec3 b) {
    vec3 ab = b - a;
    float along = clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(p - a - ab * along);
}

// Unsigned distance to a filled convex pentagon with vertices in order around it: the plane
// distance when p projects inside it, otherwise the distance to the nearest edge.
float pentagonDistance(vec3 p, vec3 v0, vec3 v1, vec3 v2, vec3 v3, vec3 v4) {
    vec3 normal = cross(v1 - v0, v2 - v0);
    bool projectsInside = dot(cross(normal, v1 - v0), p - v0) >= 0.0 &&
                          dot(cross(normal, v2 - v1), p - v1) >= 0.0 &&
                          dot(cross(normal, v3 - v2), p - v2) >= 0.0 &&
                          dot(cross(normal, v4 - v3), p - v3) >= 0.0 &&
                          dot(cross(normal, v0 - v4), p - v4) >= 0.0;
    if (projectsInside) return abs(dot(normal, p - v0)) / length(normal);
    return min(min(min(segmentDistance(p, v0, v1), segmentDistance(p, v1, v2)),
                   min(segmentDistance(p, v2, v3), segmentDistance(p, v3, v4))),
               segmentDistance(p, v4, v0));
}

float sdf(vec3 p) {
    const float goldenRatio = 1.6180340;
    const float inverseGolden = 0.6180340;
    const float scale = 0.92 / goldenRatio;
    // Outward unit face normals and the face distance from the centre (1.37638 before scaling).
    const vec3 normalY = vec3(0.0, 0.85065081, 0.52573111);  // (0, phi, 1) normalised
    const vec3 normalZ = vec3(0.52573111, 0.0, 0.85065081);  // (1, 0, phi)
    const vec3 normalX = vec3(0.85065081, 0.52573111, 0.0);  // (phi, 1, 0)
    const float faceDistance = 1.37638192 * scale;

    // Vertices shared by the three pentagons (all in or on the positive octant, or mirrored across one plane).
    const vec3 corner = vec3(1.0, 1.0, 1.0) * scale;
    const vec3 topRight = vec3(inverseGolden, goldenRatio, 0.0) * scale;
    const vec3 topLeft = vec3(-inverseGolden, goldenRatio, 0.0) * scale;
    const vec3 upperBack = vec3(-1.0, 1.0, 1.0) * scale;
    const vec3 frontUp = vec3(0.0, inverseGolden, goldenRatio) * scale;
    const vec3 frontDown = vec3(0.0, -inverseGolden, goldenRatio) * scale;
    const vec3 lowerFront = vec3(1.0, -1.0, 1.0) * scale;
    const vec3 sideFront = vec3(goldenRatio, 0.0, inverseGolden) * scale;
    const vec3 sideBack = vec3(goldenRatio, 0.0, -inverseGolden) * scale;
    const vec3 upperSide = vec3(1.0, 1.0, -1.0) * scale;

    vec3 q = abs(p);
    float deepest = max(max(dot(q, normalY), dot(q, normalZ)), dot(q, normalX)) - faceDistance;
    if (deepest <= 0.0) return deepest;  // inside: the nearest face plane

    float faceY = pentagonDistance(q, topRight, topLeft, upperBack, frontUp, corner);
    float faceZ = pentagonDistance(q, frontUp, frontDown, lowerFront, sideFront, corner);
    float faceX = pentagonDistance(q, sideFront, sideBack, upperSide, topRight, corner);
    return min(min(faceY, faceZ), faceX);
}
