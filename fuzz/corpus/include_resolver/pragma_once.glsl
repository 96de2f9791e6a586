#include "shape.glsl"
#include "shape.glsl"
/* #include "ignored_in_comment.glsl" */
float sdf(vec3 p) {
    return shape(p);
}
// an error after the includes, to check that line numbers survive them:
float broken() { return missingAfterIncludes; }
