/* sdfwb
name: Fish
category: Animal
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A swimming fish heading towards +X: a laterally flattened ellipsoid body with a forked
  tail, dorsal, anal and pectoral fins and eyes. A travelling body wave (period 2 s) bends it
  sideways, growing from nose to tail. The wave shifts z by g(x, t) with |dg/dx| <= 0.38, so
  the bent field is divided by 1.38 to keep its gradient below 1; with the ellipsoid bounds and
  smooth unions this makes the field conservative.
*/
#include "../lib/modelling.glsl"

// A thin fin in the XY plane: a rounded teardrop outline from a (radius ra) to b (radius rb),
// 0.036 thick across z.
float fin(vec3 p, vec2 a, vec2 b, float ra, float rb) {
    return sdPlate(sdRoundCone2(p.xy, a, b, ra, rb), p.z, 0.018);
}

float fishBody(vec3 p) {
    float body = sdEllipsoid(p - vec3(0.12, 0.0, 0.0), vec3(0.62, 0.33, 0.16));
    // Narrow tail stalk joining the body to the tail fin.
    float stalk = sdRoundCone(p, vec3(-0.25, 0.0, 0.0), vec3(-0.6, 0.0, 0.0), 0.12, 0.04);
    body = smoothMin(body, stalk, 0.1);

    // Forked tail: two lobes fanning back up and back down (mirrored through y = 0).
    vec3 t = vec3(p.x, abs(p.y), p.z);
    float tail = fin(t, vec2(-0.56, 0.0), vec2(-0.82, 0.27), 0.04, 0.09);
    body = smoothMin(body, tail, 0.05);

    // Dorsal fin on the back and a smaller anal fin underneath, both raked backwards.
    float dorsal = fin(p, vec2(0.26, 0.22), vec2(-0.12, 0.41), 0.03, 0.07);
    float anal = fin(p, vec2(-0.15, -0.2), vec2(-0.36, -0.27), 0.03, 0.05);
    body = smoothMin(body, min(dorsal, anal), 0.04);

    // Pectoral fins behind the gills, mirrored through z = 0 and angled out and back.
    vec3 s = vec3(p.x, p.y, abs(p.z)) - vec3(0.32, -0.1, 0.12);
    s.xz = rotate2(s.xz, 0.5);
    float pectoral = sdPlate(sdRoundCone2(s.xy, vec2(0.0), vec2(-0.2, -0.07), 0.03, 0.06), s.z, 0.012);
    body = smoothMin(body, pectoral, 0.03);

    float eye = sdSphere(vec3(p.x, p.y, abs(p.z)) - vec3(0.5, 0.07, 0.085), 0.05);
    return min(body, eye);
}

float sdf(vec3 p, float time) {
    // Body wave travelling from head to tail; amplitude grows towards the tail.
    const float k = 3.0;                       // wave number
    const float omega = 3.14159265;            // 2 s period
    float amplitude = 0.1 * clamp((0.55 - p.x) / 1.4, 0.0, 1.0);
    float shift = amplitude * sin(k * p.x + omega * time);
    // |d shift / dx| <= 0.1 / 1.4 + 0.1 * k = 0.372: divide by the Lipschitz bound.
    return fishBody(vec3(p.x, p.y, p.z - shift)) / 1.38;
}
