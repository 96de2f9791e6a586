/* sdfwb
name: Sphere
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Sphere of radius 0.8 at the origin; the simplest exact SDF.
*/
float sdf(vec3 p) {
    return length(p) - 0.8;
}
