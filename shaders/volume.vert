// volume.vert: volume ray casting through a 3D texture (vertex stage, for
// volume.frag).
//
// What it does: the volume is the unit cube [0,1]^3 in object space, and
// object space is texture space. Draw the cube's front faces (cull back
// faces) with gl_MultiTexCoord0.xyz = gl_Vertex.xyz. The shader hands on
// the ray's entry point (`ray_start`, texture space) and its direction in
// texture space (`ray_direction`, not normalised): perspective, from the
// eye (the model-view inverse applied to the eye-space origin) to the
// vertex, which is affine in the position and so interpolates exactly;
// orthographic, the eye-space view direction (0,0,-1) taken back to
// object space.
//
// State it reads: uniform float perspective (1.0 perspective, 0.0
// orthographic); gl_Vertex, gl_MultiTexCoord0, gl_ModelViewMatrixInverse,
// gl_ModelViewProjectionMatrix.
//
// After the "Shaders" slides (seed 004, "Volume Shading": starting
// location from the 3D texture coordinates, ray direction from the eye
// position taken back by gl_ModelViewMatrixInverse), which give both of
// its forms; the orthographic form is added.

uniform float perspective;

varying vec3 ray_start;
varying vec3 ray_direction;

void main(void)
{
    vec3 eye = (gl_ModelViewMatrixInverse * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
    vec3 view = (gl_ModelViewMatrixInverse * vec4(0.0, 0.0, -1.0, 0.0)).xyz;
    ray_direction = mix(view, gl_Vertex.xyz - eye, perspective);
    ray_start = gl_MultiTexCoord0.xyz;
    gl_Position = ftransform();
}
