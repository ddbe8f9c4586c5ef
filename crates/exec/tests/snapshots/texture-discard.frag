// A texture lookup (implicit LOD from derivatives), a lookup with a
// bias, and discard on the looked-up alpha.
uniform sampler2D tex;
uniform sampler2D detail;
uniform float cutoff;

void main()
{
    vec4 c = texture2D(tex, gl_TexCoord[0].st);
    if (c.a < cutoff)
        discard;
    vec4 d = texture2D(detail, gl_TexCoord[0].st * 8.0, 1.0);
    gl_FragColor = c * d;
}
