uniform vec4 scale;
void main() { gl_FragColor = scale; }
