#version 130
uniform uint mode;
void main() {
    float v = 0.0;
    switch (mode) {
    case 1u:
        v = 0.5;
        break;
    default:
    }
    gl_FragColor = vec4(v);
}
