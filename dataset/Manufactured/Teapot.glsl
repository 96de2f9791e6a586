/* sdfwb
name: Teapot
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A teapot pouring towards +X: a squat round body on a foot ring, a domed lid with a
  knob, an S-curved spout made of tapered segments that rises from the lower front, and a
  loop handle at the back (torus in the XY plane, outer half). Ellipsoid bounds, unions and
  smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 c = p - vec3(-0.05, -0.2, 0.0);
    float body = sdEllipsoid(c, vec3(0.55, 0.45, 0.55));
    float foot = sdTorus(c + vec3(0.0, 0.38, 0.0), 0.35, 0.06);
    float pot = smoothMin(body, foot, 0.06);
    pot = max(pot, -0.48 - c.y);                            // stands flat

    // Lid: a low dome with a rim and a round knob.
    float lidRim = sdTorus(c - vec3(0.0, 0.37, 0.0), 0.27, 0.035);
    float lid = sdEllipsoid(c - vec3(0.0, 0.38, 0.0), vec3(0.28, 0.13, 0.28));
    float knob = sdSphere(c - vec3(0.0, 0.56, 0.0), 0.07);
    float neck = sdCylinder(c - vec3(0.0, 0.5, 0.0), 0.03, 0.03);
    pot = min(pot, smoothMin(smoothMin(lid, lidRim, 0.03), min(knob, neck), 0.03));

    // Spout: tapered segments from the lower front, curving up and out to +X.
    float spout = sdRoundCone(c, vec3(0.38, -0.12, 0.0), vec3(0.62, 0.08, 0.0), 0.12, 0.07);
    spout = smoothMin(spout, sdRoundCone(c, vec3(0.62, 0.08, 0.0), vec3(0.8, 0.34, 0.0), 0.07, 0.05), 0.04);
    // Open mouth at the tip.
    float mouth = sdCapsule(c, vec3(0.78, 0.3, 0.0), vec3(0.9, 0.48, 0.0), 0.03);
    spout = max(spout, -mouth);
    pot = smoothMin(pot, spout, 0.06);

    // Handle: a loop on the -X side.
    vec3 h = c - vec3(-0.55, 0.02, 0.0);
    float handle = sdTorusXY(vec3(h.x, h.y, h.z), 0.25, 0.055);
    handle = max(handle, h.x + 0.05);
    return smoothMin(pot, handle, 0.05);
}
