/* sdfwb
name: Chess Knight
category: Misc
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A chess knight facing +X: a round stepped base with a bead, and a horse's head and
  neck built as a 2D profile (tapered discs for neck, head and muzzle, triangles for the ears
  and mane, a cut for the mouth) given a thick, fully rounded rim, with eyes and nostrils.
  Exact revolved parts; the profile is a union of exact 2D shapes (a bound), extruded:
  conservative.
*/
#include "../lib/modelling.glsl"

float headProfile(vec2 q) {
    // Neck rising from the base, leaning forward.
    float neck = sdRoundCone2(q, vec2(-0.05, -0.45), vec2(0.0, 0.15), 0.27, 0.2);
    // Head: a long tapered shape sloping down towards the muzzle at +X.
    float head = sdRoundCone2(q, vec2(0.0, 0.3), vec2(0.36, 0.02), 0.2, 0.12);
    float shape = smoothMin(neck, head, 0.08);
    // Ear pointing up and back, and the mane down the back of the neck.
    float ear = sdTriangle2(q, vec2(-0.12, 0.38), vec2(0.06, 0.45), vec2(-0.08, 0.65)) - 0.02;
    float mane = sdTriangle2(q, vec2(-0.14, 0.4), vec2(-0.3, -0.28), vec2(-0.12, -0.2)) - 0.05;
    shape = smoothMin(shape, min(ear, mane), 0.04);
    // Mouth: a small wedge cut into the front of the muzzle.
    float mouth = sdTriangle2(q, vec2(0.52, -0.05), vec2(0.34, -0.01), vec2(0.52, 0.02));
    shape = max(shape, -mouth);
    // Chest: scoop under the jaw.
    float scoop = length(q - vec2(0.3, -0.3)) - 0.17;
    return smoothSubtract(shape, scoop, 0.04);
}

float sdf(vec3 p) {
    // Base like the other pieces.
    float base = sdCylinder(p - vec3(0.0, -0.82, 0.0), 0.46, 0.06) - 0.02;
    base = min(base, sdFrustum(p - vec3(0.0, -0.68, 0.0), 0.4, 0.32, 0.08));
    base = min(base, sdTorus(p - vec3(0.0, -0.58, 0.0), 0.3, 0.04));

    // Head: the profile given a thickness of 0.34 with a rounded rim.
    vec3 h = p - vec3(0.0, 0.1, 0.0);
    float head = sdPlate(headProfile(h.xy), h.z, 0.17);
    float knight = smoothMin(base, head, 0.06);

    // Eyes and nostrils as small bumps on both sides.
    vec3 m = vec3(h.x, h.y, abs(h.z));
    float eye = sdSphere(m - vec3(0.08, 0.3, 0.15), 0.04);
    float nostril = sdSphere(m - vec3(0.42, 0.04, 0.1), 0.03);
    return min(knight, min(eye, nostril));
}
