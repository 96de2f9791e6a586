/* sdfwb
name: Teapot
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A teapot pouring towards +X: a squat round body on a foot ring, a domed lid with a
  knob, an S-curved spout made of tapered segments that rises from the lower front, and a
  loop handle at the back (torus in the XY plane, outer half). Ellipsoid bounds, unions and
  smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

