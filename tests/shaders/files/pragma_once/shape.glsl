#pragma once
float shape(vec3 p) { return length(p) - 0.5; }
