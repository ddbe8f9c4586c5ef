// Shared by the mesh shaders: loaded as the second source string, after
// the lecture's "#version 150\n" and before the stage's own file.
const float PI = 3.14159265;

uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat3 normalMatrix;
uniform vec3 lightDirection;

float lambert(vec3 n, vec3 l)
{
    return max(dot(normalize(n), normalize(l)), 0.0);
}
