// Imitates: a whole Shadertoy written with the Mercury demogroup's hg_sdf
// conventions, the library's pieces pasted at the top as people do on
// Shadertoy: #define PI/TAU, vmax(), fBox(), pR() rotating a swizzle in
// place, pMod1() repeating one axis in place and returning the cell index,
// fOpUnionChamfer(); then an arcade (a row of columns between a floor slab
// and a roof slab, turned by pR) in `float scene(vec3 p)`, and a
// mainImage() with a camera that sways with iTime (still at iTime = 0)
// set up by an IQ-style setCamera(ro, ta, 0.0), focal 2.0. The arcade
// floats in the cube over a sky that depends on rd.y only, so the picture
// can be compared with sdfwb's tracer.
//
// Why the audit should find it clean: fBox is exact; pR is a rotation and
// pMod1 a piecewise translation under which each endless column sits in
// the middle of its cell, so the nearest column is the one in the cell
// (exact, continuous across the cell borders); max() with a plane keeps
// the five columns within |x| <= 0.86, a 1-Lipschitz bound. The chamfer,
// (a + b - r)/sqrt(2) where it is below min(a, b), has |grad| =
// sqrt(1 + cos(angle between grad a and grad b)): 1 for the right angle at
// which the vertical columns (horizontal gradients) meet the slabs' flat
// faces (vertical gradients), which is the only place the chamfer is
// active: the slabs' rims lie 0.09 beyond the outer columns and 0.28 to
// the sides of the row, more than the chamfer's reach (~1.7 r = 0.07
// around the junction). The final max() with |y| - 0.7 clips the endless
// columns at the slabs' outer faces. So: continuous, |grad| <= 1, bounded
// (grows outside), no NaN. iTime moves only the camera, but the file uses
// it: animated.
// expect: entry=scene flags=none animated=yes
// picture: eye=0.4,1,3.2 target=0,0,0 focal=2.0

////////////////////////////////////////////////////////////////
//                hg_sdf-style helpers (pasted)
////////////////////////////////////////////////////////////////

#define PI 3.14159265
#define TAU (2*PI)

float vmax(vec3 v) {
	return max(max(v.x, v.y), v.z);
}

// Box: correct distance to corners
float fBox(vec3 p, vec3 b) {
	vec3 d = abs(p) - b;
	return length(max(d, vec3(0))) + vmax(min(d, vec3(0)));
}

// Rotate around a coordinate axis (i.e. in a plane perpendicular to that axis) by angle <a>.
void pR(inout vec2 p, float a) {
	p = cos(a)*p + sin(a)*vec2(p.y, -p.x);
}

// Repeat space along one axis. Use like this to repeat along the x axis:
// <float cell = pMod1(p.x,5);> - using the return value is optional.
float pMod1(inout float p, float size) {
	float c = floor(p/size + 0.5);
	p -= size*c;
	return c;
}

// The "Chamfer" method: a 45-degree bevel where the two shapes meet.
float fOpUnionChamfer(float a, float b, float r) {
	return min(min(a, b), (a + b - r)*sqrt(0.5));
}

////////////////////////////////////////////////////////////////

#define SPACING 0.38
#define CHAMFER 0.04

float scene(vec3 p) {
	pR(p.xz, 0.3);

	float floorSlab = fBox(p - vec3(0, -0.62, 0), vec3(0.92, 0.08, 0.35));
	float roofSlab  = fBox(p - vec3(0,  0.62, 0), vec3(0.92, 0.08, 0.35));

	// endless columns, one per cell, then only the middle five
	vec3 q = p;
	pMod1(q.x, SPACING);
	float columns = length(q.xz) - 0.07;
	columns = max(columns, abs(p.x) - 0.86);

	float d = fOpUnionChamfer(columns, floorSlab, CHAMFER);
	d = fOpUnionChamfer(d, roofSlab, CHAMFER);

	// cut the columns at the slabs' outer faces
	return max(d, abs(p.y) - 0.7);
}

vec3 normal(vec3 p) {
	vec2 e = vec2(0.0005, 0);
	return normalize(vec3(scene(p + e.xyy) - scene(p - e.xyy),
	                      scene(p + e.yxy) - scene(p - e.yxy),
	                      scene(p + e.yyx) - scene(p - e.yyx)));
}

float march(vec3 ro, vec3 rd) {
	float t = 0.;
	for (int i = 0; i < 256; ++i) {
		float d = scene(ro + rd*t);
		if (abs(d) < 0.0001*t) return t;
		t += d;
		if (t > 20.) break;
	}
	return -1.;
}

float ambientOcclusion(vec3 p, vec3 n) {
	float o = 0.;
	for (int i = 1; i <= 5; ++i) {
		float h = 0.03*float(i);
		o += max(h - scene(p + n*h), 0.)/h;
	}
	return clamp(1. - 0.25*o, 0., 1.);
}

mat3 setCamera(vec3 ro, vec3 ta, float cr) {
	vec3 cw = normalize(ta - ro);
	vec3 cp = vec3(sin(cr), cos(cr), 0.);
	vec3 cu = normalize(cross(cw, cp));
	vec3 cv = cross(cu, cw);
	return mat3(cu, cv, cw);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
	vec2 p = (2.*fragCoord - iResolution.xy)/iResolution.y;

	vec3 ro = vec3(0.4, 1., 3.2);
	pR(ro.xz, 0.3*sin(0.2*iTime));
	vec3 ta = vec3(0);
	mat3 ca = setCamera(ro, ta, 0.);
	vec3 rd = ca*normalize(vec3(p, 2.));

	vec3 col = vec3(0.68, 0.76, 0.92) - 0.25*rd.y;

	float t = march(ro, rd);
	if (t > 0.) {
		vec3 pos = ro + rd*t;
		vec3 n = normal(pos);
		vec3 light = normalize(vec3(0.6, 0.9, 0.4));
		float diffuse = max(dot(n, light), 0.);
		float ao = ambientOcclusion(pos, n);
		vec3 albedo = vec3(0.85, 0.55, 0.25);   // sandstone
		if (abs(pos.y) < 0.53) albedo = vec3(0.9, 0.8, 0.3);   // columns
		col = albedo*(diffuse*vec3(1.1, 1., 0.85) + ao*(0.25 + 0.1*n.y));
	}

	fragColor = vec4(pow(col, vec3(1./2.2)), 1.);
}
