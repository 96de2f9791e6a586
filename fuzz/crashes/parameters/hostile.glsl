uniform float r = 0.5; // @label "open
uniform vec3 c = vec3(1,,2);
uniform float x = 1e39;
