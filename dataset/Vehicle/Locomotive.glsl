/* sdfwb
name: Steam Locomotive
category: Vehicle
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A toy-style steam locomotive heading towards +X: a cylindrical boiler on a frame
  with a flared smokestack, a steam dome and a headlamp, a cab at the back with a roof and
  windows, a pointed cowcatcher, three big driving wheels per side joined by a coupling rod,
  and buffers. Exact cylinders, frustums, boxes and tori joined with min and max: conservative.
*/
#include "../lib/modelling.glsl"

// Driving wheel with its axle along Z: tyre, web and hub.
float wheel(vec3 q, float r) {
    float tyre = sdCylinderZ(q, r, 0.035) - 0.01;
    float dish = sdCylinderZ(q - vec3(0.0, 0.0, 0.04), r - 0.035, 0.02);
    float hub = sdCylinderZ(q - vec3(0.0, 0.0, 0.03), 0.04, 0.03);
    return min(max(tyre, -dish), hub);
}

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));
    // Frame: a long low platform.
    float frame = sdBox(p - vec3(-0.05, -0.42, 0.0), vec3(0.8, 0.05, 0.25));
    // Boiler: a cylinder along X with a smoke-box ring at the front.
    float boiler = sdCylinderX(p - vec3(0.2, -0.15, 0.0), 0.22, 0.48);
    float smokeBox = sdCylinderX(p - vec3(0.63, -0.15, 0.0), 0.235, 0.06);
    float front = sdCylinderX(p - vec3(0.7, -0.15, 0.0), 0.16, 0.02);
    float loco = min(min(frame, boiler), min(smokeBox, front));
    // Smokestack flaring at the top, steam dome, headlamp.
    float stack = sdFrustum(p - vec3(0.52, 0.2, 0.0), 0.07, 0.12, 0.15);
    stack = max(stack, -sdCylinder(p - vec3(0.52, 0.35, 0.0), 0.08, 0.05));
    float dome = sdCapsuleY(p - vec3(0.12, 0.1, 0.0), 0.02, 0.09);
    float lamp = sdCylinderX(p - vec3(0.72, 0.13, 0.0), 0.05, 0.04);
    loco = min(loco, smoothMin(boiler, min(min(stack, dome), lamp), 0.04));

    // Cab: a box with window openings and an overhanging roof.
    float cab = sdBox(p - vec3(-0.5, 0.0, 0.0), vec3(0.22, 0.37, 0.26));
    float windows = sdBox(m - vec3(-0.47, 0.15, 0.3), vec3(0.12, 0.09, 0.08));
    windows = min(windows, sdBox(p - vec3(-0.25, 0.15, 0.0), vec3(0.06, 0.09, 0.16)));
    cab = max(cab, -windows);
    float roof = sdRoundBox(p - vec3(-0.5, 0.39, 0.0), vec3(0.28, 0.025, 0.3), 0.015);
    loco = min(loco, min(cab, roof));

    // Cowcatcher: a wedge in front of the frame.
    vec3 c = p - vec3(0.82, -0.5, 0.0);
    float wedge = max(sdBox(c, vec3(0.1, 0.1, 0.24)), dot(c, normalize(vec3(1.0, 0.9, 0.0))) - 0.02);
    loco = min(loco, wedge);
    // Buffers at the back.
    float buffers = sdCylinderX(m - vec3(-0.87, -0.42, 0.17), 0.04, 0.04);
    loco = min(loco, buffers);

    // Driving wheels (three per side) and the coupling rod.
    float wx = clamp(round((p.x + 0.05) / 0.3), -1.0, 1.0) * 0.3 - 0.05;   // nearest wheel centre
    float wheels = wheel(m - vec3(wx, -0.6, 0.27), 0.16);
    float rod = sdBox(m - vec3(-0.05, -0.54, 0.34), vec3(0.34, 0.018, 0.012));
    return min(loco, min(wheels, rod));
}
