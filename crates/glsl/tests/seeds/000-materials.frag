// seed: 000_bda539806ee70a96.txt lines 151-186
// expect: pass
// version: 120
// stage: fragment
/* This is the corresponding fragment shader for materials */

// Note that this comes from the vertex shader and has been interpolated to
// the correct value for this pixel.
varying vec3 normal;

void getLight(in int light, in vec3 N, inout vec4 ambient, inout vec4 diffuse,
             inout vec4 specular)
{
    vec3 L = normalize(gl_LightSource[light].position.xyz);
    vec3 H = normalize(gl_LightSource[light].halfVector.xyz);
    diffuse += max(0.0, dot(N, L)) * gl_FrontLightProduct[light].diffuse;
    specular += pow(max(0.0, dot(N, H)), gl_FrontMaterial.shininess) *
        gl_FrontLightProduct[light].specular;
    ambient += gl_FrontLightProduct[light].ambient;
}

void main()
{
    vec3 N = normalize(normal);
    vec4 ambient = vec4(0, 0, 0, 1);
    vec4 diffuse = vec4(0, 0, 0, 1);
    vec4 specular = vec4(0, 0, 0, 1);

    getLight(0, N, ambient, diffuse, specular);
    getLight(1, N, ambient, diffuse, specular);

    ambient.w = 1.;
    diffuse.w = 1.;
    specular.w = 1.;

    gl_FragColor = gl_Color * (diffuse + ambient + gl_FrontMaterial.emission)
        + specular;
    /* Need to copy over alpha */
    gl_FragColor.a = gl_Color.a;
}
