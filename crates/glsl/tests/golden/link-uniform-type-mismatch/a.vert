uniform vec3 scale;
void main() { gl_Position = gl_Vertex * vec4(scale, 1.0); }
