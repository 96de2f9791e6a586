// Imitates: a Fragmentarium (Mikael Hvidtfeldt Christensen, "Syntopia") fragment for Tglad's
// Mandelbox in the formulation Fragmentarium's examples use (the running derivative kept in
// p.w, so one vec4 multiply scales the point and its derivative together): `#info` lines,
// `#define providesInit` with an empty init(), `#include "DE-Raytracer.frag"` (the host's
// raytracer: camera, main(), colouring, and the `vec4 orbitTrap` this file writes without
// declaring it), `#group Mandelbox`, uniforms with Fragmentarium's GUI annotations after the
// semicolon (`slider[min,default,max]`, `checkbox[true]`), globals computed at file scope from
// the uniforms (`vec4 scale = vec4(Scale, Scale, Scale, abs(Scale)) / MinRad2;`),
// `float DE(vec3 pos)`, and presets at the end: `#preset Default` (which Fragmentarium applies
// when the file loads) and a second preset, applied only when chosen.
//
// Host support: sdfwb reads the annotated uniforms as parameters with the sliders' defaults,
// then applies the Default preset's values to them (Iterations 12, Scale -2.5; Shrink keeps its
// slider default 2.5; the raytracer's settings in the preset, FOV, Eye and the like, name no
// uniform of this file); it declares orbitTrap as DE-Raytracer.frag does, and calls init(). The
// entry is `DE`.
//
// Why the audit should find it non-conservative: the estimate is (|p_n| - |s - 1|) / w_n -
// |s|^(1-n), w_n = p.w the product of the derivative's scales. The box fold is a reflection
// (isometric, piecewise) and the sphere fold a conformal map, so |grad |p_n|| <= w_n and the
// first part alone would be 1-Lipschitz; but inside the sphere fold's shell (MinRad2 < r^2 <
// 1) w_n is multiplied by MinRad2 / r^2, which varies with the point, and the quotient picks up
// -(|p_n| - |s - 1|) grad w_n / w_n^2, which adds to the slope where orbits pass through the
// shell. With the preset's Scale = -2.5 and 12 iterations the audit reads a Lipschitz constant
// of about 1.18 (1.14-1.18 over seeds); with the slider defaults (Scale 3, 17 iterations) it
// reads 0.95, with the Positive preset 0.54, and flags nothing: the flag depends on the Default
// preset being the one applied. (|grad |p_n|| <= w_n holds although c is added back each
// iteration: w gains c.w = 1 as the derivative gains the identity.) No bailout (every point
// runs all the iterations), and clamp, max and the multiplies are continuous: no jump. The box
// spans [-2, 2]^3 for this negative scale, [-0.8, 0.8]^3 after Shrink: the field grows
// outside. No NaN (r^2 = 0 gives MinRad2 / 0 = inf, clamped to 1, only at points no sample
// hits). No time: not animated.
// expect: entry=DE flags=non-conservative animated=no

#info Mandelbox distance estimator (Tglad's folds, derivative in p.w)
#info Negative scales give the mirrored 'box of boxes' variant.
#define providesInit
#include "DE-Raytracer.frag"
#group Mandelbox

// Number of fractal iterations.
uniform int Iterations;  slider[0,17,300]

// Orbit trap colouring: how many of the first iterations feed it.
uniform int ColorIterations;  slider[0,3,300]
uniform bool DoTrap; checkbox[true]

// Squared radius of the sphere fold's inner ball (the outer one is 1).
uniform float MinRad2; slider[0,0.25,2.0]

// Scale parameter. Negative values mirror every level.
uniform float Scale;  slider[-3.0,3.0,5.0]

// The fractal is large (radius 2 for negative scales): shrink it into the unit box.
uniform float Shrink; slider[1.0,2.5,8.0]

// Precomputed from the uniforms, once per frame on most drivers.
vec4 scale = vec4(Scale, Scale, Scale, abs(Scale)) / MinRad2;
float foldOffset = abs(Scale - 1.0);
float tailTerm = pow(abs(Scale), float(1 - Iterations));

void init() {
	// nothing to set up: the globals above depend only on the uniforms
}

float DE(vec3 pos) {
	pos *= Shrink;
	vec4 p = vec4(pos, 1.0);
	vec4 c = p; // the constant added back each iteration; its w is the derivative's 1

	for (int i = 0; i < Iterations; i++) {
		// box fold: reflect whatever lies outside [-1, 1] back in
		p.xyz = clamp(p.xyz, -1.0, 1.0) * 2.0 - p.xyz;

		// sphere fold: grow the inner ball, invert the shell, leave the outside alone
		float r2 = dot(p.xyz, p.xyz);
		if (DoTrap && i < ColorIterations) orbitTrap = min(orbitTrap, abs(vec4(p.xyz, r2)));
		p *= clamp(max(MinRad2 / r2, MinRad2), 0.0, 1.0);

		// scale (w by |Scale|) and translate
		p = p * scale + c;
	}
	return ((length(p.xyz) - foldOffset) / p.w - tailTerm) / Shrink;
}

#preset Default
FOV = 0.62536
Eye = -2.2,1.3,2.3
Target = 0,0,0
Up = 0.1887,0.9504,0.2470
AntiAlias = 1
Detail = -2.8
DetailAO = -0.5
FudgeFactor = 1
MaxRaySteps = 160
Dither = 0.5
AO = 0,0,0,0.7
Specular = 0.4
SpecularExp = 16
SpotLightDir = 0.5,0.3
CamLight = 1,1,1,0.9
Glow = 1,1,1,0
BaseColor = 1,1,1
OrbitStrength = 0.6
X = 0.5,0.6,0.6,0.7
Y = 1,0.6,0,0.4
Z = 0.8,0.78,1,0.5
R = 0.4,0.7,1,0.12
BackgroundColor = 0.6,0.6,0.45
GradientBackground = 0.3
Iterations = 12
ColorIterations = 3
DoTrap = true
MinRad2 = 0.25
Scale = -2.5
#endpreset

#preset Positive
FOV = 0.4
Eye = 3.1,2.2,3.6
Target = 0,0,0
Iterations = 17
Scale = 2.0
Shrink = 7.0
#endpreset
