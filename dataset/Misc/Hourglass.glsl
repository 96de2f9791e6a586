/* sdfwb
name: Hourglass
category: Misc
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: An hourglass: two glass bulbs tapering to a narrow waist (each a round cone from a
  small sphere at the neck to a large one near the end plate, mirrored through y = 0 and
  blended), held between two round wooden end plates by three turned posts with beads
  (angular repetition). Exact round cones, cylinders, capsules and spheres joined with min
  and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Glass: the upper bulb mirrored to make the lower one; blended at the neck.
    vec3 g = vec3(p.x, abs(p.y), p.z);
    float bulb = sdRoundCone(g, vec3(0.0, 0.02, 0.0), vec3(0.0, 0.42, 0.0), 0.035, 0.28);
    float neck = sdCylinder(p, 0.045, 0.06);
    float glass = smoothMin(bulb, neck, 0.04);
    // Caps where the glass meets the plates.
    float caps = sdCylinder(vec3(p.x, abs(p.y) - 0.68, p.z), 0.2, 0.04);

    // End plates and three posts with beads.
    float plates = sdCylinder(vec3(p.x, abs(p.y) - 0.76, p.z), 0.42, 0.05) - 0.02;
    vec2 s = sectorFold(rotate2(p.xz, 0.5236), 3.0);
    vec3 q = vec3(s.x - 0.36, p.y, s.y);
    float post = sdCapsuleY(q, 0.7, 0.032);
    float bead = sdSphere(vec3(q.x, abs(q.y) - 0.45, q.z), 0.055);
    bead = min(bead, sdSphere(q, 0.05));
    float frame = min(plates, min(post, bead));
    return min(min(glass, caps), frame);
}
