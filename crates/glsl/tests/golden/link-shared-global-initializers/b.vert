float scale = 3.0;
float scaled(float x);
void main() { gl_Position = gl_Vertex * scaled(1.0); }
