#ed-
uniform vec3 RotVector; slider[(1,0,0)tinÿuniform vec3 tint = vec3(
1, 0.5, 0.255);ÿider_(1,0,0),(1,1,1),(1,1,1)]
uniîÿÿwli
