/* sdfwb
name: Submarine
category: Vehicle
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A submarine cruising towards +X with its five-blade propeller turning (a fifth of a
  turn every 0.5 s, so it loops): a long hull with a round bow and a tapering stern, a conning
  tower (sail) with dive planes and a periscope, cross-shaped stern fins and portholes. The
  propeller is a rigid rotation of five pitched blades, all evaluated (a pitched blade is not
  mirror symmetric, so angular folding would be discontinuous).
  Exact round cones, boxes and tori and ellipsoid bounds: conservative.
*/
#include "../lib/modelling.glsl"

// One propeller blade at angle `angle` around the X axis, pitched by 0.5 rad.
float propBlade(vec3 q, float angle) {
    vec2 r = rotate2(q.yz, -angle);
    vec3 bq = vec3(q.x, r.x, r.y);
    bq.xz = rotate2(bq.xz, 0.5);
    return sdEllipsoid(bq - vec3(0.0, 0.1, 0.0), vec3(0.015, 0.09, 0.04));
}

float submarine(vec3 p, float time) {
    vec3 m = vec3(p.x, p.y, abs(p.z));
    // Hull: a fat round bow blended into a cone that tapers to the stern.
    float bow = sdRoundCone(p, vec3(0.45, 0.0, 0.0), vec3(-0.2, 0.0, 0.0), 0.22, 0.22);
    float stern = sdRoundCone(p, vec3(-0.2, 0.0, 0.0), vec3(-0.72, 0.0, 0.0), 0.22, 0.05);
    float hull = smoothMin(bow, stern, 0.05);
    // Sail (conning tower): a rounded, tapered block with dive planes and a periscope.
    vec3 s = p - vec3(0.12, 0.3, 0.0);
    float sail = sdRoundBox(s, vec3(0.16, 0.12, 0.05), 0.04);
    sail = max(sail, dot(s - vec3(0.1, 0.0, 0.0), vec3(0.8, 0.6, 0.0)));   // raked front
    float divePlanes = sdRoundBox(m - vec3(0.14, 0.32, 0.1), vec3(0.05, 0.01, 0.09), 0.008);
    float periscope = min(sdCapsule(p, vec3(0.05, 0.4, 0.0), vec3(0.05, 0.58, 0.0), 0.016),
                          sdCapsule(p, vec3(0.05, 0.58, 0.0), vec3(0.11, 0.58, 0.0), 0.016));
    float sub = smoothMin(hull, sail, 0.05);
    sub = min(sub, min(divePlanes, periscope));
    // Stern fins: a cross of plates.
    vec3 f = p - vec3(-0.6, 0.0, 0.0);
    vec2 c = sectorFold(f.yz, 4.0);
    float fin = sdPlate(sdTriangle2(vec2(f.x, c.x), vec2(0.14, 0.0), vec2(-0.1, 0.0), vec2(-0.1, 0.2)) - 0.01, c.y, 0.01);
    sub = smoothMin(sub, fin, 0.02);
    // Portholes along both sides.
    float px = clamp(round((p.x - 0.1) / 0.16), -2.0, 1.0) * 0.16 + 0.1;
    // Rings in the XY plane on the hull side (|z| = 0.2), facing out along z.
    float holes = sdTorusXY(m - vec3(px, 0.03, 0.205), 0.035, 0.012);
    sub = min(sub, holes);

    // Propeller behind the stern, spinning about X.
    vec3 q = p - vec3(-0.78, 0.0, 0.0);
    float shaft = sdCylinderX(q - vec3(0.03, 0.0, 0.0), 0.02, 0.04);
    q.yz = rotate2(q.yz, MODEL_TAU * 0.4 * time);
    // Five pitched blades. A pitched blade is not mirror symmetric, so angular folding would
    // jump at the sector borders; near the hub every blade matters: evaluate all five.
    float blade = propBlade(q, 0.0);
    for (int i = 1; i < 5; ++i) blade = min(blade, propBlade(q, float(i) * MODEL_TAU / 5.0));
    float hub = sdSphere(q, 0.04);
    return min(sub, min(shaft, min(blade, hub)));
}

float sdf(vec3 p, float time) {
    // Uniform scale by 1.07 (exact: divide the point, multiply the distance), centred.
    const float scale = 1.07;
    return submarine(p / scale - vec3(-0.05, 0.0, 0.0), time) * scale;
}
