/* sdfwb
name: Desk Lamp
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: An anglepoise-style desk lamp facing +X: a heavy round base, a two-segment arm with
  ball joints, and a conical shade (a hollow frustum, open at the front) with a bulb inside,
  aimed forwards and down. Exact primitives; the shell uses max: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    float base = sdCylinder(p - vec3(-0.35, -0.82, 0.0), 0.32, 0.05) - 0.02;
    float button = sdCylinder(p - vec3(-0.15, -0.75, 0.0), 0.04, 0.02);

    // Arm: lower segment leaning forward, upper segment reaching forward.
    vec3 j0 = vec3(-0.35, -0.74, 0.0), j1 = vec3(-0.05, 0.1, 0.0), j2 = vec3(0.35, 0.45, 0.0);
    float arm = min(sdCapsule(p, j0, j1, 0.03), sdCapsule(p, j1, j2, 0.03));
    // Parallel spring rods beside the arm segments (mirrored through z = 0).
    vec3 m = vec3(p.x, p.y, abs(p.z));
    arm = min(arm, sdCapsule(m, j0 + vec3(0.05, 0.05, 0.04), j1 + vec3(0.03, -0.05, 0.04), 0.012));
    float joints = min(sdSphere(p - j0, 0.06), min(sdSphere(p - j1, 0.06), sdSphere(p - j2, 0.055)));

    // Shade: a cone opening towards +X and down, hanging from the top joint.
    vec3 s = p - vec3(0.5, 0.32, 0.0);
    s.xy = rotate2(s.xy, -0.87);               // turn the local -Y axis towards +X and down
    float shell = sdFrustum(s, 0.3, 0.1, 0.18);
    // Cavity: the same cone 0.02 thinner, reaching well past the opening so that no thin
    // near-zero film is left across the mouth.
    float inside = sdFrustum(s + vec3(0.0, 0.12, 0.0), 0.402, 0.091, 0.28);
    shell = max(shell, -inside) - 0.01;
    float cap = sdSphere(s - vec3(0.0, 0.18, 0.0), 0.1);
    float bulb = sdSphere(s + vec3(0.0, 0.05, 0.0), 0.1);
    float shade = min(min(shell, cap), bulb);

    return min(min(base, button), min(min(arm, joints), shade));
}
