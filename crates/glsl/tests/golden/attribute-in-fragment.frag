attribute vec4 position;
void main() { gl_FragColor = position; }
