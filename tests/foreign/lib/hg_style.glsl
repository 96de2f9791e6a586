////////////////////////////////////////////////////////////////
//
//                     hg_style.glsl
//
//  A small distance-function library written for sdfwb's tests,
//  in the manner of the Mercury demogroup's hg_sdf: constants as
//  #defines, f* primitives, p* domain operators that modify p in
//  place (inout) and return a cell index, fOp* combinations.
//  Same naming and calling conventions, our own code.
//
//  Included by several tests/foreign/*.glsl; not an SDF itself
//  (there is no sdf()/map() here).
//
////////////////////////////////////////////////////////////////

#define PI 3.14159265
#define TAU (2*PI)
#define PHI (sqrt(5)*0.5 + 0.5)

// [0,1] clamp as a macro (hg style), not a function.
#define saturate(x) clamp(x, 0., 1.)

// sign() that never answers 0
float sgn(float x) {
	return (x < 0.) ? -1. : 1.;
}

vec2 sgn(vec2 v) {
	return vec2(sgn(v.x), sgn(v.y));
}

float square (float x) { return x*x; }
vec2  square (vec2 x)  { return x*x; }
vec3  square (vec3 x)  { return x*x; }

float lengthSqr(vec3 x) {
	return dot(x, x);
}

// Largest / smallest component
float vmax(vec2 v) { return max(v.x, v.y); }
float vmax(vec3 v) { return max(v.x, max(v.y, v.z)); }
float vmin(vec2 v) { return min(v.x, v.y); }
float vmin(vec3 v) { return min(v.x, min(v.y, v.z)); }

////////////////////////////////////////////////////////////////
//
//                       PRIMITIVES
//
////////////////////////////////////////////////////////////////

float fSphere(vec3 p, float r) {
	return length(p) - r;
}

// Half-space below a plane: unit normal n, offset from the origin
float fPlane(vec3 p, vec3 n, float distanceFromOrigin) {
	return dot(p, n) + distanceFromOrigin;
}

// Box bound: exact on the faces, too small near edges and corners
float fBoxCheap(vec3 p, vec3 b) {
	return vmax(abs(p) - b);
}

// Box, exact everywhere
float fBox(vec3 p, vec3 b) {
	vec3 e = abs(p) - b;
	float outside = length(max(e, vec3(0)));
	float inside = vmax(min(e, vec3(0)));
	return outside + inside;
}

// 2D box (a bar endless along the third axis)
float fBox2(vec2 p, vec2 b) {
	vec2 e = abs(p) - b;
	return length(max(e, vec2(0))) + vmax(min(e, vec2(0)));
}

// Upright cylinder (axis y), half height <height>; a bound at the rims
float fCylinder(vec3 p, float r, float height) {
	float side = length(p.xz) - r;
	float caps = abs(p.y) - height;
	return max(side, caps);
}

// Upright capsule: segment from y=-c to y=c, radius r
float fCapsule(vec3 p, float r, float c) {
	float ySeg = abs(p.y) - c;
	vec3 q = vec3(p.x, max(ySeg, 0.), p.z);
	return length(q) - r;
}

// Distance to the segment <a>-<b>
float fLineSegment(vec3 p, vec3 a, vec3 b) {
	vec3 ab = b - a;
	float s = saturate(dot(p - a, ab)/dot(ab, ab));
	return length(p - (a + ab*s));
}

// Capsule between two points
float fCapsule(vec3 p, vec3 a, vec3 b, float r) {
	return fLineSegment(p, a, b) - r;
}

// Torus lying in the xz plane
float fTorus(vec3 p, float smallRadius, float largeRadius) {
	vec2 q = vec2(length(p.xz) - largeRadius, p.y);
	return length(q) - smallRadius;
}

// Hexagonal prism along y, measured at the circumcircle (a bound)
float fHexagonCircumcircle(vec3 p, vec2 h) {
	vec3 q = abs(p);
	float across = max(dot(q.xz, vec2(sqrt(3.)*0.5, 0.5)), q.z);
	return max(q.y - h.y, across - h.x);
}

////////////////////////////////////////////////////////////////
//
//                 DOMAIN OPERATORS (p is inout)
//
////////////////////////////////////////////////////////////////

// Rotation in a coordinate plane; pR(p.xz, a) turns x towards z.
void pR(inout vec2 p, float a) {
	float c = cos(a), s = sin(a);
	p = vec2(c*p.x + s*p.y, c*p.y - s*p.x);
}

void pR45(inout vec2 p) {
	p = sqrt(0.5)*vec2(p.x + p.y, p.y - p.x);
}

// Endless repetition along one axis with cells of width <size>
// centred on multiples of <size>. Returns the cell index.
float pMod1(inout float p, float size) {
	float h = 0.5*size;
	float cell = floor((p + h)/size);
	p = mod(p + h, size) - h;
	return cell;
}

// As pMod1, every second cell mirrored so neighbours agree at the seams
float pModMirror1(inout float p, float size) {
	float cell = pMod1(p, size);
	if (mod(cell, 2.) < 0.5) p = -p;
	return cell;
}

// Repetition limited to the cells <start>..<stop>; the end cells
// extend to infinity.
float pModInterval1(inout float p, float size, float start, float stop) {
	float h = 0.5*size;
	float cell = floor((p + h)/size);
	p = mod(p + h, size) - h;
	float clamped = clamp(cell, start, stop);
	p += size*(cell - clamped);
	return clamped;
}

// Angular repetition around the origin: <repetitions> sectors, the
// first one centred on +x. Returns the sector index.
float pModPolar(inout vec2 p, float repetitions) {
	float sector = TAU/repetitions;
	float a = atan(p.y, p.x) + 0.5*sector;
	float r = length(p);
	float cell = floor(a/sector);
	a = mod(a, sector) - 0.5*sector;
	p = r*vec2(cos(a), sin(a));
	if (abs(cell) >= 0.5*repetitions) cell = abs(cell);
	return cell;
}

// Repetition in a plane
vec2 pMod2(inout vec2 p, vec2 size) {
	vec2 h = 0.5*size;
	vec2 cell = floor((p + h)/size);
	p = mod(p + h, size) - h;
	return cell;
}

// Mirror at the plane |p| = dist; returns which side p was on
float pMirror (inout float p, float dist) {
	float side = sgn(p);
	p = abs(p) - dist;
	return side;
}

////////////////////////////////////////////////////////////////
//
//                     COMBINATIONS
//
////////////////////////////////////////////////////////////////

// Union with a 45-degree chamfer of size r
float fOpUnionChamfer(float a, float b, float r) {
	float chamfer = (a + b - r)*sqrt(0.5);
	return min(min(a, b), chamfer);
}

// Union with a quarter-circle fillet of radius r
float fOpUnionRound(float a, float b, float r) {
	vec2 u = max(vec2(r) - vec2(a, b), vec2(0));
	return max(r, min(a, b)) - length(u);
}

// Intersection with a rounded edge of radius r
float fOpIntersectionRound(float a, float b, float r) {
	vec2 u = max(vec2(r) + vec2(a, b), vec2(0));
	return min(-r, max(a, b)) + length(u);
}

float fOpDifferenceRound (float a, float b, float r) {
	return fOpIntersectionRound(a, -b, r);
}

// Quadratic soft union
float fOpUnionSoft(float a, float b, float r) {
	float e = max(r - abs(a - b), 0.);
	return min(a, b) - 0.25*e*e/r;
}
