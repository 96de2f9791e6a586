/* sdfwb
name: Rubber Duck
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A bath duck looking towards +X: an ellipsoid body with a flat bottom and an upturned
  tail, a round head blended onto it, a flattened two-part beak and bead eyes.
  Conservative: ellipsoids are bounds and the parts are joined with min and smooth minimum,
  which keep the gradient at most 1 but underestimate the distance near the seams.
*/
#include "../lib/modelling.glsl"

