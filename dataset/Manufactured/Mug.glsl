/* sdfwb
name: Coffee Mug
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A coffee mug with its handle towards +X: a hollow cylinder with rounded lips and a
  thick base, coffee standing a little below the rim, and a D-shaped handle (a torus tube cut
  to its outer half) blended onto the side. Cylinders and tori are exact; the hollowing (max)
  and smooth unions make the field conservative.
  Parameters: coffee level (-0.3 to 0.5), handle thickness (0.03-0.1).
*/
uniform float coffeeLevel = 0.35;      // @range -0.3 0.5 @step 0.01 @label "Coffee level"
uniform float handleThickness = 0.07;  // @range 0.03 0.1 @step 0.005 @label "Handle thickness"

#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    vec3 q = p - vec3(-0.15, -0.05, 0.0);
    // Wall: a rounded solid cylinder minus a rounded inner one open at the top.
    float outer = sdCylinder(q, 0.5, 0.55) - 0.04;
    float inner = sdCylinder(q - vec3(0.0, 0.2, 0.0), 0.44, 0.55) - 0.02;
    float cup = max(outer, -inner);
    // Coffee: a flat disc filling the cup to below the rim.
    float coffee = sdCylinder(q - vec3(0.0, coffeeLevel, 0.0), 0.45, 0.02);
    cup = min(cup, coffee);

    // Handle: a torus in the XY plane on the +X side, keeping only the part outside the wall.
    vec3 h = q - vec3(0.5, 0.02, 0.0);
    float handle = sdTorusXY(h, 0.27, handleThickness);
    handle = max(handle, -0.1 - h.x);
    return smoothMin(cup, handle, 0.05);
}
