#version 120
// Sphere impostor, vertex stage.
//
// Each sphere is drawn as one screen-facing quad: four vertices that all
// carry the sphere centre in gl_Vertex and one corner of the quad in
// `corner`. The quad is placed in eye space in front of the sphere and
// made large enough to cover its silhouette; the fragment stage then
// ray-casts the sphere inside it.

attribute vec2 corner;   // this vertex's corner of the quad, each component -1 or +1
attribute float radius;  // sphere radius, in eye-space units

varying vec3 sphereCenter;  // eye space
varying float sphereRadius;
varying vec3 quadPoint;     // eye-space position of this vertex on the quad

// How much bigger than the sphere the quad is, so that perspective never
// pushes the silhouette outside it.
const float margin = 1.5;

void main()
{
    vec4 center = gl_ModelViewMatrix * gl_Vertex;
    sphereCenter = center.xyz / center.w;
    sphereRadius = radius;

    // In front of the sphere, facing the viewer.
    quadPoint = sphereCenter + vec3(corner * (radius * margin), radius);

    gl_Position = gl_ProjectionMatrix * vec4(quadPoint, 1.0);
    gl_FrontColor = gl_Color;
}
