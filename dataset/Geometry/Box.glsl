/* sdfwb
name: Box
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Axis-aligned box, half extents (0.8, 0.5, 0.6); exact inside and outside.
*/
float sdf(vec3 p) {
    vec3 q = abs(p) - vec3(0.8, 0.5, 0.6);
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}
