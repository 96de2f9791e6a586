/* sdfwb
name: Pyramid
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Square pyramid, base 1.44 x 1.44 at y = -0.68, apex at y = 0.68; one side faces +X.
  The pyramid is convex and mirror-symmetric in x and z, so after folding x and z to be positive
  the nearest boundary point lies on the +X face, the +Z face or the base. Outside, the field is
  the least exact distance to those three faces; inside, the distance to the boundary of a convex
  solid is the distance to the nearest face plane. Both are exact.
  Parameters: half base (0.1-0.72), height (0.2-1.36).
*/
uniform float halfBase = 0.72;  // @range 0.1 0.72 @step 0.01 @label "Half base"
uniform float height = 1.36;    // @range 0.2 1.36 @step 0.01 @label "Height"

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
    float baseY = -0.5 * height;
    vec3 apex = vec3(0.0, 0.5 * height, 0.0);
    vec3 q = vec3(abs(p.x), p.y, abs(p.z));

    // Signed distances to the planes of the +X face, the +Z face and the base; the side
    // planes contain the apex and have outward normal (height, halfBase) in their (across, y) plane.
    vec2 sideNormal = normalize(vec2(height, halfBase));
    float planeX = dot(vec2(q.x, q.y - apex.y), sideNormal);
    float planeZ = dot(vec2(q.z, q.y - apex.y), sideNormal);
    float planeBase = baseY - q.y;
    float deepest = max(max(planeX, planeZ), planeBase);
    if (deepest <= 0.0) return deepest;  // inside: the nearest face plane

    vec3 cornerFront = vec3(halfBase, baseY, halfBase);   // +x +z
    vec3 cornerBackX = vec3(halfBase, baseY, -halfBase);  // +x -z
    vec3 cornerBackZ = vec3(-halfBase, baseY, halfBase);  // -x +z
    float faceX = triangleDistance(q, apex, cornerBackX, cornerFront);
    float faceZ = triangleDistance(q, apex, cornerFront, cornerBackZ);
    // The base square, measured directly: overshoot past its edges and height above or below it.
    vec2 pastEdge = max(q.xz - halfBase, 0.0);
    float base = length(vec3(pastEdge.x, q.y - baseY, pastEdge.y));
    return min(min(faceX, faceZ), base);
}
