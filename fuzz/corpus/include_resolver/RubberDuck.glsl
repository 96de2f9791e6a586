/* sdfwb
name: Rubber Duck
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A bath duck looking towards +X: an ellipsoid body with a flat bottom and an upturned
  tail, a round head blended onto it, a flattened two-part beak and bead eyes.
  Conservative: ellipsoids are bounds and the parts are joined with min and smooth minimum,
  which keep the gradient at most 1 but underestimate the distance near the seams.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Body: a wide ellipsoid, cut flat underneath so the duck floats upright.
    float body = sdEllipsoid(p - vec3(-0.08, -0.28, 0.0), vec3(0.72, 0.42, 0.52));
    // Tail: a small ellipsoid tilted upwards at the back.
    vec3 t = p - vec3(-0.7, -0.08, 0.0);
    t.xy = rotate2(t.xy, 0.7);
    float tail = sdEllipsoid(t, vec3(0.22, 0.1, 0.2));
    body = smoothMin(body, tail, 0.15);
    body = max(body, -0.62 - p.y);

    // Head sits forward on the body with a soft neck.
    float head = sdSphere(p - vec3(0.32, 0.36, 0.0), 0.33);
    float duck = smoothMin(body, head, 0.12);

    // Beak: two flat lobes (upper and lower) pointing to +X.
    float upper = sdEllipsoid(p - vec3(0.66, 0.32, 0.0), vec3(0.2, 0.06, 0.15));
    float lower = sdEllipsoid(p - vec3(0.62, 0.25, 0.0), vec3(0.15, 0.04, 0.11));
    duck = smoothMin(duck, min(upper, lower), 0.03);

    // Eyes: small beads on both sides of the head (mirrored through z = 0).
    vec3 e = vec3(p.x, p.y, abs(p.z));
    float eye = sdSphere(e - vec3(0.52, 0.47, 0.17), 0.065);
    return min(duck, eye);
}
