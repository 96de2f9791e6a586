/* sdfwb
name: Snowman
category: Nature
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A snowman looking towards +X: three stacked snowballs blended together, a carrot nose,
  coal eyes, mouth and buttons, stick arms with twig fingers, a top hat and a scarf.
  Exact spheres, cones and cylinders joined by min, max and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));   // mirrored through z = 0 for paired parts

    // Snowballs.
    float base = sdSphere(p - vec3(0.0, -0.58, 0.0), 0.36);
    float middle = sdSphere(p - vec3(0.0, -0.06, 0.0), 0.27);
    float head = sdSphere(p - vec3(0.0, 0.34, 0.0), 0.19);
    float snow = smoothMin(smoothMin(base, middle, 0.06), head, 0.05);
    snow = max(snow, -0.9 - p.y);                         // settled flat on the ground

    // Carrot nose, coal eyes, a smile of coal and three buttons.
    float nose = sdRoundCone(p, vec3(0.16, 0.33, 0.0), vec3(0.42, 0.3, 0.0), 0.04, 0.008);
    float eyes = sdSphere(m - vec3(0.16, 0.4, 0.07), 0.025);
    vec3 sm = m - vec3(0.0, 0.34, 0.0);
    float mouth = sdSphere(sm - vec3(0.172, -0.07, 0.03), 0.016);
    mouth = min(mouth, sdSphere(sm - vec3(0.162, -0.085, 0.075), 0.016));
    float buttons = min(sdSphere(p - vec3(0.265, 0.0, 0.0), 0.03), sdSphere(p - vec3(0.27, -0.12, 0.0), 0.03));
    buttons = min(buttons, sdSphere(p - vec3(0.35, -0.5, 0.0), 0.035));
    float details = min(min(nose, eyes), min(mouth, buttons));

    // Stick arms with a forked end.
    float arm = sdCapsule(m, vec3(0.0, 0.0, 0.22), vec3(0.05, 0.28, 0.62), 0.022);
    arm = min(arm, sdCapsule(m, vec3(0.04, 0.22, 0.52), vec3(0.14, 0.3, 0.64), 0.014));
    arm = min(arm, sdCapsule(m, vec3(0.04, 0.22, 0.52), vec3(-0.02, 0.4, 0.6), 0.014));

    // Top hat: brim and crown, tipped back a little.
    vec3 h = p - vec3(-0.02, 0.49, 0.0);
    h.xy = rotate2(h.xy, 0.12);
    float brim = sdCylinder(h, 0.22, 0.015) - 0.005;
    float crown = sdCylinder(h - vec3(0.0, 0.16, 0.0), 0.14, 0.16) - 0.005;
    float hat = min(brim, crown);

    // Scarf: a thick ring round the neck with a hanging tail.
    float scarf = sdTorus(p - vec3(0.0, 0.18, 0.0), 0.17, 0.05);
    vec3 st = p - vec3(0.1, 0.1, 0.16);
    scarf = smoothMin(scarf, sdRoundBox(st, vec3(0.045, 0.14, 0.02), 0.015), 0.03);

    return min(min(snow, details), min(min(arm, hat), scarf));
}
