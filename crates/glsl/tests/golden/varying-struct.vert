struct S { float a; };
varying S s;
void main() { gl_Position = vec4(1.0); }
