/* sdfwb
name: Trophy Cup
category: Misc
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A trophy: a deep cup (a hollowed half ellipsoid with a rolled lip) with two loop
  handles at the sides (tori in the YZ plane, outer halves), a knopped stem and a stepped
  plinth with a name plate facing +X. Ellipsoid bounds, exact tori, cylinders and boxes,
  joined with min, max and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));
    // Cup: a half ellipsoid shell open at the top.
    vec3 c = p - vec3(0.0, 0.42, 0.0);
    float outer = sdEllipsoid(c, vec3(0.42, 0.5, 0.42));
    float inner = sdEllipsoid(c - vec3(0.0, 0.02, 0.0), vec3(0.37, 0.46, 0.37));
    float cup = max(max(outer, -inner), c.y - 0.02);
    cup = max(cup, -c.y - 0.5);
    float lip = sdTorus(c - vec3(0.0, 0.02, 0.0), 0.395, 0.03);
    cup = min(cup, lip);
    // Handles: loops on both sides (mirrored through z = 0), in the YZ plane.
    vec3 h = m - vec3(0.0, 0.22, 0.42);
    float handle = sdTorusYZ(h, 0.17, 0.035);
    handle = max(handle, -h.z - 0.02);
    cup = smoothMin(cup, handle, 0.03);

    // Stem with a knop, flaring into the foot.
    float stem = sdFrustum(p - vec3(0.0, -0.25, 0.0), 0.1, 0.06, 0.22);
    float knop = sdEllipsoid(p - vec3(0.0, -0.2, 0.0), vec3(0.11, 0.06, 0.11));
    float neck = sdFrustum(p - vec3(0.0, -0.03, 0.0), 0.05, 0.15, 0.07);
    float foot = sdFrustum(p - vec3(0.0, -0.5, 0.0), 0.28, 0.12, 0.05);
    float trophy = smoothMin(cup, smoothMin(neck, min(stem, knop), 0.04), 0.04);
    trophy = smoothMin(trophy, foot, 0.04);

    // Plinth: two stacked blocks and a name plate on the front.
    float plinth = sdRoundBox(p - vec3(0.0, -0.64, 0.0), vec3(0.36, 0.1, 0.36), 0.02);
    plinth = min(plinth, sdRoundBox(p - vec3(0.0, -0.8, 0.0), vec3(0.44, 0.07, 0.44), 0.02));
    float plate = sdRoundBox(p - vec3(0.36, -0.64, 0.0), vec3(0.015, 0.05, 0.2), 0.008);
    return min(trophy, min(plinth, plate));
}
