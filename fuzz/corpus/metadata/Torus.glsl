/* sdfwb
name: Torus
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Ring torus in the XZ plane, tilted towards the viewer; major radius 0.65, tube radius 0.25.
*/
float sdf(vec3 p) {
    // Tilt 30 degrees about X so the hole is visible from the default camera.
