/* sdfwb
name: Bicycle
category: Vehicle
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A diamond-frame bicycle riding towards +X: two spoked wheels (torus tyres, twelve
  spokes by angular repetition, hubs), a frame of capsule tubes (top, down and seat tubes,
  chain and seat stays, fork), handlebars with grips, a saddle, a chainring and pedals.
  Exact capsules, tori and boxes joined with min; the saddle is an ellipsoid bound.
  Conservative.
*/
#include "../lib/modelling.glsl"

float wheel(vec3 q) {
    float tyre = sdTorusXY(q, 0.31, 0.03);
    float rim = sdTorusXY(q, 0.28, 0.012);
    vec2 s = sectorFold(q.xy, 12.0);
    float spoke = sdCapsule(vec3(s, q.z), vec3(0.03, 0.0, 0.0), vec3(0.28, 0.0, 0.0), 0.006);
    float hub = sdCylinderZ(q, 0.03, 0.04);
    return min(min(tyre, rim), min(spoke, hub));
}

float sdf(vec3 p) {
    vec3 rearHub = vec3(-0.52, -0.5, 0.0), frontHub = vec3(0.52, -0.5, 0.0);
    vec3 bracket = vec3(-0.06, -0.48, 0.0), seatTop = vec3(-0.2, 0.0, 0.0);
    vec3 headTop = vec3(0.32, 0.0, 0.0), headBottom = vec3(0.37, -0.14, 0.0);
    float wheels = min(wheel(p - rearHub), wheel(p - frontHub));

    const float tube = 0.022;
    float frame = sdCapsule(p, bracket, seatTop, tube);
    frame = min(frame, sdCapsule(p, seatTop, headTop, tube));
    frame = min(frame, sdCapsule(p, bracket, headBottom, tube + 0.004));
    frame = min(frame, sdCapsule(p, headBottom, headTop, tube + 0.006));
    // Chain and seat stays and the fork are paired either side of the wheel (mirrored in z).
    vec3 m = vec3(p.x, p.y, abs(p.z));
    vec3 side = vec3(0.0, 0.0, 0.05);
    frame = min(frame, sdCapsule(m, rearHub + side, bracket + vec3(0.0, 0.0, 0.02), 0.015));
    frame = min(frame, sdCapsule(m, rearHub + side, seatTop + vec3(0.0, -0.04, 0.015), 0.014));
    frame = min(frame, sdCapsule(m, frontHub + side, headBottom + vec3(0.0, 0.0, 0.02), 0.016));

    // Handlebars: a stem, a bar across and grips.
    vec3 barCentre = vec3(0.28, 0.12, 0.0);
    float bars = sdCapsule(p, headTop, barCentre, 0.018);
    bars = min(bars, sdCapsule(m, barCentre, barCentre + vec3(-0.06, 0.0, 0.25), 0.016));
    bars = min(bars, sdCapsule(m, barCentre + vec3(-0.06, 0.0, 0.2), barCentre + vec3(-0.08, 0.0, 0.28), 0.024));
    // Saddle on a seat post.
    float post = sdCapsule(p, seatTop, seatTop + vec3(-0.02, 0.08, 0.0), 0.016);
    float saddle = sdEllipsoid(p - vec3(-0.2, 0.1, 0.0), vec3(0.13, 0.03, 0.06));

    // Chainring, cranks and pedals.
    float ring = sdCylinderZ(p - bracket - vec3(0.0, 0.0, 0.04), 0.09, 0.008);
    float crank = sdCapsule(p, bracket + vec3(0.0, 0.0, 0.05), bracket + vec3(0.1, -0.14, 0.06), 0.014);
    crank = min(crank, sdCapsule(p, bracket + vec3(0.0, 0.0, -0.05), bracket + vec3(-0.1, 0.14, -0.06), 0.014));
    float pedals = min(sdBox(p - bracket - vec3(0.1, -0.14, 0.1), vec3(0.04, 0.01, 0.04)),
                       sdBox(p - bracket - vec3(-0.1, 0.14, -0.1), vec3(0.04, 0.01, 0.04)));
    float drive = min(min(ring, crank), pedals);
    return min(min(wheels, frame), min(min(bars, post), min(saddle, drive)));
}
