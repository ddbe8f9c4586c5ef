void main() { gl_FragColor = vec4(1.0); }
void main() { gl_FragColor = vec4(0.0); }
