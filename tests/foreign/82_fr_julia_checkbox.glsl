// Imitates: a Fragmentarium (Syntopia) Mandelbulb fragment of the kind the examples folder and
// fractalforums threads pass around: `#info`, `#define providesInit`, `#include
// "MathUtils.frag"` and `#include "DE-Raytracer.frag"`, `#group Mandelbulb`, a Julia switch
// as a checkbox (`uniform bool Julia; checkbox[false]`) with its constant as a vector slider
// (`uniform vec3 JuliaC; slider[(-2,-2,-2),(0,0,0),(2,2,2)]`), the iteration count locked in
// the GUI (`uniform int Iterations; slider[0,9,100] Locked`), White and Nylander's power
// formula in spherical coordinates with the running derivative dr, a bailout, orbitTrap
// written undeclared, `float DE(vec3 pos)` returning 0.5 log(r) r / dr, and a `#preset
// Default` (with the `Locked` suffix on a value, as Fragmentarium saves it) that repeats the
// fractal's defaults beside the camera. `time` appears only in a comment.
//
// Host support: sdfwb reads the annotated uniforms (bool checkboxes, vector sliders, the
// `Locked` keyword after a slider) as parameters, applies the Default preset (the same
// values), declares orbitTrap and calls the empty init(). The entry is `DE`. Not animated:
// `time` is only in a comment, and sdfwb reads the text without its comments.
//
// Why the audit should find it discontinuous and non-conservative: 0.5 log(r) r / dr is a
// distance estimate only for escaping orbits, and only asymptotically. Near and inside the bulb
// (orbits still bounded after 9 iterations, about a third of the cube) it follows the orbit,
// which is chaotic: dr multiplies by 8 r^7 each step, an orbit that passes near the origin
// resets it to about 1, and an orbit near the z axis (the formula's poles) turns fast in phi, so
// f swings between -0.002 and -0.08 within 1e-5. |grad f| exceeds 1.05 at about 12 % of the
// points inside and about half a percent of those outside: the audit reads a Lipschitz constant
// of about 3.3 (2.9-3.5 over seeds). The field is continuous in exact arithmetic: the bailout
// switch is seamless (one more iteration past r = 5 changes the estimate by a relative
// |pos| / r^8 + 1 / (8 r^7 dr), about 1e-6), atan()'s cut is harmless for an integer Power,
// and in float64 the rises across the audit's jump points shrink 63-fold per 63-fold
// refinement (0.01-0.07 over 3e-7, then 1e-4-2e-3 over 5e-9: cliffs a few 1e-7 wide with
// slopes of 1e5). In float32 they do not: near |p| = 0.8 neighbouring coordinates are 6e-8
// apart, and the audit's finest line search (64 points over about 1e-5) puts a whole cliff
// within one or two of its intervals, so it confirms jumps of about 0.02 (median; 17-23 jumps
// on every seed tried). See Known misses in the README. No NaN: acos() gets z.z / r clamped to
// [-1, 1], and r = 0 only at a point no sample hits. The bulb (radius about 1.2) fits the view.
// expect: entry=DE flags=discontinuous,non-conservative animated=no

#info Mandelbulb distance estimator (White & Nylander's power formula)
#define providesInit
#include "MathUtils.frag"
#include "DE-Raytracer.frag"
#group Mandelbulb

// Number of fractal iterations.
uniform int Iterations;  slider[0,9,100] Locked

// Number of iterations that feed the orbit trap colouring.
uniform int ColorIterations;  slider[0,4,100]

// Mandelbulb exponent (8 is standard)
uniform float Power; slider[0,8,16]

// Escape radius
uniform float Bailout; slider[0,5,30]

// Julia mode: add a constant instead of the starting point
uniform bool Julia; checkbox[false]
uniform vec3 JuliaC; slider[(-2,-2,-2),(0,0,0),(2,2,2)]

// To animate the power, declare `uniform float time;` and use Power + sin(time) below.

void init() {
}

// z -> z^Power in spherical coordinates; dr follows the derivative's length
void powN(inout vec3 z, float r, inout float dr) {
	float theta = acos(clamp(z.z / r, -1.0, 1.0)) * Power;
	float phi = atan(z.y, z.x) * Power;
	float rp = pow(r, Power - 1.0);
	dr = rp * Power * dr + 1.0;
	z = rp * r * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

float DE(vec3 pos) {
	vec3 z = pos;
	float r = length(z);
	float dr = 1.0;
	for (int i = 0; i < Iterations; i++) {
		if (r > Bailout) break;
		powN(z, r, dr);
		z += Julia ? JuliaC : pos;
		r = length(z);
		if (i < ColorIterations) orbitTrap = min(orbitTrap, abs(vec4(z, r * r)));
	}
	return 0.5 * log(r) * r / dr;
}

#preset Default
FOV = 0.56
Eye = 1.9,1.5,2.7
Target = 0,0,0
Up = -0.14,0.92,-0.37
Detail = -2.6
DetailAO = -0.6
FudgeFactor = 0.8
MaxRaySteps = 180
AO = 0,0,0,0.75
Specular = 0.5
SpecularExp = 20
SpotLightDir = 0.3,0.5
CamLight = 1,1,1,1
BaseColor = 1,1,1
OrbitStrength = 0.7
X = 0.5,0.6,0.6,0.5
Y = 1,0.6,0,0.5
Z = 0.8,0.78,1,0.4
R = 0.67,0.4,1,0.1
BackgroundColor = 0.2,0.2,0.25
Iterations = 9 Locked
ColorIterations = 4
Power = 8
Bailout = 5
Julia = false
JuliaC = 0,0,0
#endpreset
