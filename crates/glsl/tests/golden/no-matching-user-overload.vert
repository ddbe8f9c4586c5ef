float scale(float x, float k) { return x * k; }
float scale(vec2 x, float k) { return x.x * k; }
void main()
{
    gl_Position = vec4(scale(vec3(1.0), 2.0));
}
