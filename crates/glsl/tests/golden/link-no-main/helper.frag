vec4 shade() { return vec4(1.0); }
