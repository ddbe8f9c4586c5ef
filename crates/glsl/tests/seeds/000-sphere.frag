// seed: 000_bda539806ee70a96.txt lines 280-380
// expect: pass
// version: 120
// stage: fragment
// note: semantic slip kept as given (valid GLSL, so it compiles): the exp2 fog term on lines 90-92 computes exp2(-gl_Fog.density * c * c * c * INV_LOG2), i.e. density*c^3, where GL_EXP2 fog is exp(-(density*c)^2) = exp2(-gl_Fog.density * gl_Fog.density * c * c * INV_LOG2) (c = gl_FogFragCoord), as 000-outline.frag and 000-x.frag write it
// Fragment shader

// 0 is no fog, 1 is linear, 2 is exp, 3 is exp2
uniform float fogging[4];

uniform float perspective;

varying vec4 color;
varying vec3 view_direction;
varying vec3 sphere_center;
varying float radius2;
varying vec3 point;

const float INV_LOG2 = 1.442695;

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

void main(void)
{
    vec3 ray_origin = mix(point, vec3(0., 0., 0.), perspective);
    vec3 ray_direction = mix(vec3(0., 0., 1.), normalize(view_direction),
                             perspective);
    vec3 sphere_direction = mix(ray_origin - sphere_center, sphere_center,
                                perspective);

    // Calculate sphere-ray intersection
    float b = mix(dot(sphere_direction, ray_direction),
                  dot(ray_direction, sphere_direction), perspective);
float position = b * b + radius2 - dot(sphere_direction, sphere_direction);

// Check if the ray missed the sphere
if (position < 0.0)
    discard;

// Calculate nearest point of intersection
float nearest = mix(sqrt(position) - b, b - sqrt(position), perspective);

// Calculate intersection point on the sphere surface. The ray
// origin is at the quad (center point), so we need to project
// back towards the user to get the front face.
vec3 ipoint = nearest * ray_direction + ray_origin;

// Calculate normal at the intersection point
vec3 N = normalize(ipoint - sphere_center);

// Calculate depth in fragment space
vec2 clipZW = ipoint.z * gl_ProjectionMatrix[2].zw +
    gl_ProjectionMatrix[3].zw;
gl_FragDepth = 0.5 + 0.5 * clipZW.x / clipZW.y;

// Calculate lighting
vec4 diffuse = vec4(0, 0, 0, 1);
vec4 ambient = vec4(0, 0, 0, 1);
vec4 specular = vec4(0, 0, 0, 1);

getLight(0, N, ambient, diffuse, specular);
getLight(1, N, ambient, diffuse, specular);

ambient.w = 1.;
diffuse.w = 1.;
specular.w = 1.;

// Calculate fog
// No fogging
float fog = fogging[0];

// Linear fog
fog += mix(0.0, clamp((gl_Fog.end - gl_FogFragCoord) * gl_Fog.scale,
    0.0, 1.0), fogging[1]);

// Exp fog
fog += mix(0.0, clamp(exp(-gl_Fog.density * gl_FogFragCoord), 0.0,
    1.0), fogging[2]);

// Exp^2 fog: exp(x) = 2^(x/log(2))
fog += mix(0.0, clamp(exp2(-gl_Fog.density * gl_FogFragCoord *
    gl_FogFragCoord * gl_FogFragCoord *
        INV_LOG2), 0.0, 1.0), fogging[3]);

// Calculate final color
gl_FragColor = mix(gl_Fog.color, color * (diffuse + ambient +
        gl_FrontMaterial.emission) + specular, fog);
}
