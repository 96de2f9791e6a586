/* sdfwb
name: Helicopter
category: Vehicle
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A light helicopter facing +X with its rotors turning: a bubble cabin with a glazed
  nose, an engine hump and mast, a tapering tail boom with a fin and a two-blade tail rotor,
  skids on struts, and a four-blade main rotor (a quarter turn every 0.3 s, so it loops).
  Rotors are rigid rotations of symmetric blades (angular repetition); ellipsoid bounds,
  unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p, float time) {
    vec3 m = vec3(p.x, p.y, abs(p.z));
    // Cabin: a rounded bubble, nose forward.
    float cabin = sdEllipsoid(p - vec3(0.22, -0.12, 0.0), vec3(0.38, 0.27, 0.26));
    float hump = sdEllipsoid(p - vec3(0.0, 0.08, 0.0), vec3(0.26, 0.14, 0.16));
    float body = smoothMin(cabin, hump, 0.1);
    // Tail boom to -X, rising slightly, with a fin at its end.
    float boom = sdRoundCone(p, vec3(-0.05, -0.02, 0.0), vec3(-0.72, 0.08, 0.0), 0.11, 0.035);
    body = smoothMin(body, boom, 0.08);
    vec3 f = p - vec3(-0.7, 0.08, 0.0);
    float fin = sdPlate(sdTriangle2(f.xy, vec2(0.08, 0.0), vec2(-0.1, 0.0), vec2(-0.08, 0.25)) - 0.02, f.z, 0.012);
    body = smoothMin(body, fin, 0.02);

    // Skids: two long tubes on struts.
    float skid = sdCapsule(m, vec3(-0.3, -0.5, 0.22), vec3(0.45, -0.5, 0.22), 0.025);
    skid = min(skid, sdCapsule(m, vec3(0.45, -0.5, 0.22), vec3(0.55, -0.44, 0.22), 0.025));
    float struts = min(sdCapsule(m, vec3(0.3, -0.3, 0.12), vec3(0.3, -0.5, 0.22), 0.018),
                       sdCapsule(m, vec3(-0.12, -0.25, 0.1), vec3(-0.15, -0.5, 0.22), 0.018));
    body = min(body, min(skid, struts));

    // Mast and main rotor: four blades spinning about Y.
    float mast = sdCylinder(p - vec3(0.0, 0.26, 0.0), 0.03, 0.08);
    float rotorHub = sdCylinder(p - vec3(0.0, 0.34, 0.0), 0.06, 0.025);
    vec3 r = p - vec3(0.0, 0.35, 0.0);
    r.xz = rotate2(r.xz, MODEL_TAU * time / 1.2);
    vec2 s = sectorFold(r.xz, 4.0);
    float blade = sdBox(vec3(s.x - 0.46, r.y, s.y), vec3(0.4, 0.008, 0.04)) - 0.006;
    body = min(body, min(min(mast, rotorHub), blade));

    // Tail rotor: two blades spinning in the XY plane on the +z side of the fin.
    vec3 t = p - vec3(-0.74, 0.14, 0.04);
    t.xy = rotate2(t.xy, MODEL_TAU * time / 0.4);
    vec2 u = sectorFold(t.xy, 2.0);
    float tailBlade = sdBox(vec3(u.x - 0.07, u.y, t.z), vec3(0.07, 0.018, 0.005)) - 0.004;
    float tailHub = sdCylinderZ(t, 0.025, 0.02);
    return min(body, min(tailBlade, tailHub));
}
