// The stage's own file: the third source string.
in vec3 normal;
out vec4 color;

void main(void)
{
    float d = lambert(normal, lightDirection);
    color = vec4(vec3(d) + 0.1 * sin(PI * 0.5), 1.0);
}
