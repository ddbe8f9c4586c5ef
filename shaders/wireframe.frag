// wireframe.frag: single-pass wireframe over shaded triangles (fragment
// stage; vertex: wireframe.vert, or wireframe-geom.vert + wireframe.geom).
//
// What it does: recovers the window-space distance to the nearest
// triangle edge (edge_distance * gl_FragCoord.w, see wireframe.vert),
// and blends line_color over the fill with intensity exp2(-2 d^2), where
// d is that distance minus half of line_width (0 inside the line): a
// line_width-pixel line with smooth, antialiased sides, as the slides
// suggest (fade by e^(-2 d^2), exp or exp2). The fill is gl_Color lit by
// GL light 0 (directional): ambient + diffuse of the front light product
// with gl_Color as the material colour; both faces lit (|N.L|).
//
// State it reads: uniform vec4 line_color; uniform float line_width
// (pixels); gl_LightSource[0].position, gl_LightSource[0].ambient,
// gl_LightSource[0].diffuse, gl_Color, gl_FragCoord,
// `varying vec3 edge_distance, normal`.
//
// After the "Shaders" slides (seed 004, "Wireframe Shading": find the
// minimum distance, compare it to the line width, fade); see
// wireframe.vert for the changes.

uniform vec4 line_color;
uniform float line_width;

varying vec3 edge_distance;
varying vec3 normal;

void main(void)
{
    vec3 dist = edge_distance * gl_FragCoord.w;
    float d = min(dist.x, min(dist.y, dist.z));
    d = max(d - 0.5 * line_width, 0.0);
    float line = exp2(-2.0 * d * d);

    vec3 L = normalize(gl_LightSource[0].position.xyz);
    float n_dot_l = abs(dot(normalize(normal), L));
    vec3 fill = gl_Color.rgb * (gl_LightSource[0].ambient.rgb +
                                n_dot_l * gl_LightSource[0].diffuse.rgb);
    fill = clamp(fill, 0.0, 1.0);
    gl_FragColor = vec4(mix(fill, line_color.rgb, line * line_color.a), gl_Color.a);
}
