// The stage's own file: the third source string.
in vec3 in_pos;
in vec3 in_normal;
out vec3 normal;

void main(void)
{
    normal = normalMatrix * in_normal;
    gl_Position = projectionMatrix * modelViewMatrix * vec4(in_pos, 1.0);
}
