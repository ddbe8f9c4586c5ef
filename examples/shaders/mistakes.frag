// Three deliberate mistakes, for `shaderbox check` to report.
// No #version: this is GLSL 1.10.

uniform sampler2D tex;
varying vec2 uv;

void main()
{
    float brightness = 1;                        // 1.10 has no int -> float conversion
    vec3 c = texture2D(tex, uv);                 // texture2D returns a vec4
    gl_FragColour = vec4(c * brightness, 1.0);   // gl_FragColor, misspelt
}
