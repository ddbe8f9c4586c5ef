float f(float x) { return x; }
int f(float x) { return 1; }
void main() { gl_FragColor = vec4(f(1.0)); }
