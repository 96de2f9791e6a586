/* sdfwb
name: Sitting Cat
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A cat sitting upright and looking towards +X: a pear-shaped body with haunches,
  straight front legs, a round head with cheeks, a muzzle and two pointed ears, and a tail
  curled around the front paws (a tube along a circular arc). Ellipsoid bounds, unions and
  smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));   // mirrored through z = 0 for paired parts

    // Body: a pear leaning back slightly, with haunches.
    vec3 b = p - vec3(-0.12, -0.38, 0.0);
    b.xy = rotate2(b.xy, 0.25);
    float body = sdEllipsoid(b, vec3(0.3, 0.45, 0.28));
    float haunch = sdEllipsoid(m - vec3(-0.2, -0.62, 0.16), vec3(0.3, 0.22, 0.16));
    body = smoothMin(body, haunch, 0.1);
    float chest = sdEllipsoid(p - vec3(0.02, -0.2, 0.0), vec3(0.22, 0.3, 0.22));
    body = smoothMin(body, chest, 0.1);
    float leg = sdRoundCone(m, vec3(0.12, -0.3, 0.09), vec3(0.18, -0.8, 0.09), 0.07, 0.06);
    body = smoothMin(body, leg, 0.05);

    // Head: round, with full cheeks and a small muzzle.
    float head = sdEllipsoid(p - vec3(0.1, 0.26, 0.0), vec3(0.24, 0.22, 0.26));
    float muzzle = sdEllipsoid(p - vec3(0.3, 0.19, 0.0), vec3(0.1, 0.08, 0.12));
    head = smoothMin(head, muzzle, 0.06);
    // Ears: pointed cones on top, leaning out.
    float ear = sdRoundCone(m, vec3(0.08, 0.38, 0.13), vec3(0.06, 0.62, 0.18), 0.1, 0.012);
    head = smoothMin(head, ear, 0.04);
    float cat = smoothMin(body, head, 0.08);

    float eye = sdSphere(m - vec3(0.29, 0.32, 0.09), 0.04);
    float nose = sdSphere(p - vec3(0.4, 0.22, 0.0), 0.025);
    cat = min(cat, min(eye, nose));

    // Tail: a tube lying on the ground, curling round the body to the front paws.
    vec3 t = p - vec3(-0.15, -0.8, 0.0);
    t.xz = rotate2(t.xz, -1.2);           // arc from behind the cat round its +z side
    float tail = sdArcTubeXZ(t, 0.4, 1.5, 0.06);
    return smoothMin(cat, tail, 0.05);
}
