/* sdfwb
name: Sphere
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Sphere of radius 0.8 at the origin; the simplest exact SDF. Parameters: radius (0.1-0.95).
*/
uniform float radius = 0.8;  // @range 0.1 0.95 @step 0.01 @label "Radius"

float sdf(vec3 p) {
    return length(p) - radius;
}
