/* sdfwb
name: Rabbit
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A sitting rabbit facing +X: a pear-shaped body with big haunches, a round head with
  a snout, two tall ears, front paws, hind feet and a pom-pom tail. Ellipsoid bounds,
  unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));   // mirrored through z = 0 for paired parts

    // Body: a pear leaning back, with haunches on both sides.
    vec3 b = p - vec3(-0.18, -0.38, 0.0);
    b.xy = rotate2(b.xy, 0.5);
    float body = sdEllipsoid(b, vec3(0.32, 0.42, 0.32));
    float haunch = sdEllipsoid(m - vec3(-0.28, -0.55, 0.2), vec3(0.3, 0.25, 0.15));
    body = smoothMin(body, haunch, 0.1);
    float hindFoot = sdEllipsoid(m - vec3(-0.05, -0.78, 0.25), vec3(0.25, 0.07, 0.09));
    body = smoothMin(body, hindFoot, 0.06);
    float frontPaw = sdCapsule(m, vec3(0.1, -0.45, 0.1), vec3(0.15, -0.8, 0.1), 0.07);
    body = smoothMin(body, frontPaw, 0.05);

    // Head up front, a snout, and a round tail at the back.
    float head = sdEllipsoid(p - vec3(0.18, 0.08, 0.0), vec3(0.26, 0.22, 0.22));
    float snout = sdSphere(p - vec3(0.38, 0.03, 0.0), 0.11);
    head = smoothMin(head, snout, 0.08);
    float rabbit = smoothMin(body, head, 0.12);
    float tail = sdSphere(p - vec3(-0.6, -0.52, 0.0), 0.1);
    rabbit = smoothMin(rabbit, tail, 0.04);

    // Ears: long flat-ish ellipsoids leaning back and apart.
    vec3 e = m - vec3(0.08, 0.45, 0.09);
    e.xy = rotate2(e.xy, 0.3);
    e.yz = rotate2(e.yz, -0.18);
    float ear = sdEllipsoid(e, vec3(0.09, 0.34, 0.05));
    rabbit = smoothMin(rabbit, ear, 0.06);

    float eye = sdSphere(m - vec3(0.33, 0.15, 0.12), 0.04);
    float nose = sdSphere(p - vec3(0.49, 0.06, 0.0), 0.03);
    return min(rabbit, min(eye, nose));
}
