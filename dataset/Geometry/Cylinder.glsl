/* sdfwb
name: Cylinder
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Upright capped cylinder, radius 0.7, half height 0.8. A solid of revolution is measured in
  its meridian half-plane (distance from the axis, height), where the profile is a rectangle; the
  exact 2D rectangle distance is the exact 3D distance.
  Parameters: radius (0.05-0.7), half height (0.05-0.8).
*/
uniform float radius = 0.7;      // @range 0.05 0.7 @step 0.01 @label "Radius"
uniform float halfHeight = 0.8;  // @range 0.05 0.8 @step 0.01 @label "Half height"

float sdf(vec3 p) {
    // Meridian coordinates, folded to the upper half: (distance from the axis, |height|).
    vec2 meridian = vec2(length(p.xz), abs(p.y));
    vec2 overshoot = meridian - vec2(radius, halfHeight);
    return min(max(overshoot.x, overshoot.y), 0.0) + length(max(overshoot, 0.0));
}
