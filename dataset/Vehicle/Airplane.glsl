/* sdfwb
name: Propeller Plane
category: Vehicle
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A light propeller aircraft flying towards +X with its two-blade propeller spinning
  (half a turn every 0.25 s, so the motion loops). Tapered fuselage, cockpit canopy, straight
  wings with rounded tips, a tailplane and fin, a spinner and fixed landing gear. Plates come
  from exact 2D outlines; the propeller is a rigid rotation of two blades. Ellipsoid bounds,
  unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p, float time) {
    vec3 m = vec3(p.x, p.y, abs(p.z));
    // Fuselage: thick at the nose, tapering to the tail.
    float fuselage = sdRoundCone(p, vec3(0.45, 0.0, 0.0), vec3(-0.75, 0.08, 0.0), 0.13, 0.04);
    fuselage = smoothMin(fuselage, sdEllipsoid(p - vec3(0.35, 0.0, 0.0), vec3(0.28, 0.14, 0.14)), 0.06);
    float canopy = sdEllipsoid(p - vec3(0.18, 0.12, 0.0), vec3(0.2, 0.1, 0.09));
    float plane = smoothMin(fuselage, canopy, 0.03);

    // Wings: straight, slightly swept, rounded tips, a little dihedral.
    vec3 w = m - vec3(0.12, -0.04, 0.0);
    w.yz = rotate2(w.yz, -0.06);
    float wingOutline = sdRoundCone2(w.xz, vec2(0.0, 0.0), vec2(-0.05, 0.82), 0.14, 0.08);
    float wings = sdPlate(wingOutline, w.y, 0.025);
    // Tailplane and fin at the back.
    vec3 t = m - vec3(-0.68, 0.08, 0.0);
    float tailplane = sdPlate(sdRoundCone2(t.xz, vec2(0.0, 0.0), vec2(-0.03, 0.3), 0.09, 0.05), t.y, 0.015);
    vec3 f = p - vec3(-0.68, 0.08, 0.0);
    float finOutline = sdTriangle2(f.xy, vec2(0.14, 0.0), vec2(-0.1, 0.0), vec2(-0.1, 0.28));
    float fin = sdPlate(finOutline - 0.03, f.z, 0.015);
    plane = smoothMin(plane, min(wings, min(tailplane, fin)), 0.03);

    // Landing gear: two struts with wheels under the wings, a tail wheel.
    float strut = sdCapsule(m, vec3(0.25, -0.06, 0.1), vec3(0.28, -0.3, 0.2), 0.018);
    float wheel = sdTorusXY(m - vec3(0.28, -0.32, 0.2), 0.045, 0.03);
    plane = min(plane, min(strut, wheel));

    // Spinner and propeller at the nose, spinning about the X axis.
    float spinner = sdRoundCone(p, vec3(0.6, 0.0, 0.0), vec3(0.72, 0.0, 0.0), 0.08, 0.02);
    vec3 q = p - vec3(0.63, 0.0, 0.0);
    q.yz = rotate2(q.yz, MODEL_TAU * 2.0 * time);
    vec3 b = vec3(q.x, abs(q.y), q.z);                    // two opposite blades
    float blade = sdPlate(sdRoundCone2(b.yz, vec2(0.05, 0.0), vec2(0.4, 0.0), 0.04, 0.03), b.x, 0.012);
    return min(plane, min(spinner, blade));
}
