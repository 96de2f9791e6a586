/* sdfwb
name: Rounded Cross
category: Geometry
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Three rounded square bars along X, Y and Z, merged with a small fillet and trimmed by a
  ball of radius 0.93 so the bar ends become domes. Each bar is an exact rounded box, but the
  construction is a bound: the smooth union is a weighted blend of 1-Lipschitz fields (exact away
  from the fillets, an underestimate inside and in the blend), and intersecting with the ball
  through max() is exact only where the ball or the bars alone decide. The field is 1-Lipschitz
  and never exceeds the true distance.
  Parameters: bar half width (0.1-0.4), edge rounding (0-0.1), fillet (0.01-0.25).
*/
uniform float barHalfWidth = 0.26;  // @range 0.1 0.4 @step 0.01 @label "Bar half width"
uniform float edgeRounding = 0.08;  // @range 0.0 0.1 @step 0.01 @label "Edge rounding"
uniform float fillet = 0.12;        // @range 0.01 0.25 @step 0.01 @label "Fillet"

float roundBox(vec3 p, vec3 halfSize, float rounding) {
    vec3 q = abs(p) - (halfSize - rounding);
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - rounding;
}

// Polynomial smooth minimum with blend width `width`; its partial derivatives are non-negative
// and sum to 1, so blending 1-Lipschitz fields stays 1-Lipschitz.
float smoothUnion(float a, float b, float width) {
    float h = clamp(0.5 + 0.5 * (b - a) / width, 0.0, 1.0);
    return mix(b, a, h) - width * h * (1.0 - h);
}

float sdf(vec3 p) {
    const float barHalfLength = 0.95;
    float barX = roundBox(p, vec3(barHalfLength, barHalfWidth, barHalfWidth), edgeRounding);
    float barY = roundBox(p, vec3(barHalfWidth, barHalfLength, barHalfWidth), edgeRounding);
    float barZ = roundBox(p, vec3(barHalfWidth, barHalfWidth, barHalfLength), edgeRounding);
    float bars = smoothUnion(smoothUnion(barX, barY, fillet), barZ, fillet);
    float trimBall = length(p) - 0.93;
    return max(bars, trimBall);
}
