#version 130
uniform uint flags;
void main() {
    int bit = 4;
    gl_FragColor = vec4(float(flags & bit));
}
