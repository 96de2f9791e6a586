/* sdfwb
name: Dice
category: Misc
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A six-sided die with rounded edges and spherical pips dimpled into its faces
  (opposite faces sum to seven: 1 on +X, 2 on +Y, 3 on +Z). A rounded box minus small
  spheres: the subtraction (max) makes it conservative.
  The audit measures it as exact: the pips are shallow, so the max() underestimate near their
  rims is below the audit's resolution; declared conservative because it is one in theory.
*/
#include "../lib/modelling.glsl"

