/* sdfwb
name: Windmill
category: Manufactured
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A Dutch tower windmill whose four lattice sails turn (one quarter turn every 2 s, so
  the motion loops). A tapered round tower with a door and windows, a gallery ring, a
  thatched-cap dome and a hub at the front (+X). Each sail is a spar with a lattice of bars
  on one side; the four sails are one sail rotated rigidly by the sail angle plus multiples of
  a quarter turn. Exact parts joined with min and max: conservative.
*/
#include "../lib/modelling.glsl"

float sail(vec3 q) {
    // q: sail frame, spar along +y from the hub, the sail's face in the y-z plane.
    float spar = sdBox(q - vec3(0.0, 0.3, 0.0), vec3(0.015, 0.3, 0.015));
    // Lattice: frame of the sail cloth beside the spar (z > 0), with cross bars.
    vec3 l = q - vec3(0.0, 0.37, 0.09);
    float frame = sdBox(l, vec3(0.01, 0.22, 0.08));
    float opening = sdBox(l, vec3(0.05, 0.205, 0.065));
    frame = max(frame, -opening);
    float barY = clamp(round(l.y / 0.085), -2.0, 2.0) * 0.085;
    float bars = sdBox(l - vec3(0.0, barY, 0.0), vec3(0.008, 0.008, 0.08));
    float midBar = sdBox(l, vec3(0.008, 0.22, 0.008));
    return min(spar, min(frame, min(bars, midBar)));
}

float sdf(vec3 p, float time) {
    // Tower: a tapered round body with a base plinth.
    float tower = sdFrustum(p - vec3(-0.1, -0.38, 0.0), 0.38, 0.26, 0.5);
    float plinth = sdCylinder(p - vec3(-0.1, -0.86, 0.0), 0.42, 0.04);
    // Door and windows cut into the front.
    float door = sdBox(p - vec3(0.3, -0.72, 0.0), vec3(0.2, 0.13, 0.07));
    float window = sdBox(p - vec3(0.22, -0.3, 0.0), vec3(0.2, 0.07, 0.05));
    tower = max(tower, -min(door, window));
    // Gallery ring and cap.
    float gallery = sdCylinder(p - vec3(-0.1, 0.1, 0.0), 0.36, 0.02);
    float cap = sdEllipsoid(p - vec3(-0.1, 0.14, 0.0), vec3(0.33, 0.3, 0.33));
    cap = max(cap, 0.12 - p.y);
    float mill = min(min(tower, plinth), min(gallery, cap));

    // Hub: an axle sticking out towards +X.
    vec3 h = p - vec3(0.3, 0.28, 0.0);
    float axle = sdCylinderX(h + vec3(0.1, 0.0, 0.0), 0.045, 0.12);
    float hub = sdSphere(h - vec3(0.03, 0.0, 0.0), 0.06);
    mill = min(mill, min(axle, hub));

    // Sails: rotate about the axle (X axis); the four sails are a quarter turn apart. A sail
    // is not mirror symmetric (its lattice is on one side), so all four are evaluated.
    float angle = MODEL_TAU * 0.125 * time;                // quarter turn per 2 s
    vec3 s = h - vec3(0.05, 0.0, 0.0);
    s.yz = rotate2(s.yz, angle);
    float sails = sail(s);
    for (int i = 1; i < 4; ++i) {
        s.yz = vec2(-s.z, s.y);                            // next sail: a quarter turn on
        sails = min(sails, sail(s));
    }
    return min(mill, sails);
}
