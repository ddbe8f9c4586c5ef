#ifndef LIGHTS
#error LIGHTS must be defined by the application
#endif
void main() { gl_FragColor = vec4(1.0); }
