/* sdfwb
name: Spinning Top
category: Misc
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A wooden spinning top balanced on its point: a rounded body of revolution (a
  frustum to the point, a wide ridge, a domed shoulder) with six bumps round the ridge and a
  handle stem with a knob. It spins (a sixth of a turn every 0.25 s) while its axis precesses
  round the vertical once every 3 s, tilted by 0.15 rad about the tip. Both motions are rigid,
  so distances are kept; the bumps are symmetric and repeated by angular repetition.
  Conservative (unions and smooth unions).
*/
#include "../lib/modelling.glsl"

// The top in its own frame: tip at the origin, axis along +Y.
float top(vec3 p, float spin) {
    float cone = sdFrustum(p - vec3(0.0, 0.36, 0.0), 0.02, 0.48, 0.36);
    float ridge = sdTorus(p - vec3(0.0, 0.74, 0.0), 0.48, 0.07);
    float shoulder = sdEllipsoid(p - vec3(0.0, 0.76, 0.0), vec3(0.5, 0.2, 0.5));
    float body = smoothMin(smoothMin(cone, ridge, 0.04), shoulder, 0.06);
    vec2 s = sectorFold(rotate2(p.xz, spin), 6.0);
    float bumps = sdSphere(vec3(s.x - 0.55, p.y - 0.74, s.y), 0.06);
    body = smoothMin(body, bumps, 0.03);
    float stem = sdCylinder(p - vec3(0.0, 1.05, 0.0), 0.05, 0.15);
    float knob = sdSphere(p - vec3(0.0, 1.23, 0.0), 0.07);
    float tip = sdSphere(p - vec3(0.0, 0.025, 0.0), 0.025);
    return min(min(body, tip), smoothMin(stem, knob, 0.03));
}

float sdf(vec3 p, float time) {
    // Pivot about the tip, which rests at (0, -0.88, 0): tilt 0.15 rad towards an azimuth that
    // turns once every 3 s.
    vec3 q = p - vec3(0.0, -0.88, 0.0);
    float azimuth = MODEL_TAU * time / 3.0;
    q.xz = rotate2(q.xz, -azimuth);
    q.xy = rotate2(q.xy, 0.15);
    q.xz = rotate2(q.xz, azimuth);
    // The top is drawn 1.2 times its modelled size (uniform scale: exact).
    return top(q / 1.2, MODEL_TAU * time / 1.5) * 1.2;
}
