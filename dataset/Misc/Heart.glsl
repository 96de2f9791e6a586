/* sdfwb
name: Beating Heart
category: Misc
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A plump heart symbol facing +X (it lies in the YZ plane) beating with a double
  "lub-dub" pulse once a second. Two round lobes and two tapered cones meeting at the
  point, blended smoothly, then flattened along X: squashing by 0.55 along one axis is a
  non-uniform scale, so the field is multiplied by 0.55 to stay 1-Lipschitz. The beat is a
  uniform scale s(t), exact (f(p/s) * s). Conservative.
*/
#include "../lib/modelling.glsl"

float heart2(vec3 q) {
    // q: z across the heart, y up, x through it (before flattening).
    vec3 m = vec3(q.x, q.y, abs(q.z));
    float lobe = sdSphere(m - vec3(0.0, 0.25, 0.3), 0.38);
    float side = sdRoundCone(m, vec3(0.0, 0.22, 0.28), vec3(0.0, -0.62, 0.0), 0.36, 0.04);
    float h = smoothMin(lobe, side, 0.05);
    // Blend the two halves so the dip between the lobes is soft.
    return h;
}

float sdf(vec3 p, float time) {
    // Double pulse: a strong beat then a weaker one, repeating every second.
    float t = fract(time);
    float beat = exp(-60.0 * (t - 0.15) * (t - 0.15)) + 0.6 * exp(-60.0 * (t - 0.38) * (t - 0.38));
    float s = 1.15 * (1.0 + 0.09 * beat);                 // overall size times the pulse
    vec3 q = p / s;
    const float squash = 0.55;                             // thickness squash along X
    float d = heart2(vec3(q.x / squash, q.y - 0.05, q.z)) * squash;
    return d * s;
}
