#info Mandelbox
#include "DE-Raytracer.frag"
#group Box
uniform int Iterations;  slider[0,17,300]
uniform float Scale; slider[-3.0,3.0,5.0] Locked
uniform vec3 RotVector; slider[(0,0,0),(1,1,1),(1,1,1)]
uniform bool Julia; checkbox[false]
uniform vec3 BaseColor; color[1.0,0.5,0.25]
float DE(vec3 p) { return length(p) - Scale; }
#preset Default
Scale = 2.5 Locked
RotVector = 0,1,0
Julia = true
#endpreset
