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
*/

// Real cube root that accepts negative arguments.
