/* sdfwb
name: Flying Bird
category: Animal
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A small bird in flight towards +X, flapping its wings (period 1.2 s). Ellipsoid body,
  round head with a cone beak, a fanned tail plate and two swept wing plates that rotate
  rigidly about shoulder axes along X. The wings are one plate mirrored through z = 0.
  Rigid motions keep distances; ellipsoid bounds and smooth unions make it conservative.
*/
#include "../lib/modelling.glsl"

