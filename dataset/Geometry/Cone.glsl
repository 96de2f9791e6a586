/* sdfwb
name: Cone
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Solid right circular cone, apex up at y = 0.85, flat base of radius 0.8 at y = -0.85.
  In the meridian half-plane (distance from the axis, height) the cone is a right triangle whose
  only real boundary is the slanted side and the base segment (the axis edge is interior). The
  exact distance to those two segments, signed by a point-in-triangle test, is the exact 3D distance.
  Parameters: base radius (0.1-0.8), half height (0.1-0.85).
*/
uniform float baseRadius = 0.8;   // @range 0.1 0.8 @step 0.01 @label "Base radius"
uniform float halfHeight = 0.85;  // @range 0.1 0.85 @step 0.01 @label "Half height"

float segmentDistance2(vec2 p, vec2 a, vec2 b) {
    vec2 ab = b - a;
    float along = clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(p - a - ab * along);
}

float sdf(vec3 p) {
    vec2 meridian = vec2(length(p.xz), p.y);
    vec2 apex = vec2(0.0, halfHeight);
    vec2 rim = vec2(baseRadius, -halfHeight);
    vec2 baseCentre = vec2(0.0, -halfHeight);

    float toSide = segmentDistance2(meridian, apex, rim);
    float toBase = segmentDistance2(meridian, baseCentre, rim);
    float distanceToSurface = min(toSide, toBase);

    // Inside: above the base plane and on the axis side of the slanted line.
    vec2 side = rim - apex;
    vec2 fromApex = meridian - apex;
    bool axisSideOfSlant = side.x * fromApex.y - side.y * fromApex.x < 0.0;
    bool inside = meridian.y > -halfHeight && axisSideOfSlant;
    return inside ? -distanceToSurface : distanceToSurface;
}
