/* sdfwb
name: Mountain Range
category: Nature
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A diorama block of mountains: a tall main peak and three lower ones (cones blended
  with smooth minimum) rising from rolling ground, roughened by ridged plane waves and cut
  to a square block whose sides show the cross-section. Ridges: a sum of a*|sin(k.p)| terms
  whose gradient is at most sum(a|k|) = 0.94, so the terrain is divided by 1.94 before the
  block cut (an intersection). Conservative.
*/
#include "../lib/modelling.glsl"

// Ridged roughness: sharp creases where the sines cross zero, like eroded rock ribs.
float ridges(vec3 p) {
    float n = 0.05 * abs(sin(dot(p, vec3(4.0, 1.5, 3.0)) + 0.5));
    n += 0.035 * abs(sin(dot(p, vec3(-3.5, 2.0, 5.0)) + 1.2));
    n += 0.02 * abs(sin(dot(p, vec3(8.0, -3.0, -7.0)) + 2.0));
    n += 0.012 * abs(sin(dot(p, vec3(-10.0, 6.0, 12.0))));
    return n;
}

float sdf(vec3 p) {
    float ground = -0.55;
    float peaks = sdFrustum(p - vec3(0.05, 0.1, -0.05), 0.75, 0.0, 0.65);
    peaks = smoothMin(peaks, sdFrustum(p - vec3(-0.45, -0.15, 0.3), 0.48, 0.0, 0.4), 0.08);
    peaks = smoothMin(peaks, sdFrustum(p - vec3(0.5, -0.22, 0.32), 0.42, 0.0, 0.33), 0.08);
    peaks = smoothMin(peaks, sdFrustum(p - vec3(-0.4, -0.2, -0.4), 0.45, 0.0, 0.35), 0.08);
    float land = smoothMin(peaks, p.y - ground, 0.15);
    land = (land + ridges(p)) / 1.94;
    // The diorama block: keep only what lies inside a box with a flat bottom.
    float block = sdBox(p - vec3(0.0, -0.2, 0.0), vec3(0.9, 0.65, 0.72));
    return max(land, block);
}
