// sdf takes a vec2 here (line 3), which the contract does not allow.
float sdf(vec2 p) {
    return length(p) - 0.5;
}
