#define MUL(a, b) ((a) * (b))
void main() { gl_FragColor = vec4(MUL(1.0)); }
