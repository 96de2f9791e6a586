/* sdfwb
name: Elephant
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: An elephant facing +X: a heavy ellipsoid body on four column legs, a domed head,
  a trunk of tapered segments curling down and forward, big flat ears, tusks, eyes and a
  thin tail. Ellipsoid bounds, unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));   // mirrored through z = 0 for paired parts

    float body = sdEllipsoid(p - vec3(-0.12, 0.05, 0.0), vec3(0.55, 0.38, 0.36));
    // Legs: rounded columns, front and back pairs.
    vec3 l = vec3(p.x + 0.1 - 0.29 * sign(p.x + 0.1), p.y, abs(p.z) - 0.19);
    float leg = sdRoundCone(l, vec3(0.0, -0.1, 0.0), vec3(0.0, -0.78, 0.0), 0.13, 0.12);
    leg = max(leg, -0.86 - p.y);                       // flat soles
    float elephant = smoothMin(body, leg, 0.08);

    // Head with a domed forehead, blended onto the body.
    float head = sdSphere(p - vec3(0.42, 0.22, 0.0), 0.27);
    elephant = smoothMin(elephant, head, 0.12);

    // Trunk: tapered segments bending down and curling forward at the tip.
    float trunk = sdRoundCone(p, vec3(0.6, 0.15, 0.0), vec3(0.74, -0.15, 0.0), 0.12, 0.09);
    trunk = min(trunk, sdRoundCone(p, vec3(0.74, -0.15, 0.0), vec3(0.76, -0.45, 0.0), 0.09, 0.07));
    trunk = min(trunk, sdRoundCone(p, vec3(0.76, -0.45, 0.0), vec3(0.86, -0.6, 0.0), 0.07, 0.06));
    elephant = smoothMin(elephant, trunk, 0.06);

    // Ears: big flat rounded flaps on the sides of the head, swept back a little.
    vec3 e = m - vec3(0.3, 0.2, 0.25);
    e.xz = rotate2(e.xz, -0.5);
    float earOutline = sdRoundCone2(e.xy, vec2(0.0, 0.06), vec2(-0.04, -0.16), 0.2, 0.13);
    float ear = sdPlate(earOutline, e.z, 0.03);
    elephant = smoothMin(elephant, ear, 0.04);

    // Tusks and eyes.
    float tusk = sdRoundCone(m, vec3(0.6, 0.02, 0.12), vec3(0.8, -0.12, 0.17), 0.04, 0.015);
    float eye = sdSphere(m - vec3(0.6, 0.3, 0.14), 0.035);
    elephant = min(elephant, min(tusk, eye));

    // Thin tail hanging at the back.
    float tail = sdRoundCone(p, vec3(-0.62, 0.12, 0.0), vec3(-0.72, -0.25, 0.0), 0.03, 0.02);
    return smoothMin(elephant, tail, 0.03);
}
