uniform float radius = 0.5;   // @range 0.1 1.0 @step 0.01 @label "Sphere radius"
uniform int count = 4; // @range 1 12
uniform bool hollow = true;
uniform vec2 offset = vec2(0.0); // @range -1 1
uniform vec3 tint = vec3(1, 0.5, 0.25); // @color
uniform float scale = 2.0f; // @range 0.01 100 @log
float sdf(vec3 p) { return length(p) - radius; }
