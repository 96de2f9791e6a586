/* sdfwb
name: Flying Bird
category: Animal
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A small bird in flight towards +X, flapping its wings (period 1.2 s). Ellipsoid body,
  round head with a cone beak, a fanned tail plate and two swept wing plates that rotate
  rigidly about shoulder axes along X. The wings are one plate mirrored through z = 0.
  Rigid motions keep distances; ellipsoid bounds and smooth unions make it conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p, float time) {
    // Body slightly nose-up, head in front, beak pointing to +X.
    vec3 b = p - vec3(-0.05, -0.05, 0.0);
    b.xy = rotate2(b.xy, -0.15);
    float body = sdEllipsoid(b, vec3(0.42, 0.2, 0.2));
    float head = sdSphere(p - vec3(0.38, 0.08, 0.0), 0.15);
    float bird = smoothMin(body, head, 0.1);
    float beak = sdRoundCone(p, vec3(0.5, 0.07, 0.0), vec3(0.7, 0.04, 0.0), 0.05, 0.008);
    bird = min(bird, beak);
    float eye = sdSphere(vec3(p.x, p.y, abs(p.z)) - vec3(0.45, 0.13, 0.09), 0.03);
    bird = min(bird, eye);

    // Tail: a flat fan behind the body, spread in the XZ plane.
    vec3 t = p - vec3(-0.45, -0.08, 0.0);
    t.xy = rotate2(t.xy, 0.12);
    float tail = sdPlate(sdRoundCone2(t.xz, vec2(0.05, 0.0), vec2(-0.3, 0.0), 0.05, 0.13), t.y, 0.02);
    bird = smoothMin(bird, tail, 0.05);

    // Wings: mirrored through z = 0; each hinges about an axis along X at the shoulder.
    float flap = 0.75 * sin(6.2831853 * time / 1.2);
    vec3 w = vec3(p.x, p.y, abs(p.z)) - vec3(0.05, 0.05, 0.1);
    w.yz = rotate2(w.yz, -flap);
    // Wing outline in the wing's own XZ plane: broad at the root, swept back to a pointed tip.
    float outline = sdRoundCone2(w.xz, vec2(0.0, 0.05), vec2(-0.14, 0.66), 0.18, 0.08);
    float wing = sdPlate(outline, w.y, 0.025);
    return smoothMin(bird, wing, 0.05);
}
