// A light loop over gl_LightSource[i]: unrolled for the first lights
// (static uniform reads), a dynamic index for a uniform light count.
varying vec3 normal;
uniform int extra_lights;

vec4 diffuse(int i, vec3 N)
{
    vec3 L = normalize(gl_LightSource[i].position.xyz);
    return max(dot(N, L), 0.0) * gl_LightSource[i].diffuse;
}

void main()
{
    vec3 N = normalize(normal);
    vec4 color = gl_LightModel.ambient;
    for (int i = 0; i < 2; i++)
        color += diffuse(i, N);
    for (int j = 2; j < extra_lights; j++)
        color += diffuse(j, N);
    gl_FragColor = color;
}
