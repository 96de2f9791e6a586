/* sdfwb
name: Wooden Chair
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A kitchen chair facing +X: four square legs with side stretchers, a thick seat and a
  back of two posts, a top rail and three vertical slats (the back posts continue the rear
  legs up). Rounded boxes, exact each, joined with min: conservative.
  The audit measures it as exact: the parts barely overlap, so the min() underestimate inside
  the joints is below the audit's resolution; declared conservative because it is one in theory.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));   // mirrored through z = 0
    // Legs: the front pair at +X, the rear pair at -X continuing up as back posts.
    float frontLeg = sdRoundBox(m - vec3(0.32, -0.55, 0.32), vec3(0.05, 0.35, 0.05), 0.015);
    float rearLeg = sdRoundBox(m - vec3(-0.32, -0.05, 0.32), vec3(0.05, 0.85, 0.05), 0.015);
    float stretcher = sdRoundBox(m - vec3(0.0, -0.6, 0.32), vec3(0.32, 0.025, 0.025), 0.01);
    float frame = min(min(frontLeg, rearLeg), stretcher);
    // Seat: a thick board overhanging the legs a little.
    float seat = sdRoundBox(p - vec3(0.0, -0.16, 0.0), vec3(0.42, 0.045, 0.42), 0.02);
    // Back: a curved-looking top rail and three slats between the posts.
    float rail = sdRoundBox(p - vec3(-0.32, 0.68, 0.0), vec3(0.045, 0.1, 0.34), 0.02);
    float slats = sdRoundBox(vec3(p.x + 0.32, p.y - 0.25, abs(abs(p.z) - 0.13) ), vec3(0.025, 0.33, 0.04), 0.01);
    slats = min(slats, sdRoundBox(vec3(p.x + 0.32, p.y - 0.25, p.z), vec3(0.025, 0.33, 0.04), 0.01));
    return min(min(frame, seat), min(rail, slats));
}
