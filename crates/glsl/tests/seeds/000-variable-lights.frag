// seed: 000_bda539806ee70a96.txt lines 413-460
// expect: pass
// version: 120
// stage: fragment
/* This is the corresponding fragment shader for materials */
uniform float light_enabled[8];
varying vec3 normal;

const vec3 UNIT_VEC3 = vec3(1.0, 0.0, 0.0);

void getLight(in int light, in float enabled, in vec3 N, inout vec4 ambient,
             inout vec4 diffuse, inout vec4 specular)
{
    vec3 L = normalize(mix(UNIT_VEC3, gl_LightSource[light].position.xyz,
                          enabled));
    vec3 H = normalize(mix(UNIT_VEC3, gl_LightSource[light].halfVector.xyz,
                          enabled));
    diffuse += enabled * max(0.0, dot(N, L)) *
              gl_FrontLightProduct[light].diffuse;
    specular += enabled * pow(max(0.0, dot(N, H)), gl_FrontMaterial.shininess) *
              gl_FrontLightProduct[light].specular;
    ambient += enabled * gl_FrontLightProduct[light].ambient;
}

void main()
{
    vec3 N = normalize(normal);
    vec4 ambient = vec4(0, 0, 0, 1);
    vec4 diffuse = vec4(0, 0, 0, 1);
    vec4 specular = vec4(0, 0, 0, 1);

    getLight(0, light_enabled[0], N, ambient, diffuse, specular);
    getLight(1, light_enabled[1], N, ambient, diffuse, specular);
    getLight(2, light_enabled[2], N, ambient, diffuse, specular);
    getLight(3, light_enabled[3], N, ambient, diffuse, specular);
    getLight(4, light_enabled[4], N, ambient, diffuse, specular);
    getLight(5, light_enabled[5], N, ambient, diffuse, specular);
    getLight(6, light_enabled[6], N, ambient, diffuse, specular);
    getLight(7, light_enabled[7], N, ambient, diffuse, specular);

    ambient.w = 1.;
    diffuse.w = 1.;
    specular.w = 1.;

    gl_FragColor = gl_Color * (diffuse + ambient + gl_FrontMaterial.emission)
        + specular;
    /* Need to copy over alpha */
    gl_FragColor.a = gl_Color.a;
}
