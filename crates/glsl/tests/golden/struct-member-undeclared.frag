struct Light { vec3 position; vec3 color; };
uniform Light light;
void main()
{
    gl_FragColor = vec4(light.colour, 1.0);
}
