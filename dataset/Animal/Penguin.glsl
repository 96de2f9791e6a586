/* sdfwb
name: Penguin
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A standing penguin facing +X: an upright egg-shaped body blended with a round head,
  a short pointed beak, eyes, two flat flippers held slightly out and two flat feet.
  Ellipsoid bounds, unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Body: an egg, fuller at the bottom (two ellipsoids blended), with a slight belly bulge.
    float body = sdEllipsoid(p - vec3(0.0, -0.2, 0.0), vec3(0.42, 0.58, 0.44));
    float belly = sdEllipsoid(p - vec3(0.08, -0.3, 0.0), vec3(0.38, 0.45, 0.38));
    body = smoothMin(body, belly, 0.1);
    float head = sdSphere(p - vec3(0.04, 0.5, 0.0), 0.28);
    float penguin = smoothMin(body, head, 0.18);

    // Beak: a short cone pointing to +X, slightly downwards.
    float beak = sdRoundCone(p, vec3(0.25, 0.5, 0.0), vec3(0.47, 0.44, 0.0), 0.07, 0.012);
    penguin = smoothMin(penguin, beak, 0.03);

    // Everything below is mirrored through z = 0.
    vec3 m = vec3(p.x, p.y, abs(p.z));
    float eye = sdSphere(m - vec3(0.22, 0.58, 0.13), 0.045);
    penguin = min(penguin, eye);

    // Flippers: flat plates hanging down the sides, tilted out from the body.
    vec3 f = m - vec3(-0.02, 0.1, 0.38);
    f.yz = rotate2(f.yz, 0.5);
    float flipper = sdPlate(sdRoundCone2(f.xy, vec2(0.0, 0.0), vec2(-0.06, -0.48), 0.1, 0.045), f.z, 0.03);
    penguin = smoothMin(penguin, flipper, 0.04);

    // Feet: flat, three-lobed plates at the bottom pointing forwards.
    vec3 foot = m - vec3(0.15, -0.8, 0.16);
    float toes = sdRoundCone2(foot.xz, vec2(-0.1, 0.0), vec2(0.15, 0.0), 0.06, 0.09);
    float feet = sdPlate(toes, foot.y, 0.03);
    return smoothMin(penguin, feet, 0.04);
}
