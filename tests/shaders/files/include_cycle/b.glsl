// b includes a again on line 2.
#include "a.glsl"
float bHelper() { return 1.0; }
