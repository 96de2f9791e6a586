/* sdfwb
name: Hexagonal Prism
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Upright regular hexagonal prism, apothem 0.78 (a flat side faces +X), half height 0.62.
  The hexagon's mirror lines fold any point into the 30-degree wedge next to +X; folding by a
  mirror of the shape never moves the nearest boundary point farther, so there the exact 2D
  distance is the distance to one half side. Extruding an exact 2D distance along Y (the
  rectangle rule on (2D distance, |y| - half height)) keeps it exact.
  Parameters: apothem (0.1-0.78), half height (0.05-0.62).
*/
uniform float apothem = 0.78;     // @range 0.1 0.78 @step 0.01 @label "Apothem"
uniform float halfHeight = 0.62;  // @range 0.05 0.62 @step 0.01 @label "Half height"

float sdf(vec3 p) {
    float halfSide = apothem * (0.45033 / 0.78);  // apothem * tan(30 deg): half the length of one side

    vec2 q = abs(p.xz);
    // Mirror at 60 degrees, then at 30 degrees; each normal points to the side we keep.
    const vec2 mirror60 = vec2(0.8660254, -0.5);
    q -= 2.0 * min(dot(q, mirror60), 0.0) * mirror60;
    const vec2 mirror30 = vec2(0.5, -0.8660254);
    q -= 2.0 * min(dot(q, mirror30), 0.0) * mirror30;

    // q now lies in the wedge 0..30 degrees; its piece of boundary is x = apothem, 0 <= z <= halfSide.
    vec2 nearest = vec2(apothem, clamp(q.y, 0.0, halfSide));
    float hexagon = length(q - nearest) * sign(q.x - apothem);

    vec2 w = vec2(hexagon, abs(p.y) - halfHeight);
    return min(max(w.x, w.y), 0.0) + length(max(w, 0.0));
}
