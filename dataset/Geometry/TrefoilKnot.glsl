/* sdfwb
name: Trefoil Knot
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Tube of radius 0.14 around a trefoil, the (2,3) torus knot ((0.52 + 0.26 cos 3t) cos 2t,
  (0.52 + 0.26 cos 3t) sin 2t, 0.26 sin 3t), with its threefold symmetry axis turned from +X
  towards the viewer's side. The knot is a smooth closed quadratic B-spline through 30 points of
  that curve: piece i is a quadratic Bezier from the midpoint of Q(i-1) Q(i) to the midpoint of
  Q(i) Q(i+1) with control point Q(i), so tangents match at every joint. The distance to a piece is
  exact (a cubic solved in closed form), and the least over all pieces is the exact distance to
  the spline. To stay cheap without changing that value, each piece lies within its sagitta of its
  chord, so chord distances bound the piece distances from both sides: the two pieces with the
  nearest chords are solved, and the others are solved only when their lower bound still beats
  the result (rare). The tube radius is below the spline's smallest curvature radius (about 0.3)
  and half the closest approach of two strands (about 0.22), so the tube is exact inside too. It is
  the exact distance to this spline trefoil, a close approximation of the parametric curve.
  Parameters: tube radius (0.04-0.17).
*/
uniform float tubeRadius = 0.14;  // @range 0.04 0.17 @step 0.01 @label "Tube radius"


// Real cube root that accepts negative arguments.
float cubeRoot(float x) { return sign(x) * pow(abs(x), 1.0 / 3.0); }

// Exact distance from p to the quadratic Bezier curve start -> (control) -> end.
float bezierDistance(vec3 p, vec3 start, vec3 control, vec3 end) {
    // B(t) = start + 2t * toControl + t^2 * bend
    vec3 toControl = control - start;
    vec3 bend = start - 2.0 * control + end;
    vec3 fromPoint = start - p;
    // (B(t) - p) . B'(t) = 0, divided by |bend|^2: t^3 + k2 t^2 + k1 t + k0 = 0.
    float inverseBend = 1.0 / max(dot(bend, bend), 1e-20);
    float k2 = 3.0 * dot(toControl, bend) * inverseBend;
    float k1 = (2.0 * dot(toControl, toControl) + dot(fromPoint, bend)) * inverseBend;
    float k0 = dot(fromPoint, toControl) * inverseBend;
    // Substitute t = x - k2 / 3 to remove the square term: x^3 + a x + b = 0.
    float a = k1 - k2 * k2 / 3.0;
    float b = k2 * (2.0 * k2 * k2 - 9.0 * k1) / 27.0 + k0;
    float discriminant = 0.25 * b * b + a * a * a / 27.0;

    // Candidate parameters: the local minima of the squared distance (the clamping below also
    // yields the ends, which is where any minimum over [0, 1] that is not a root must lie).
    vec2 candidates;
    if (discriminant >= 0.0) {
        // One real root (Cardano).
        float s = sqrt(discriminant);
        candidates = vec2(cubeRoot(-0.5 * b + s) + cubeRoot(-0.5 * b - s));
    } else {
        // Three real roots 2m cos(phi/3 - 2 pi k/3), m = sqrt(-a/3). The middle one (k = 1) is a
        // local maximum of the squared distance, so only the largest (k = 0) and smallest (k = 2) count.
        float m = sqrt(-a / 3.0);
        float phi = acos(clamp(-b / (2.0 * max(m * m * m, 1e-30)), -1.0, 1.0));
        candidates = 2.0 * m * cos(vec2(phi, phi + 6.2831853) / 3.0);
    }
    candidates -= k2 / 3.0;

    float best = 1e10;
    for (int i = 0; i < 2; ++i) {
        float t = candidates[i];
        // One Newton step on the cubic recovers the precision lost to cancellation.
        float value = ((t + k2) * t + k1) * t + k0;
        float slope = (3.0 * t + 2.0 * k2) * t + k1;
        if (abs(slope) > 1e-12) t -= value / slope;
        t = clamp(t, 0.0, 1.0);
        best = min(best, length(fromPoint + (2.0 * toControl + bend * t) * t));
    }
    return best;
}

const int knotPoints = 30;
const float majorRadius = 0.52;
const float minorRadius = 0.26;
const float stepAngle = 6.2831853 / float(knotPoints);
const float maxSagitta = 0.0285;  // largest distance from a piece to its chord (measured: 0.0282)

// Knot point from (cos 2t, sin 2t) and (cos 3t, sin 3t).
vec3 knotPoint(vec2 turn2, vec2 turn3) {
    float radial = majorRadius + minorRadius * turn3.x;
    return vec3(radial * turn2.x, radial * turn2.y, minorRadius * turn3.y);
}

// Multiplies unit complex numbers: advances an angle by a fixed step without calling sin or cos.
vec2 rotateBy(vec2 value, vec2 step) {
    return vec2(value.x * step.x - value.y * step.y, value.x * step.y + value.y * step.x);
}

float segmentDistance(vec3 p, vec3 a, vec3 b) {
    vec3 ab = b - a;
    float along = clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(p - a - ab * along);
}

// Walking the pieces in order: Q(i-1), Q(i) and the angle pairs of Q(i+1).
const vec2 step2 = vec2(cos(2.0 * stepAngle), sin(2.0 * stepAngle));
const vec2 step3 = vec2(cos(3.0 * stepAngle), sin(3.0 * stepAngle));
const vec3 lastPoint = vec3((majorRadius + minorRadius * cos(-3.0 * stepAngle)) * cos(-2.0 * stepAngle),
                            (majorRadius + minorRadius * cos(-3.0 * stepAngle)) * sin(-2.0 * stepAngle),
                            minorRadius * sin(-3.0 * stepAngle));
const vec3 firstPoint = vec3(majorRadius + minorRadius, 0.0, 0.0);

float sdf(vec3 p) {
    // Knot frame: `axis` is the threefold symmetry axis. The rows are orthonormal (a rotation).
    const vec3 axis = vec3(0.7977694, 0.3390520, 0.4986059);      // (0.8, 0.34, 0.5) normalised
    const vec3 side = vec3(-0.5299989, 0.0, 0.8479983);           // horizontal, perpendicular to axis
    const vec3 upward = vec3(-0.2875155, 0.9407676, -0.1796972);  // side x axis
    vec3 local = vec3(dot(p, side), dot(p, upward), dot(p, axis));

    // Pass 1: the two pieces with the nearest chords, and the third nearest chord distance.
    vec3 previous = lastPoint, current = firstPoint;
    vec2 turn2 = step2, turn3 = step3;
    float chord1 = 1e10, chord2 = 1e10, chord3 = 1e10;
    int piece1 = -1, piece2 = -1;
    vec3 start1, control1, end1, start2, control2, end2;
    for (int i = 0; i < knotPoints; ++i) {
        vec3 next = knotPoint(turn2, turn3);
        turn2 = rotateBy(turn2, step2);
        turn3 = rotateBy(turn3, step3);
        vec3 start = 0.5 * (previous + current);
        vec3 end = 0.5 * (current + next);
        float chord = segmentDistance(local, start, end);
        if (chord < chord1) {
            chord3 = chord2;
            chord2 = chord1; piece2 = piece1; start2 = start1; control2 = control1; end2 = end1;
            chord1 = chord; piece1 = i; start1 = start; control1 = current; end1 = end;
        } else if (chord < chord2) {
            chord3 = chord2;
            chord2 = chord; piece2 = i; start2 = start; control2 = current; end2 = end;
        } else {
            chord3 = min(chord3, chord);
        }
        previous = current;
        current = next;
    }
    float best = min(bezierDistance(local, start1, control1, end1),
                     bezierDistance(local, start2, control2, end2));

    // Pass 2, only when some other piece could still be nearer: its chord distance minus the
    // sagitta (a lower bound) must beat the best distance found.
    if (chord3 - maxSagitta < best) {
        previous = lastPoint;
        current = firstPoint;
        turn2 = step2;
        turn3 = step3;
        for (int i = 0; i < knotPoints; ++i) {
            vec3 next = knotPoint(turn2, turn3);
            turn2 = rotateBy(turn2, step2);
            turn3 = rotateBy(turn3, step3);
            vec3 start = 0.5 * (previous + current);
            vec3 end = 0.5 * (current + next);
            if (i != piece1 && i != piece2 && segmentDistance(local, start, end) - maxSagitta < best)
                best = min(best, bezierDistance(local, start, current, end));
            previous = current;
            current = next;
        }
    }
    return best - tubeRadius;
}
