// seed: 000_bda539806ee70a96.txt lines 616-678
// expect: pass
// version: 120
// stage: vertex
// Vertex shader
uniform vec3 right_vector;
uniform vec3 up_vector;

varying vec4 color;
varying vec3 view_direction;
varying vec3 sphere_center;
varying float radius2;
varying vec3 point;

varying float u1;
varying float r1;

void main(void)
{
    // Get billboard attributes
    float right = gl_MultiTexCoord0.x;
    float up = gl_MultiTexCoord0.y;
    float radius = gl_MultiTexCoord0.z;
    radius2 = radius * radius; // compute squared radius

    u1 = up;
    r1 = right;

    // We need to project the vertex out to the edge of the square, which
    // is the following distance:
    // float corner_distance = sqrt(2.0 * radius2);
    // but since we need to normalize the corner vector computed below
    // which has length sqrt(2.0), we can simply use radius as corner distance
    // to compute vertex position of screen-oriented quad.

    // Compute corner vector
    vec3 corner_direction = up * up_vector + right * right_vector;

    // Calculate vertex of screen-oriented quad (billboard)
    vec4 vertex = vec4(gl_Vertex.xyz + radius * corner_direction,
                      gl_Vertex.w);

    // Calculate vertex position in modelview space
    vec4 eye_space_pos = gl_ModelViewMatrix * vertex;

    // Compute sphere position in modelview space
    vec4 tmppos = gl_ModelViewMatrix * gl_Vertex;
    sphere_center = vec3(tmppos) / tmppos.w;

    // Compute ray direction and origin point
    point = vec3(eye_space_pos) / eye_space_pos.w;
    view_direction = normalize(point);

    // Pass fog coordinate
    gl_FogFragCoord = abs(sphere_center.z);

    // Pass the transformed vertex for clipping plane calculations
    gl_ClipVertex = eye_space_pos;

    // Pass color
    color = gl_Color;

    // Pass transformed vertex
    gl_Position = gl_ModelViewProjectionMatrix * vertex;
}
