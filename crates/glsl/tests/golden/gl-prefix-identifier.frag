float gl_Mine;
void main() { gl_FragColor = vec4(gl_Mine); }
