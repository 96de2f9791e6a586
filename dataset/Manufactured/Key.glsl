/* sdfwb
name: Old Key
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: An old-fashioned skeleton key lying in the XY plane (flat faces to +Z and -Z), bit
  towards +X: a ring bow with a clover cut-out, a collar, a round shaft and a bit with two
  notched wards. The outline is exact 2D distances (circles, boxes) given thickness with
  rounded rims; union and subtraction make it conservative.
  Sampling note: the key is thin, so a random ray rarely hits it; the surface and near patterns
  (100 rays per sample) leave a handful of NaN rows in 20 000 (2 in the dataset report run).
*/
#include "../lib/modelling.glsl"

float keyOutline(vec2 q) {
    // Bow: a ring with a three-lobed hole.
    vec2 b = q - vec2(-0.55, 0.05);
    float bow = length(b) - 0.3;
    float hole = min(length(b - vec2(0.0, 0.09)) - 0.09,
                     min(length(b - vec2(-0.08, -0.05)) - 0.09, length(b - vec2(0.08, -0.05)) - 0.09));
    bow = max(bow, -hole);
    // Collar and shaft.
    float collar = sdRoundBox2(q - vec2(-0.2, 0.05), vec2(0.05, 0.09), 0.02);
    float shaft = sdRoundBox2(q - vec2(0.28, 0.05), vec2(0.5, 0.045), 0.03);
    // Bit: a plate hanging below the shaft end, with two rectangular notches.
    float bit = sdBox2(q - vec2(0.62, -0.12), vec2(0.14, 0.16));
    float notch1 = sdBox2(q - vec2(0.58, -0.2), vec2(0.025, 0.1));
    float notch2 = sdBox2(q - vec2(0.7, -0.26), vec2(0.03, 0.05));
    bit = max(bit, -min(notch1, notch2));
    return min(min(bow, collar), min(shaft, bit));
}

float sdf(vec3 p) {
    return sdPlate(keyOutline(p.xy), p.z, 0.06);
}
