//! Fixed-function processing as generated GLSL 1.10.
//!
//! When a program lacks a vertex or fragment shader (or no program is in
//! use), the draw runs shaders generated here from the current GL state,
//! on the same engine as user shaders. The generated text reads the GL
//! state through the built-in uniforms (`gl_LightSource`, `gl_Fog`...), so
//! it only depends on the state that changes its shape (which lights are
//! enabled, the texture environment modes...); the draw code caches
//! compiled stages by their source text.
//!
//! Vertex stage (GL 2.1 §2.11-2.14): `ftransform()`, eye-space clip vertex,
//! lighting per §2.14.1 (positional and directional lights, attenuation,
//! spot lights, local or infinite viewer, two-sided lighting, separate
//! specular color, color material), texture coordinates through the
//! texture matrices with coordinate generation (§2.11.4: object linear,
//! eye linear, sphere map, reflection map, normal map), the fog
//! coordinate (§3.10: |z_eye| or the fog coordinate attribute).
//!
//! Fragment stage: the texture environments REPLACE / MODULATE / DECAL /
//! BLEND / ADD of §3.8.13 (Table 3.22, by the texture's base format) for
//! every enabled unit, in unit order (GL_COMBINE runs as MODULATE), color
//! sum (§3.9) and fog (§3.10).

use crate::enums::*;
use crate::texture_format::base_format;
use crate::Context;
use std::fmt::Write;

/// Name of the sampler uniform the fixed-function fragment stage uses for
/// texture unit `unit` (its value is the unit number).
pub fn sampler_name(unit: usize) -> String {
    format!("ff_sampler{unit}")
}

/// Parses [`sampler_name`] back into the unit.
pub fn sampler_unit(name: &str) -> Option<u32> {
    name.strip_prefix("ff_sampler")?.parse().ok()
}

/// The enabled texture target of a unit, by GL 2.1 §3.8.15 priority.
pub fn enabled_target(ctx: &Context, unit: u32) -> Option<u32> {
    [
        GL_TEXTURE_CUBE_MAP,
        GL_TEXTURE_3D,
        GL_TEXTURE_2D,
        GL_TEXTURE_1D,
    ]
    .into_iter()
    .find(|&t| ctx.st.is_on_unit(t, unit))
}

impl Context {
    /// Number of texture coordinate sets the fixed-function fragment stage
    /// reads (one past the last enabled unit).
    pub fn ff_texcoord_count(&self) -> usize {
        (0..crate::MAX_TEXTURE_UNITS as u32)
            .filter(|&u| enabled_target(self, u).is_some())
            .map(|u| u as usize + 1)
            .max()
            .unwrap_or(0)
    }

    /// The fixed-function vertex shader for the current state, writing
    /// `texcoords` texture coordinate sets.
    pub fn ff_vertex_source(&self, texcoords: usize) -> String {
        let st = &self.st;
        let lighting = st.is_on(GL_LIGHTING);
        let clip = (0..crate::MAX_CLIP_PLANES as u32).any(|i| st.is_on(GL_CLIP_PLANE0 + i));
        let fog = st.is_on(GL_FOG);
        let mut s = String::from("// fixed-function vertex processing\n");
        let lights: Vec<usize> = (0..crate::MAX_LIGHTS)
            .filter(|&i| st.is_on(GL_LIGHT0 + i as u32))
            .collect();
        if lighting {
            self.ff_lighting_function(&mut s, &lights);
        }
        s.push_str("void main()\n{\n    gl_Position = ftransform();\n");
        s.push_str("    vec4 ecPos = gl_ModelViewMatrix * gl_Vertex;\n");
        let needs_normal = lighting
            || (0..texcoords).any(|u| {
                (0..4).any(|c| {
                    st.is_on_unit(GL_TEXTURE_GEN_S + c as u32, u as u32)
                        && matches!(
                            st.tex_gen.get(u).map(|g| g[c].mode),
                            Some(GL_SPHERE_MAP | GL_REFLECTION_MAP | GL_NORMAL_MAP)
                        )
                })
            });
        if needs_normal {
            s.push_str("    vec3 n = gl_NormalMatrix * gl_Normal;\n");
            if st.is_on(GL_NORMALIZE) {
                s.push_str("    n = normalize(n);\n");
            } else if st.is_on(GL_RESCALE_NORMAL) {
                s.push_str("    n = n * gl_NormalScale;\n");
            }
        }
        if clip {
            s.push_str("    gl_ClipVertex = ecPos;\n");
        }
        if lighting {
            let two = st.light_model_two_side;
            s.push_str("    vec4 sec;\n");
            s.push_str("    gl_FrontColor = ff_light(n, ecPos, false, sec);\n");
            s.push_str("    gl_FrontSecondaryColor = sec;\n");
            if two {
                s.push_str("    gl_BackColor = ff_light(-n, ecPos, true, sec);\n");
                s.push_str("    gl_BackSecondaryColor = sec;\n");
            } else {
                s.push_str("    gl_BackColor = gl_FrontColor;\n");
                s.push_str("    gl_BackSecondaryColor = gl_FrontSecondaryColor;\n");
            }
        } else {
            s.push_str("    gl_FrontColor = gl_Color;\n    gl_BackColor = gl_Color;\n");
            s.push_str("    gl_FrontSecondaryColor = gl_SecondaryColor;\n");
            s.push_str("    gl_BackSecondaryColor = gl_SecondaryColor;\n");
        }
        for u in 0..texcoords.min(crate::MAX_TEXTURE_UNITS) {
            let _ = writeln!(s, "    vec4 tc{u} = gl_MultiTexCoord{u};");
            for (c, comp) in ["s", "t", "p", "q"].iter().enumerate() {
                if !st.is_on_unit(GL_TEXTURE_GEN_S + c as u32, u as u32) {
                    continue;
                }
                let plane = ["S", "T", "R", "Q"][c];
                let expr = match st.tex_gen[u][c].mode {
                    GL_OBJECT_LINEAR => format!("dot(gl_ObjectPlane{plane}[{u}], gl_Vertex)"),
                    GL_EYE_LINEAR => format!("dot(gl_EyePlane{plane}[{u}], ecPos)"),
                    GL_SPHERE_MAP => {
                        format!("ff_sphere_map(ecPos, n).{}", ["x", "y"][c.min(1)])
                    }
                    GL_REFLECTION_MAP => format!(
                        "reflect(normalize(ecPos.xyz), normalize(n)).{}",
                        ["x", "y", "z"][c.min(2)]
                    ),
                    _ => format!("n.{}", ["x", "y", "z"][c.min(2)]),
                };
                let _ = writeln!(s, "    tc{u}.{comp} = {expr};");
            }
            let _ = writeln!(s, "    gl_TexCoord[{u}] = gl_TextureMatrix[{u}] * tc{u};");
        }
        if fog {
            if st.fog.coord_src == GL_FOG_COORD {
                s.push_str("    gl_FogFragCoord = gl_FogCoord;\n");
            } else {
                s.push_str("    gl_FogFragCoord = abs(ecPos.z);\n");
            }
        }
        s.push_str("}\n");
        if s.contains("ff_sphere_map") {
            // GL 2.1 §2.11.4: r = u - 2 n (n . u), m = 2 sqrt(rx² + ry² + (rz + 1)²).
            let f = "vec2 ff_sphere_map(vec4 ecPos, vec3 n)\n{\n    vec3 u = normalize(ecPos.xyz);\n    vec3 r = reflect(u, normalize(n));\n    float m = 2.0 * sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0));\n    return vec2(r.x / m + 0.5, r.y / m + 0.5);\n}\n";
            s = s.replacen("void main()", &format!("{f}void main()"), 1);
        }
        s
    }

    /// `vec4 ff_light(vec3 n, vec4 ecPos, bool back, out vec4 sec)`: GL 2.1
    /// §2.14.1 for the enabled lights.
    fn ff_lighting_function(&self, s: &mut String, lights: &[usize]) {
        let st = &self.st;
        let cm = st.is_on(GL_COLOR_MATERIAL);
        let local = st.light_model_local_viewer;
        let separate = st.light_model_color_control == GL_SEPARATE_SPECULAR_COLOR;
        // Material colors, with color material substituting gl_Color.
        let mat = |face: &str, which: &str, back: bool| -> String {
            let tracked = cm && {
                let f = st.color_material_face;
                let face_ok = f == GL_FRONT_AND_BACK || (f == GL_BACK) == back;
                let mode = st.color_material_mode;
                face_ok
                    && match which {
                        "ambient" => mode == GL_AMBIENT || mode == GL_AMBIENT_AND_DIFFUSE,
                        "diffuse" => mode == GL_DIFFUSE || mode == GL_AMBIENT_AND_DIFFUSE,
                        "specular" => mode == GL_SPECULAR,
                        _ => mode == GL_EMISSION,
                    }
            };
            if tracked {
                "gl_Color".into()
            } else {
                format!("gl_{face}Material.{which}")
            }
        };
        s.push_str("vec4 ff_light(vec3 n, vec4 ecPos, bool back, out vec4 sec)\n{\n");
        for (back, face) in [(false, "Front"), (true, "Back")] {
            let _ = writeln!(
                s,
                "    vec4 em{face} = {}; vec4 am{face} = {}; vec4 dm{face} = {}; vec4 sm{face} = {}; float sh{face} = gl_{face}Material.shininess;",
                mat(face, "emission", back),
                mat(face, "ambient", back),
                mat(face, "diffuse", back),
                mat(face, "specular", back),
            );
        }
        s.push_str(
            "    vec4 em = back ? emBack : emFront;\n    vec4 am = back ? amBack : amFront;\n    vec4 dm = back ? dmBack : dmFront;\n    vec4 sm = back ? smBack : smFront;\n    float shininess = back ? shBack : shFront;\n",
        );
        s.push_str("    vec3 c = em.rgb + am.rgb * gl_LightModel.ambient.rgb;\n");
        s.push_str("    vec3 spec = vec3(0.0);\n");
        s.push_str("    vec3 V = ecPos.xyz / ecPos.w;\n");
        for &i in lights {
            let l = format!("gl_LightSource[{i}]");
            let _ = write!(
                s,
                "    {{
        vec3 VP;
        float att = 1.0;
        if ({l}.position.w != 0.0) {{
            vec3 d = {l}.position.xyz / {l}.position.w - V;
            float dist = length(d);
            VP = normalize(d);
            att = 1.0 / ({l}.constantAttenuation + {l}.linearAttenuation * dist + {l}.quadraticAttenuation * dist * dist);
        }} else {{
            VP = normalize({l}.position.xyz);
        }}
        if ({l}.spotCutoff != 180.0) {{
            float sd = dot(-VP, normalize({l}.spotDirection));
            att *= sd >= {l}.spotCosCutoff ? pow(max(sd, 0.0), {l}.spotExponent) : 0.0;
        }}
        float nDotVP = max(dot(n, VP), 0.0);
        vec3 h = VP + {eye};
        float nDotH = max(dot(n, normalize(h)), 0.0);
        float f = nDotVP > 0.0 ? 1.0 : 0.0;
        float specPow = nDotH > 0.0 ? pow(nDotH, shininess) : (shininess == 0.0 ? 1.0 : 0.0);
        c += att * (am.rgb * {l}.ambient.rgb + nDotVP * dm.rgb * {l}.diffuse.rgb);
        spec += att * f * specPow * sm.rgb * {l}.specular.rgb;
    }}
",
                eye = if local {
                    "normalize(-V)"
                } else {
                    "vec3(0.0, 0.0, 1.0)"
                },
            );
        }
        if separate {
            s.push_str("    sec = vec4(spec, 0.0);\n    return vec4(c, dm.a);\n}\n");
        } else {
            s.push_str("    sec = vec4(0.0);\n    return vec4(c + spec, dm.a);\n}\n");
        }
    }

    /// The base format of the texture a unit samples (for Table 3.22).
    fn unit_base_format(&self, unit: usize, target: u32) -> u32 {
        self.objects
            .bound_texture(unit, target)
            .and_then(|t| t.base_image())
            .and_then(|i| base_format(i.internal_format as i32))
            .unwrap_or(GL_RGBA)
    }

    /// The shape of the fixed-function fragment stage for the current
    /// state: what [`fragment_source`] writes and
    /// [`crate::ff_fragment::FixedFragment`] runs. `vertex_fixed` tells
    /// whether the vertex stage is fixed function too (color sum then
    /// also applies with separate specular lighting).
    pub fn ff_fragment_shape(&self, vertex_fixed: bool) -> FragmentShape {
        let st = &self.st;
        let mut units = Vec::new();
        for u in 0..crate::MAX_TEXTURE_UNITS {
            let Some(target) = enabled_target(self, u as u32) else {
                continue;
            };
            let base = self.unit_base_format(u, target);
            let shadow = base == GL_DEPTH_COMPONENT
                && self
                    .objects
                    .bound_texture(u, target)
                    .is_some_and(|t| t.params.compare_mode == GL_COMPARE_R_TO_TEXTURE)
                && matches!(target, GL_TEXTURE_1D | GL_TEXTURE_2D);
            let lookup = match (target, shadow) {
                (GL_TEXTURE_1D, true) => Lookup::Shadow1DProj,
                (_, true) => Lookup::Shadow2DProj,
                (GL_TEXTURE_1D, _) => Lookup::Texture1DProj,
                (GL_TEXTURE_3D, _) => Lookup::Texture3DProj,
                (GL_TEXTURE_CUBE_MAP, _) => Lookup::TextureCube,
                _ => Lookup::Texture2DProj,
            };
            // Table 3.22: what each base format contributes.
            let has_color = base != GL_ALPHA;
            let has_alpha = matches!(base, GL_ALPHA | GL_LUMINANCE_ALPHA | GL_INTENSITY | GL_RGBA);
            let intensity = base == GL_INTENSITY;
            use {AlphaOp as A, RgbOp as C};
            let (rgb, alpha) = match st.tex_env[u].mode {
                GL_REPLACE => (
                    if has_color { C::Texture } else { C::Color },
                    if has_alpha { A::Texture } else { A::Color },
                ),
                GL_DECAL => match base {
                    GL_RGB => (C::Texture, A::Color),
                    GL_RGBA => (C::MixByTextureAlpha, A::Color),
                    _ => (C::Color, A::Color),
                },
                GL_BLEND => (
                    if has_color { C::BlendEnv } else { C::Color },
                    if intensity {
                        A::BlendEnv
                    } else if has_alpha {
                        A::Modulate
                    } else {
                        A::Color
                    },
                ),
                GL_ADD => (
                    if has_color { C::Add } else { C::Color },
                    if intensity {
                        A::Add
                    } else if has_alpha {
                        A::Modulate
                    } else {
                        A::Color
                    },
                ),
                // MODULATE (and COMBINE, not implemented).
                _ => (
                    if has_color { C::Modulate } else { C::Color },
                    if has_alpha { A::Modulate } else { A::Color },
                ),
            };
            units.push(UnitShape {
                unit: u,
                lookup,
                rgb,
                alpha,
            });
        }
        let separate = st.is_on(GL_LIGHTING)
            && st.light_model_color_control == GL_SEPARATE_SPECULAR_COLOR
            && vertex_fixed;
        let fog = st.is_on(GL_FOG).then_some(match st.fog.mode {
            GL_LINEAR => FogMode::Linear,
            GL_EXP2 => FogMode::Exp2,
            _ => FogMode::Exp,
        });
        FragmentShape {
            units,
            color_sum: st.is_on(GL_COLOR_SUM) || separate,
            fog,
        }
    }

    /// The fixed-function fragment shader for the current state (see
    /// [`Context::ff_fragment_shape`]).
    pub fn ff_fragment_source(&self, vertex_fixed: bool) -> String {
        fragment_source(&self.ff_fragment_shape(vertex_fixed))
    }
}

/// The shape of a fixed-function fragment stage (GL 2.1 §3.8.13–§3.10):
/// the enabled texture units in order, color sum, fog.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FragmentShape {
    pub units: Vec<UnitShape>,
    pub color_sum: bool,
    pub fog: Option<FogMode>,
}

/// One enabled texture unit of a [`FragmentShape`]: its lookup and its
/// texture environment's RGB and alpha functions (Table 3.22 for the
/// mode and the texture's base format).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UnitShape {
    pub unit: usize,
    pub lookup: Lookup,
    pub rgb: RgbOp,
    pub alpha: AlphaOp,
}

/// The lookup of a fixed-function texture unit (projective, from
/// `gl_TexCoord[unit]`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lookup {
    Texture1DProj,
    Texture2DProj,
    Texture3DProj,
    TextureCube,
    Shadow1DProj,
    Shadow2DProj,
}

/// The RGB of a texture environment: of the colour so far `c`, the
/// texel `t` and the environment colour `e`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RgbOp {
    /// c
    Color,
    /// t
    Texture,
    /// c · t
    Modulate,
    /// mix(c, t, t.a)
    MixByTextureAlpha,
    /// mix(c, e, t)
    BlendEnv,
    /// c + t
    Add,
}

/// The alpha of a texture environment (see [`RgbOp`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlphaOp {
    /// c.a
    Color,
    /// t.a
    Texture,
    /// c.a · t.a
    Modulate,
    /// mix(c.a, e.a, t.a)
    BlendEnv,
    /// c.a + t.a
    Add,
}

/// The fog equation of GL 2.1 §3.10.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FogMode {
    Linear,
    Exp,
    Exp2,
}

/// The GLSL of a fixed-function fragment stage of shape `shape`.
pub fn fragment_source(shape: &FragmentShape) -> String {
    let mut decls = String::from("// fixed-function fragment processing\n");
    let mut body = String::from("void main()\n{\n    vec4 c = gl_Color;\n");
    for unit in &shape.units {
        let u = unit.unit;
        let name = sampler_name(u);
        let (sampler, lookup) = match unit.lookup {
            Lookup::Texture1DProj => (
                "sampler1D",
                format!("texture1DProj({name}, gl_TexCoord[{u}].sq)"),
            ),
            Lookup::Texture2DProj => (
                "sampler2D",
                format!("texture2DProj({name}, gl_TexCoord[{u}])"),
            ),
            Lookup::Texture3DProj => (
                "sampler3D",
                format!("texture3DProj({name}, gl_TexCoord[{u}])"),
            ),
            Lookup::TextureCube => (
                "samplerCube",
                format!("textureCube({name}, gl_TexCoord[{u}].stp)"),
            ),
            Lookup::Shadow1DProj => (
                "sampler1DShadow",
                format!("shadow1DProj({name}, gl_TexCoord[{u}])"),
            ),
            Lookup::Shadow2DProj => (
                "sampler2DShadow",
                format!("shadow2DProj({name}, gl_TexCoord[{u}])"),
            ),
        };
        let _ = writeln!(decls, "uniform {sampler} {name};");
        let _ = writeln!(body, "    {{\n        vec4 t = {lookup};");
        let env = format!("gl_TextureEnvColor[{u}]");
        let rgb = match unit.rgb {
            RgbOp::Color => "c.rgb".to_string(),
            RgbOp::Texture => "t.rgb".to_string(),
            RgbOp::Modulate => "c.rgb * t.rgb".to_string(),
            RgbOp::MixByTextureAlpha => "mix(c.rgb, t.rgb, t.a)".to_string(),
            RgbOp::BlendEnv => format!("mix(c.rgb, {env}.rgb, t.rgb)"),
            RgbOp::Add => "c.rgb + t.rgb".to_string(),
        };
        let a = match unit.alpha {
            AlphaOp::Color => "c.a".to_string(),
            AlphaOp::Texture => "t.a".to_string(),
            AlphaOp::Modulate => "c.a * t.a".to_string(),
            AlphaOp::BlendEnv => format!("mix(c.a, {env}.a, t.a)"),
            AlphaOp::Add => "c.a + t.a".to_string(),
        };
        let _ = writeln!(
            body,
            "        c = clamp(vec4({rgb}, {a}), 0.0, 1.0);\n    }}"
        );
    }
    if shape.color_sum {
        body.push_str("    c.rgb = clamp(c.rgb + gl_SecondaryColor.rgb, 0.0, 1.0);\n");
    }
    if let Some(mode) = shape.fog {
        let f = match mode {
            FogMode::Linear => "(gl_Fog.end - z) * gl_Fog.scale",
            FogMode::Exp2 => "exp(-(gl_Fog.density * z) * (gl_Fog.density * z))",
            FogMode::Exp => "exp(-gl_Fog.density * z)",
        };
        let _ = writeln!(
            body,
            "    float z = gl_FogFragCoord;\n    float f = clamp({f}, 0.0, 1.0);\n    c.rgb = mix(gl_Fog.color.rgb, c.rgb, f);"
        );
    }
    body.push_str("    gl_FragColor = c;\n}\n");
    decls + &body
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::param::Param;
    use glsl::{compile, CompileOptions, Stage};

    fn compiles(src: &str, stage: Stage) {
        let sh = compile(&[src], &CompileOptions::new(stage));
        assert!(sh.ok(), "{}\n{src}", sh.info_log());
    }

    #[test]
    fn default_state_sources_compile() {
        let ctx = Context::new(4, 4);
        let vs = ctx.ff_vertex_source(0);
        assert!(vs.contains("ftransform()"));
        assert!(!vs.contains("ff_light"));
        compiles(&vs, Stage::Vertex);
        let fs = ctx.ff_fragment_source(true);
        assert!(fs.contains("gl_FragColor = c"));
        compiles(&fs, Stage::Fragment);
    }

    #[test]
    fn full_state_sources_compile() {
        let mut ctx = Context::new(4, 4);
        ctx.enable(GL_LIGHTING);
        ctx.enable(GL_LIGHT0);
        ctx.enable(GL_LIGHT3);
        ctx.enable(GL_COLOR_MATERIAL);
        ctx.enable(GL_NORMALIZE);
        ctx.enable(GL_FOG);
        ctx.enable(GL_CLIP_PLANE2);
        ctx.enable(GL_COLOR_SUM);
        ctx.light_model(GL_LIGHT_MODEL_TWO_SIDE, Param::I(1));
        ctx.light_model(GL_LIGHT_MODEL_LOCAL_VIEWER, Param::I(1));
        ctx.light_model(
            GL_LIGHT_MODEL_COLOR_CONTROL,
            Param::I(GL_SEPARATE_SPECULAR_COLOR as i32),
        );
        ctx.fog(GL_FOG_MODE, Param::I(GL_LINEAR as i32));
        let mut modes = [GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD].iter();
        for (u, target) in [
            GL_TEXTURE_2D,
            GL_TEXTURE_1D,
            GL_TEXTURE_3D,
            GL_TEXTURE_CUBE_MAP,
            GL_TEXTURE_2D,
        ]
        .iter()
        .enumerate()
        {
            ctx.active_texture(GL_TEXTURE0 + u as u32);
            ctx.enable(*target);
            ctx.tex_env(
                GL_TEXTURE_ENV,
                GL_TEXTURE_ENV_MODE,
                Param::I(*modes.next().unwrap() as i32),
            );
            ctx.enable(GL_TEXTURE_GEN_S);
            ctx.enable(GL_TEXTURE_GEN_T);
            let mode = [
                GL_OBJECT_LINEAR,
                GL_EYE_LINEAR,
                GL_SPHERE_MAP,
                GL_REFLECTION_MAP,
                GL_NORMAL_MAP,
            ][u];
            ctx.tex_gen(GL_S, GL_TEXTURE_GEN_MODE, Param::I(mode as i32));
            ctx.tex_gen(GL_T, GL_TEXTURE_GEN_MODE, Param::I(mode as i32));
        }
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.ff_texcoord_count(), 5);
        let vs = ctx.ff_vertex_source(ctx.ff_texcoord_count());
        assert!(vs.contains("gl_LightSource[3]"));
        assert!(!vs.contains("gl_LightSource[1]"));
        assert!(vs.contains("gl_ClipVertex"));
        compiles(&vs, Stage::Vertex);
        let fs = ctx.ff_fragment_source(true);
        assert!(fs.contains("uniform samplerCube ff_sampler3;"));
        compiles(&fs, Stage::Fragment);
    }

    #[test]
    fn table_3_22_by_base_format() {
        let mut ctx = Context::new(4, 4);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, t);
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_ALPHA as i32,
            [1, 1],
            0,
            GL_ALPHA,
            GL_UNSIGNED_BYTE,
            Some(&[128]),
        );
        ctx.enable(GL_TEXTURE_2D);
        let fs = ctx.ff_fragment_source(true);
        // MODULATE with an ALPHA texture keeps the fragment color.
        assert!(fs.contains("vec4(c.rgb, c.a * t.a)"), "{fs}");
        ctx.tex_env(
            GL_TEXTURE_ENV,
            GL_TEXTURE_ENV_MODE,
            Param::I(GL_REPLACE as i32),
        );
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_RGB as i32,
            [1, 1],
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&[1, 2, 3]),
        );
        let fs = ctx.ff_fragment_source(true);
        assert!(fs.contains("vec4(t.rgb, c.a)"), "{fs}");
        assert_eq!(sampler_unit(&sampler_name(5)), Some(5));
    }
}
