vec4 shade(vec3 n);
void main() { gl_FragColor = shade(vec3(0.0, 0.0, 1.0)); }
