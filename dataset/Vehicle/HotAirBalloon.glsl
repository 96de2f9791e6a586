/* sdfwb
name: Hot Air Balloon
category: Vehicle
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A hot-air balloon: a teardrop envelope (a sphere blended into a cone narrowing to the
  mouth) with twelve raised seams between the gores, a burner frame, suspension ropes and a
  wicker basket with a padded rim. Angular repetition for the seams and ropes; exact spheres,
  frustums, boxes and capsules joined with min and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Envelope: a sphere on top of a cone that narrows to the mouth.
    float top = sdSphere(p - vec3(0.0, 0.3, 0.0), 0.55);
    float cone = sdFrustum(p - vec3(0.0, -0.1, 0.0), 0.16, 0.5, 0.26);
    float envelope = smoothMin(top, cone, 0.15);
    // Seams: twelve meridian ridges, each a thin wedge of the same shape slightly inflated.
    vec2 s = sectorFold(p.xz, 12.0);
    float seam = max(envelope - 0.012, abs(s.y) - 0.012);
    envelope = min(envelope, seam);
    envelope = max(envelope, -0.36 - p.y);                   // open mouth at the bottom

    // Ropes from the mouth down to the basket corners.
    vec2 r = sectorFold(rotate2(p.xz, 0.785398), 4.0);
    float ropes = sdCapsule(vec3(r.x, p.y, r.y), vec3(0.16, -0.36, 0.0), vec3(0.14, -0.62, 0.0), 0.01);
    float burner = sdCylinder(p - vec3(0.0, -0.5, 0.0), 0.07, 0.04);

    // Basket: a rounded box with a padded rim.
    float basket = sdRoundBox(p - vec3(0.0, -0.75, 0.0), vec3(0.14, 0.1, 0.14), 0.02);
    float rim = sdRoundBox(p - vec3(0.0, -0.64, 0.0), vec3(0.155, 0.015, 0.155), 0.015);
    return min(min(envelope, ropes), min(burner, min(basket, rim)));
}
