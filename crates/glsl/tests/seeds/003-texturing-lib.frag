// seed: 003_227224f6d3ad0fd5.txt lines 69-161
// expect: fail: line 20 indexes the built-in `gl_TexCoord` with the non-constant function parameter `index` (`gl_TexCoord[index].st`) although the shader never redeclares gl_TexCoord with a size: GLSL 1.10/1.20 (sections 4.1.9 and 7.6) require indices into gl_TexCoord to be integral constant expressions unless the array is first redeclared with a size (e.g. `varying vec4 gl_TexCoord[2];`); `gl_TextureEnvColor[index]` on line 38 is fine (sized by gl_MaxTextureUnits)
// version: 110
// stage: fragment
// note: the dump double-spaces every line; the inserted blank lines are removed
// note: library object (no main): applyTexture2D, linked with 003-single-texture.frag or 003-multi-texture.frag (see programs.txt)
/**
 * \file Texturing.frag
 */
const int REPLACE  = 0;
const int MODULATE = 1;
const int DECAL    = 2;
const int BLEND    = 3;
const int ADD      = 4;
const int COMBINE  = 5;

void applyTexture2D(in sampler2D texUnit, in int type, in int index, inout vec4 color)
{
    // Read from the texture
    vec4 texture = texture2D(texUnit, gl_TexCoord[index].st);

    if (type == REPLACE)
    {
        color = texture;
    }
    else if (type == MODULATE)
    {
        color *= texture;
    }
    else if (type == DECAL)
    {
        vec3 temp = mix(color.rgb, texture.rgb, texture.a);

        color = vec4(temp, color.a);
    }
    else if (type == BLEND)
    {
        vec3 temp = mix(color.rgb, gl_TextureEnvColor[index].rgb, texture.rgb);

        color = vec4(temp, color.a * texture.a);
    }
    else if (type == ADD)
    {
        color.rgb += texture.rgb;
        color.a   *= texture.a;

        color = clamp(color, 0.0, 1.0);
    }
    else
    {
        color = clamp(texture * color, 0.0, 1.0);
    }
}
