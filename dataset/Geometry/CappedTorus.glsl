/* sdfwb
name: Capped Torus
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Horseshoe: a tube of radius 0.2 around a circular arc of radius 0.62 that spans 130 degrees
  either side of straight up, leaving the opening at the bottom; its plane faces the +X side,
  turned 30 degrees towards +Z. The arc is mirror-symmetric, so the point is folded to one side;
  there the nearest arc point is the circle point in the point's direction when that direction
  falls on the arc, otherwise the arc's end. Both cases are exact, and the tube radius is below
  the arc radius and half the gap, so subtracting it stays exact inside.
  Parameters: arc radius (0.3-0.65), tube radius (0.03-0.22), arc half angle (20-130 degrees).
*/
uniform float arcRadius = 0.62;     // @range 0.3 0.65 @step 0.01 @label "Arc radius"
uniform float tubeRadius = 0.2;     // @range 0.03 0.22 @step 0.01 @label "Tube radius"
uniform float arcHalfAngle = 130.0; // @range 20 130 @step 1 @label "Arc half angle (degrees)"

float sdf(vec3 p) {
    // (sin, cos) of the half angle: direction of the arc's end from its centre.
    vec2 arcEnd = vec2(sin(radians(arcHalfAngle)), cos(radians(arcHalfAngle)));
    const float centreHeight = -0.11;                   // lifts the bounding box to the middle of the cube
    const vec3 facing = vec3(0.8660254, 0.0, 0.5);
    const vec3 across = vec3(-0.5, 0.0, 0.8660254);

    // In-plane coordinates (folded across the arc's mirror line) and the offset from the plane.
    vec2 q = vec2(abs(dot(p, across)), p.y - centreHeight);
    float offPlane = dot(p, facing);

    // The point's direction is on the arc when it lies on the upper side of the ray to the arc's end.
    bool facesArc = arcEnd.x * q.y - arcEnd.y * q.x >= 0.0;
    float distanceToArc = facesArc ? length(vec2(length(q) - arcRadius, offPlane))
                                   : length(vec3(q - arcEnd * arcRadius, offPlane));
    return distanceToArc - tubeRadius;
}
