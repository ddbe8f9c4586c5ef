attribute int index;
void main() { gl_Position = vec4(float(index)); }
