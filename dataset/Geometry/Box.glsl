/* sdfwb
name: Box
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Axis-aligned box, half extents (0.8, 0.5, 0.6); exact inside and outside. Parameters: half width (0.1-0.8), half height (0.1-0.5), half depth (0.1-0.6).
*/
uniform float halfWidth = 0.8;   // @range 0.1 0.8 @step 0.01 @label "Half width (X)"
uniform float halfHeight = 0.5;  // @range 0.1 0.5 @step 0.01 @label "Half height (Y)"
uniform float halfDepth = 0.6;   // @range 0.1 0.6 @step 0.01 @label "Half depth (Z)"

float sdf(vec3 p) {
    vec3 q = abs(p) - vec3(halfWidth, halfHeight, halfDepth);
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}
