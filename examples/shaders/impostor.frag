#version 120
// Sphere impostor, fragment stage.
//
// Casts the view ray through this fragment of the quad against the sphere:
// fragments that miss are discarded; the others get per-pixel lighting from
// light 0, a dark outline near the silhouette, fog, and the depth of the
// sphere surface (not of the quad), so impostors intersect correctly.

varying vec3 sphereCenter;
varying float sphereRadius;
varying vec3 quadPoint;

// Width of the outline, as a fraction of the sphere's apparent radius.
const float outlineWidth = 0.12;

void main()
{
    // Ray from the eye (the origin of eye space) through this fragment:
    // solve |t*dir - c|^2 = r^2 for the nearest t.
    vec3 dir = normalize(quadPoint);
    float b = dot(dir, sphereCenter);
    float c = dot(sphereCenter, sphereCenter) - sphereRadius * sphereRadius;
    float disc = b * b - c;
    if (disc < 0.0)
        discard;
    float t = b - sqrt(disc);
    vec3 hit = dir * t;
    vec3 normal = (hit - sphereCenter) / sphereRadius;

    // Blinn-Phong with a directional light 0.
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    vec3 h = normalize(l - dir);
    float diffuse = max(dot(normal, l), 0.0);
    float specular = pow(max(dot(normal, h), 0.0), gl_FrontMaterial.shininess);
    vec4 color = gl_Color * (gl_LightSource[0].ambient + diffuse * gl_LightSource[0].diffuse)
               + specular * gl_LightSource[0].specular * gl_FrontMaterial.specular;

    // 0 on the silhouette, 1 at the centre of the disc.
    float edge = sqrt(disc) / sphereRadius;
    if (edge < outlineWidth)
        color.rgb *= 0.2;

    // Exponential fog on the distance to the eye.
    float fog = clamp(exp(-gl_Fog.density * length(hit)), 0.0, 1.0);
    gl_FragColor = vec4(mix(gl_Fog.color.rgb, color.rgb, fog), color.a);

    // Window-space depth of the hit point (GL 2.1 section 2.11.1).
    vec4 clip = gl_ProjectionMatrix * vec4(hit, 1.0);
    float ndcDepth = clip.z / clip.w;
    gl_FragDepth = 0.5 * (gl_DepthRange.diff * ndcDepth + gl_DepthRange.near + gl_DepthRange.far);
}
