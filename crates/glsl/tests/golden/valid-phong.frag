#version 120
varying vec3 normal;
varying vec3 eye_position;
void main()
{
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - eye_position);
    float diffuse = max(dot(n, l), 0.0);
    vec3 h = normalize(l - normalize(eye_position));
    float specular = pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess);
    gl_FragColor = gl_FrontLightProduct[0].ambient
        + diffuse * gl_FrontLightProduct[0].diffuse
        + specular * gl_FrontLightProduct[0].specular;
}
