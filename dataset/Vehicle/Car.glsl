/* sdfwb
name: Car
category: Vehicle
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A compact hatchback driving towards +X with its wheels turning (a fifth of a turn per
  second, so the five-spoke wheels loop every second). Rounded-box body with wheel arches,
  a cabin with a raked windscreen and recessed side windows, bumpers, headlights, and four
  wheels (torus tyre, rim disc, spokes). Each wheel is a rigid rotation of one wheel; the
  front and back wheels are evaluated separately (mirroring in x would reverse their spin),
  the left and right ones by mirroring in z, which keeps the spin. Conservative.
*/
#include "../lib/modelling.glsl"

const float WHEEL_X = 0.52;
const float WHEEL_Y = -0.5;
const float WHEEL_Z = 0.34;

// A wheel at the origin with its axle along Z, turned by `angle`; q.z > 0 is the outside.
float wheel(vec3 q, float angle) {
    float tyre = sdTorusXY(q, 0.15, 0.075);
    float rim = sdCylinderZ(q, 0.13, 0.055);
    vec2 r = rotate2(q.xy, angle);
    vec2 s = sectorFold(r, 5.0);
    float spoke = sdBox(vec3(s.x - 0.07, s.y, q.z - 0.06), vec3(0.06, 0.018, 0.012));
    float hub = sdCylinderZ(q - vec3(0.0, 0.0, 0.06), 0.035, 0.015);
    // Dish the rim face so the spokes stand out.
    rim = max(rim, -sdCylinderZ(q - vec3(0.0, 0.0, 0.07), 0.11, 0.03));
    return min(min(tyre, rim), min(spoke, hub));
}

float sdf(vec3 p, float time) {
    vec3 m = vec3(p.x, p.y, abs(p.z));

    // Lower body: a long rounded box.
    float body = sdRoundBox(p - vec3(0.0, -0.38, 0.0), vec3(0.86, 0.16, 0.38), 0.08);
    // Cabin: a shorter box set back, with the windscreen and rear window raked.
    float cabin = sdRoundBox(p - vec3(-0.12, -0.08, 0.0), vec3(0.46, 0.18, 0.33), 0.07);
    float windscreen = dot(p - vec3(0.24, -0.08, 0.0), vec3(0.6, 0.8, 0.0));
    float rearScreen = dot(p - vec3(-0.48, -0.08, 0.0), vec3(-0.45, 0.893, 0.0));
    cabin = max(cabin, max(windscreen, rearScreen));
    float car = smoothMin(body, cabin, 0.06);
    // Side windows: shallow recesses in the cabin sides.
    float windows = sdBox(m - vec3(-0.1, -0.04, 0.34), vec3(0.34, 0.1, 0.025));
    windows = max(windows, max(windscreen + 0.05, rearScreen + 0.05));
    car = max(car, -windows);
    // Wheel arches.
    vec3 a = vec3(abs(p.x) - WHEEL_X, p.y - WHEEL_Y, m.z);
    float arch = sdCylinderZ(a - vec3(0.0, 0.0, 0.3), 0.26, 0.2);
    car = max(car, -arch);
    // Bumpers and headlights.
    float bumpers = sdRoundBox(vec3(abs(p.x) - 0.88, p.y + 0.45, p.z), vec3(0.04, 0.05, 0.36), 0.03);
    float lights = sdSphere(m - vec3(0.86, -0.3, 0.25), 0.06);
    car = min(car, min(bumpers, lights));

    // Wheels: turning clockwise seen from +Z as the car drives to +X.
    float angle = -MODEL_TAU * 0.2 * time;
    float front = wheel(m - vec3(WHEEL_X, WHEEL_Y, WHEEL_Z), angle);
    float back = wheel(m - vec3(-WHEEL_X, WHEEL_Y, WHEEL_Z), angle);
    return min(car, min(front, back));
}
