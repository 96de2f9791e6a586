// The error is inside the included file, on its line 4.
#include "helper.glsl"

float sdf(vec3 p) {
    return helperDistance(p);
}
