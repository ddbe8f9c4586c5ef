// variable-lights.frag: materials.frag for any of the eight GL lights,
// switched by a uniform (fragment stage; pair: materials.vert).
//
// What it does: as materials.frag, but sums lights 0-7, each weighted by
// light_enabled[i] (1.0 on, 0.0 off). There is no branch: a disabled
// light's direction is replaced by a dummy unit vector through mix() (so
// a zero or garbage position cannot produce NaN) and its terms are
// multiplied by 0, which is the seed's trick for hardware of its time that
// branched badly.
//
// State it reads: uniform float light_enabled[8];
// gl_LightSource[0..7].position/.halfVector (directional, eye space),
// gl_FrontLightProduct[0..7], gl_FrontMaterial.emission/.shininess,
// gl_Color, `varying vec3 normal`.
//
// After the seed talk ("GLSL v1.20", "variable lights" materials fragment
// shader), which has no slips. The enable value must be exactly 0.0 or
// 1.0: in between, the dummy direction is blended into the light's.

uniform float light_enabled[8];
varying vec3 normal;

const vec3 DUMMY_DIRECTION = vec3(1.0, 0.0, 0.0);

void addLight(in int light, in float enabled, in vec3 N, inout vec4 ambient,
              inout vec4 diffuse, inout vec4 specular)
{
    vec3 L = normalize(mix(DUMMY_DIRECTION, gl_LightSource[light].position.xyz, enabled));
    vec3 H = normalize(mix(DUMMY_DIRECTION, gl_LightSource[light].halfVector.xyz, enabled));
    ambient += enabled * gl_FrontLightProduct[light].ambient;
    diffuse += enabled * max(0.0, dot(N, L)) * gl_FrontLightProduct[light].diffuse;
    specular += enabled * pow(max(0.0, dot(N, H)), gl_FrontMaterial.shininess) *
                gl_FrontLightProduct[light].specular;
}

void main(void)
{
    vec3 N = normalize(normal);
    vec4 ambient = vec4(0.0, 0.0, 0.0, 1.0);
    vec4 diffuse = vec4(0.0, 0.0, 0.0, 1.0);
    vec4 specular = vec4(0.0, 0.0, 0.0, 1.0);

    addLight(0, light_enabled[0], N, ambient, diffuse, specular);
    addLight(1, light_enabled[1], N, ambient, diffuse, specular);
    addLight(2, light_enabled[2], N, ambient, diffuse, specular);
    addLight(3, light_enabled[3], N, ambient, diffuse, specular);
    addLight(4, light_enabled[4], N, ambient, diffuse, specular);
    addLight(5, light_enabled[5], N, ambient, diffuse, specular);
    addLight(6, light_enabled[6], N, ambient, diffuse, specular);
    addLight(7, light_enabled[7], N, ambient, diffuse, specular);

    ambient.w = 1.0;
    diffuse.w = 1.0;
    specular.w = 1.0;
    vec4 lit = gl_Color * (diffuse + ambient + gl_FrontMaterial.emission) + specular;
    gl_FragColor = vec4(lit.rgb, gl_Color.a);
}
