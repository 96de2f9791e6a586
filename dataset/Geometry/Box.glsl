/* sdfwb
name: Box
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Axis-aligned box, half extents (0.8, 0.5, 0.6); exact inside and outside. Parameters: half extents (0.1-0.8 each).
*/
uniform vec3 halfExtents = vec3(0.8, 0.5, 0.6);  // @range 0.1 0.8 @step 0.01 @label "Half extents"

float sdf(vec3 p) {
    vec3 q = abs(p) - halfExtents;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}
