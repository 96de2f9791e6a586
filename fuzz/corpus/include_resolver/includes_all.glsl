// Every kind of include the fixed workspace offers (see fuzz_include_resolver.cpp).
#version 430
#include "shape.glsl"
#include "shape.glsl"
#include "sub/up.glsl"
  #  include "chain1.glsl"   // deeper than maxDepth 4
#include "../outside.glsl"
#include "missing.glsl"
#include "main.glsl"
#include <angled.glsl>
#include ""
/* #include "in_comment.glsl"
   still a comment */
#pragma once
float sdf(in vec3 p, float time) {
    return up(p) + 0.1 * sin(time);
}
