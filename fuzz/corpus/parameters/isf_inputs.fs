/*{
  "ISFVSN": "2",
  "INPUTS": [
    { "NAME": "size", "TYPE": "float", "DEFAULT": 0.5, "MIN": 0.0, "MAX": 2.0, "LABEL": "Size" },
    { "NAME": "count", "TYPE": "long", "VALUES": [1, 2, 4], "DEFAULT": 2 },
    { "NAME": "on", "TYPE": "bool", "DEFAULT": true },
    { "NAME": "tint", "TYPE": "color", "DEFAULT": [1, 0.5, 0.25] },
    { "NAME": "at", "TYPE": "point2D", "DEFAULT": [0, 0], "MIN": [-1, -1], "MAX": [1, 1] },
    { "NAME": "img", "TYPE": "image" },
  ]
}*/
float map(vec3 p) { return length(p) - size; }
void main() { gl_FragColor = vec4(map(vec3(isf_FragNormCoord, TIME))); }
