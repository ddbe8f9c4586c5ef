#version 130
uniform int mode;
void main() {
    float v = 0.0;
    switch (mode) {
    case 1:
        v = 0.5;
        break;
    case 2 - 1:
        v = 1.0;
    }
    gl_FragColor = vec4(v);
}
