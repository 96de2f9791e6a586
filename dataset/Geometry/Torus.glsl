/* sdfwb
name: Torus
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Ring torus in the XZ plane, tilted towards the viewer; major radius 0.65, tube radius 0.25. Parameters: major radius (0.35-0.7), tube radius (0.05-0.25).
*/
uniform float majorRadius = 0.65;  // @range 0.35 0.7 @step 0.01 @label "Major radius"
uniform float tubeRadius = 0.25;   // @range 0.05 0.25 @step 0.01 @label "Tube radius"

float sdf(vec3 p) {
    // Tilt 30 degrees about X so the hole is visible from the default camera.
    const float c = 0.8660254, s = 0.5;
    p = vec3(p.x, c * p.y + s * p.z, -s * p.y + c * p.z);
    vec2 q = vec2(length(p.xz) - majorRadius, p.y);
    return length(q) - tubeRadius;
}
