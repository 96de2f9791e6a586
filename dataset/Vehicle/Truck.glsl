/* sdfwb
name: Delivery Truck
category: Vehicle
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A box truck heading towards +X: a cab with a raked windscreen, side windows, grille,
  headlights and bumper, a tall cargo box behind it, a chassis, mudguards, and three axles
  (single front wheels, a tandem pair at the back) with tyres and hubs. Rounded boxes, tori
  and cylinders joined with min and max: conservative.
*/
#include "../lib/modelling.glsl"

float wheel(vec3 q) {
    float tyre = sdTorusXY(q, 0.11, 0.065);
    float hub = sdCylinderZ(q, 0.1, 0.05);
    float cap = sdCylinderZ(q - vec3(0.0, 0.0, 0.05), 0.04, 0.015);
    return min(min(tyre, hub), cap);
}

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));
    // Chassis rail under everything.
    float chassis = sdBox(p - vec3(0.0, -0.48, 0.0), vec3(0.82, 0.04, 0.26));
    // Cab at the front.
    vec3 c = p - vec3(0.6, -0.17, 0.0);
    float cab = sdRoundBox(c, vec3(0.25, 0.29, 0.33), 0.05);
    float windscreen = dot(c - vec3(0.12, 0.29, 0.0), normalize(vec3(1.0, 0.45, 0.0)));
    cab = max(cab, windscreen);
    float sideWindow = sdBox(m - vec3(0.63, -0.02, 0.34), vec3(0.12, 0.09, 0.03));
    sideWindow = max(sideWindow, windscreen + 0.04);
    cab = max(cab, -sideWindow);
    float screenRecess = max(abs(windscreen) - 0.015, sdBox(c - vec3(0.12, 0.17, 0.0), vec3(0.2, 0.09, 0.27)));
    cab = max(cab, -screenRecess);
    // Grille, headlights and bumper.
    float grille = sdBox(p - vec3(0.85, -0.3, 0.0), vec3(0.02, 0.08, 0.18));
    float lights = sdCylinderX(m - vec3(0.85, -0.3, 0.25), 0.045, 0.015);
    float bumper = sdRoundBox(p - vec3(0.86, -0.47, 0.0), vec3(0.04, 0.05, 0.34), 0.02);
    float front = min(grille, min(lights, bumper));

    // Cargo box.
    float cargo = sdRoundBox(p - vec3(-0.27, 0.0, 0.0), vec3(0.58, 0.44, 0.36), 0.03);

    // Wheels: front axle and a tandem pair at the back; mudguards over them.
    float front1 = wheel(m - vec3(0.55, -0.58, 0.3));
    float rear = min(wheel(m - vec3(-0.63, -0.58, 0.3)), wheel(m - vec3(-0.37, -0.58, 0.3)));
    float guards = sdBox(m - vec3(-0.5, -0.4, 0.3), vec3(0.26, 0.015, 0.08));
    float truck = min(min(chassis, cab), min(front, cargo));
    truck = min(truck, guards);
    return min(truck, min(front1, rear));
}
