// seed: 003_227224f6d3ad0fd5.txt lines 265-295
// expect: pass
// version: 110
// stage: vertex
// note: the dump double-spaces every line; the inserted blank lines are removed
/**
 * \file Lighting.vert
 */
varying vec3 normal;
varying vec3 vertex;

void main()
{
    // Calculate the normal
    normal = normalize(gl_NormalMatrix * gl_Normal);

    // Transform the vertex position to eye space
    vertex = vec3(gl_ModelViewMatrix * gl_Vertex);

    gl_Position = ftransform();
}
