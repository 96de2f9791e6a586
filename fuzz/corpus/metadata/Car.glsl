/* sdfwb
name: Car
category: Vehicle
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A compact hatchback driving towards +X with its wheels turning (a fifth of a turn per
  second, so the five-spoke wheels loop every second). Rounded-box body with wheel arches,
  a cabin with a raked windscreen and recessed side windows, bumpers, headlights, and four
  wheels (torus tyre, rim disc, spokes). Each wheel is a rigid rotation of one wheel; the
  front and back wheels are evaluated separately (mirroring in x would reverse their spin),
  the left and right ones by mirroring in z, which keeps the spin. Conservative.
*/
#include "../lib/modelling.glsl"

