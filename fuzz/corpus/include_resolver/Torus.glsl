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
    const float c = 0.8660254, s = 0.5;
    p = vec3(p.x, c * p.y + s * p.z, -s * p.y + c * p.z);
    vec2 q = vec2(length(p.xz) - 0.65, p.y);
    return length(q) - 0.25;
}
