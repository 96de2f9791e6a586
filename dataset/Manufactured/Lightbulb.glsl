/* sdfwb
name: Light Bulb
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: An incandescent light bulb standing on its screw base: a glass globe flowing into a
  tapered neck, a threaded metal base (a cylinder with five rounded thread rings), an
  insulating band and a round contact at the bottom. Spheres, frustums, tori and cylinders
  joined with min and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Glass: a globe blended into a neck that narrows to the base.
    float globe = sdSphere(p - vec3(0.0, 0.32, 0.0), 0.55);
    float neck = sdFrustum(p - vec3(0.0, -0.25, 0.0), 0.2, 0.34, 0.2);
    float glass = smoothMin(globe, neck, 0.2);
    glass = max(glass, -0.42 - p.y);

    // Screw base: a core cylinder with thread rings every 0.075.
    float core = sdCylinder(p - vec3(0.0, -0.6, 0.0), 0.19, 0.18);
    float yRing = clamp(round((p.y + 0.6) / 0.075), -2.0, 2.0) * 0.075 - 0.6;
    float rings = sdTorus(p - vec3(0.0, yRing, 0.0), 0.19, 0.03);
    float base = min(core, rings);
    float collar = sdCylinder(p - vec3(0.0, -0.43, 0.0), 0.21, 0.025) - 0.01;
    // Insulator band and contact nub at the very bottom.
    float insulator = sdFrustum(p - vec3(0.0, -0.82, 0.0), 0.11, 0.17, 0.04);
    float contact = sdSphere(p - vec3(0.0, -0.86, 0.0), 0.07);
    return min(min(glass, min(base, collar)), min(insulator, contact));
}
