/* sdfwb
name: Toy Robot
category: Misc
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A retro tin toy robot facing +X: a boxy head with round eyes, a mouth grille, ear
  bolts and an antenna with a ball, a neck, a chest box with a control panel of knobs, arms
  of capsules ending in claw hands (tori cut open), and block legs with feet. Rounded boxes,
  cylinders, capsules and tori joined with min and max: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 m = vec3(p.x, p.y, abs(p.z));   // mirrored through z = 0
    // Head.
    float head = sdRoundBox(p - vec3(0.0, 0.5, 0.0), vec3(0.2, 0.17, 0.22), 0.04);
    float eyes = sdCylinderX(m - vec3(0.2, 0.54, 0.1), 0.055, 0.025);
    float pupils = sdSphere(m - vec3(0.23, 0.54, 0.1), 0.03);
    float mouth = sdBox(vec3(p.x - 0.21, p.y - 0.41, abs(abs(p.z) - 0.045) - 0.0), vec3(0.02, 0.025, 0.02));
    float ears = sdCylinderZ(m - vec3(0.0, 0.5, 0.23), 0.06, 0.03);
    float antenna = sdCapsule(p, vec3(0.0, 0.67, 0.0), vec3(0.0, 0.82, 0.0), 0.015);
    float ball = sdSphere(p - vec3(0.0, 0.85, 0.0), 0.04);
    head = max(head, -sdCylinderX(m - vec3(0.22, 0.54, 0.1), 0.04, 0.02));
    head = min(min(head, min(eyes, pupils)), min(mouth, min(ears, min(antenna, ball))));

    // Neck and body with a control panel.
    float neck = sdCylinder(p - vec3(0.0, 0.29, 0.0), 0.07, 0.05);
    float body = sdRoundBox(p - vec3(0.0, -0.02, 0.0), vec3(0.22, 0.27, 0.3), 0.04);
    float panel = sdRoundBox(p - vec3(0.22, 0.02, 0.0), vec3(0.02, 0.13, 0.17), 0.01);
    float knobs = sdCylinderX(vec3(p.x - 0.25, p.y - 0.06, abs(p.z) - 0.08), 0.03, 0.02);
    knobs = min(knobs, sdCylinderX(p - vec3(0.25, 0.06, 0.0), 0.03, 0.02));
    float slots = sdBox(vec3(p.x - 0.24, abs(p.y + 0.04) - 0.0, p.z), vec3(0.015, 0.012, 0.12));
    float torso = min(min(neck, body), min(panel, min(knobs, slots)));

    // Arms: shoulder ball, upper and lower arm, claw.
    float shoulder = sdSphere(m - vec3(0.0, 0.18, 0.34), 0.07);
    float arm = sdCapsule(m, vec3(0.0, 0.16, 0.36), vec3(0.05, -0.12, 0.4), 0.045);
    arm = min(arm, sdCapsule(m, vec3(0.05, -0.12, 0.4), vec3(0.22, -0.22, 0.4), 0.04));
    vec3 c = m - vec3(0.3, -0.24, 0.4);
    float claw = sdTorusXY(c, 0.06, 0.02);
    claw = max(claw, -sdBox(c - vec3(0.07, 0.0, 0.0), vec3(0.05, 0.03, 0.05)));
    float arms = min(min(shoulder, arm), claw);

    // Legs and feet.
    float leg = sdRoundBox(m - vec3(0.0, -0.5, 0.13), vec3(0.08, 0.22, 0.08), 0.03);
    float foot = sdRoundBox(m - vec3(0.04, -0.77, 0.14), vec3(0.16, 0.06, 0.11), 0.03);
    return min(min(head, torso), min(arms, min(leg, foot)));
}
