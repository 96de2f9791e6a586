/* sdfwb
name: Sailboat
category: Vehicle
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A small sloop sailing towards +X, bobbing and rolling on the swell (period 4 s): a
  hull made from an ellipsoid cut by the deck plane with a pointed bow, a cabin, a keel fin,
  a mast with a boom, and two triangular sails (mainsail and jib, plates from exact 2D
  triangles). The motion is a rigid rotation and translation, which keeps distances.
  Ellipsoid bounds, unions and intersections: conservative.
*/
#include "../lib/modelling.glsl"

float boat(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));
    // Hull: the lower half of an ellipsoid, narrowed towards the bow by a pair of planes.
    float hull = sdEllipsoid(p - vec3(-0.05, -0.42, 0.0), vec3(0.78, 0.3, 0.26));
    hull = max(hull, p.y + 0.42);                                       // deck level
    float bowPlanes = dot(m - vec3(0.73, -0.5, 0.0), normalize(vec3(0.35, 0.0, 1.0)));
    hull = max(hull, bowPlanes);
    float cabin = sdRoundBox(p - vec3(-0.15, -0.38, 0.0), vec3(0.22, 0.07, 0.14), 0.03);
    float keel = sdPlate(sdRoundBox2(p.xy - vec2(-0.05, -0.72), vec2(0.14, 0.12), 0.05), p.z, 0.02);
    float vessel = min(smoothMin(hull, keel, 0.04), cabin);

    // Mast, boom and sails.
    float mast = sdCapsule(p, vec3(0.12, -0.42, 0.0), vec3(0.12, 0.85, 0.0), 0.018);
    float boom = sdCapsule(p, vec3(0.12, -0.25, 0.0), vec3(-0.6, -0.25, 0.0), 0.015);
    float mainsail = sdPlate(sdTriangle2(p.xy, vec2(0.1, 0.8), vec2(0.1, -0.22), vec2(-0.58, -0.22)), p.z, 0.008);
    float jib = sdPlate(sdTriangle2(p.xy, vec2(0.14, 0.7), vec2(0.14, -0.35), vec2(0.7, -0.38)), p.z - 0.0, 0.008);
    return min(vessel, min(min(mast, boom), min(mainsail, jib)));
}

float sdf(vec3 p, float time) {
    float phase = MODEL_TAU * time / 4.0;
    // Bob up and down and roll about the X axis, pitching a little.
    vec3 q = p - vec3(0.0, 0.03 * sin(phase), 0.0);
    q.yz = rotate2(q.yz, 0.08 * sin(phase + 0.8));
    q.xy = rotate2(q.xy, 0.04 * sin(phase + 2.0));
    return boat(q);
}
