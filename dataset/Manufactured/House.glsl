/* sdfwb
name: Cottage
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A small cottage whose front door faces +X: box walls, a gable roof (a prism made by
  two sloping planes, overhanging the walls) with its ridge along X, a brick chimney, a door
  with a step and four recessed windows with sills. Boxes and planes joined with min and max:
  conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Walls.
    float walls = sdBox(p - vec3(0.0, -0.45, 0.0), vec3(0.55, 0.38, 0.5));
    // Door (front, +X) and windows (front and sides), recessed into the walls.
    float door = sdBox(p - vec3(0.56, -0.6, -0.18), vec3(0.04, 0.23, 0.1));
    vec3 w = vec3(p.x, p.y, abs(p.z + 0.0));
    float frontWindow = sdBox(p - vec3(0.56, -0.42, 0.22), vec3(0.04, 0.1, 0.12));
    float sideWindows = sdBox(vec3(abs(p.x) - 0.25, p.y + 0.42, abs(p.z) - 0.51), vec3(0.1, 0.1, 0.04));
    walls = max(walls, -min(door, min(frontWindow, sideWindows)));
    float sills = min(sdBox(p - vec3(0.58, -0.54, 0.22), vec3(0.04, 0.015, 0.14)),
                      sdBox(vec3(abs(p.x) - 0.25, p.y + 0.54, abs(p.z) - 0.53), vec3(0.12, 0.015, 0.04)));
    float step = sdBox(p - vec3(0.62, -0.8, -0.18), vec3(0.07, 0.03, 0.14));

    // Roof: two slopes meeting along a ridge parallel to X, overhanging walls and gables.
    vec3 r = p - vec3(0.0, -0.07, 0.0);
    const vec2 slope = vec2(0.7071068, 0.7071068);         // 45 degree pitch
    float pitched = dot(vec2(abs(r.z), r.y), slope) - 0.45;
    float roofSolid = max(pitched, max(-r.y, abs(r.x) - 0.62));
    float roofHollow = max(pitched + 0.06, max(-r.y + 0.06, abs(r.x) - 0.7));
    float roof = max(roofSolid, -roofHollow);
    // Gable ends: triangles of wall under the roof.
    float gable = max(pitched + 0.06, max(-r.y, abs(r.x) - 0.55));

    // Chimney rising through the roof.
    float chimney = sdBox(p - vec3(-0.25, 0.3, -0.22), vec3(0.07, 0.25, 0.07));
    float pot = sdBox(p - vec3(-0.25, 0.56, -0.22), vec3(0.085, 0.025, 0.085));
    float house = min(min(walls, gable), min(roof, min(chimney, pot)));
    return min(house, min(sills, step));
}
