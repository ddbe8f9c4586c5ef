//! The shader library (`shaders/`): every program it holds, as the files
//! that make it up, embedded in the binary.
//!
//! A program is one vertex and one fragment stage, each of one or more
//! shader objects (seed 003's library objects link a main with a library
//! file), and optionally a geometry stage ([`Geometry`]: GLSL 1.20 with
//! GL_EXT_geometry_shader4, whose primitive types and output vertex count
//! are program parameters set before linking). [`PROGRAMS`] lists them in
//! the order of `shaders/README.md`; [`build`] compiles and links one on a
//! [`gl::Context`] (a 2.1 or compatibility context for a geometry stage).

use gl::enums::*;
use gl::Context;

/// One file of `shaders/`: its name and text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShaderFile {
    pub name: &'static str,
    pub source: &'static str,
}

macro_rules! shader_files {
    ($($id:ident = $name:literal;)*) => {
        $(
            #[doc = concat!("`shaders/", $name, "`.")]
            pub const $id: ShaderFile = ShaderFile {
                name: $name,
                source: include_str!(concat!("../../../shaders/", $name)),
            };
        )*
        /// Every file of `shaders/`, sorted by name (bytewise).
        pub const FILES: &[ShaderFile] = &[$($id),*];
    };
}

shader_files! {
    CYLINDER_FRAG = "cylinder.frag";
    CYLINDER_VERT = "cylinder.vert";
    LIGHTING_VERT = "lighting.vert";
    MATERIALS_FRAG = "materials.frag";
    MATERIALS_VERT = "materials.vert";
    MULTI_TEXTURE_FRAG = "multi-texture.frag";
    NORMALS_GEOM = "normals.geom";
    NORMALS_VERT = "normals.vert";
    ONE_SIDED_LIGHTING_FRAG = "one-sided-lighting.frag";
    OUTLINE_FRAG = "outline.frag";
    PHONG_LIGHTING_LIB_FRAG = "phong-lighting-lib.frag";
    SINGLE_TEXTURE_FRAG = "single-texture.frag";
    SPHERE_POINT_VERT = "sphere-point.vert";
    SPHERE_FRAG = "sphere.frag";
    SPHERE_GEOM = "sphere.geom";
    SPHERE_VERT = "sphere.vert";
    TEXTURING_LIB_FRAG = "texturing-lib.frag";
    TEXTURING_VERT = "texturing.vert";
    TOON_FRAG = "toon.frag";
    TRANSPARENT_FRAG = "transparent.frag";
    TRIVIAL_FRAG = "trivial.frag";
    TRIVIAL_VERT = "trivial.vert";
    TWO_SIDED_LIGHTING_FRAG = "two-sided-lighting.frag";
    VARIABLE_LIGHTS_FRAG = "variable-lights.frag";
    VOLUME_FRAG = "volume.frag";
    VOLUME_VERT = "volume.vert";
    WIREFRAME_GEOM_VERT = "wireframe-geom.vert";
    WIREFRAME_FRAG = "wireframe.frag";
    WIREFRAME_GEOM = "wireframe.geom";
    WIREFRAME_VERT = "wireframe.vert";
    X_RED_FRAG = "x-red.frag";
    X_FRAG = "x.frag";
    X_VERT = "x.vert";
}

/// What kind of scene a program draws (what the gallery shows it on).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneKind {
    /// Atoms as sphere impostors (`render`'s spacefill).
    Molecule,
    /// Bonds as cylinder impostors between sphere impostors.
    BallAndStick,
    /// A lit triangle mesh with normals and colours.
    Mesh,
    /// A coarser mesh for a wireframe, with the `viewport`, `line_width`
    /// and `line_color` uniforms; without a geometry stage each vertex
    /// carries its whole triangle in texture coordinates 0-2.
    WireMesh,
    /// The lit mesh (the materials program), then this program's lines
    /// over it (`normal_length`, `root_color`, `tip_color`).
    Normals,
    /// A textured quad (texture units 0 and 1).
    TexturedQuad,
    /// The unit cube with a 3D texture.
    Volume,
}

/// The geometry stage of a program: its shader objects (the
/// GL_EXT_geometry_shader4 form) and the program parameters
/// glProgramParameteriEXT sets before the link.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Geometry {
    pub files: &'static [ShaderFile],
    /// GL_GEOMETRY_INPUT_TYPE_EXT: GL_POINTS, GL_LINES, GL_TRIANGLES...
    pub input: u32,
    /// GL_GEOMETRY_OUTPUT_TYPE_EXT: GL_POINTS, GL_LINE_STRIP or
    /// GL_TRIANGLE_STRIP.
    pub output: u32,
    /// GL_GEOMETRY_VERTICES_OUT_EXT: the most vertices one invocation emits.
    pub vertices_out: i32,
}

impl Geometry {
    /// The program parameters `(pname, value)` in the order they are set.
    pub fn parameters(&self) -> [(u32, i32); 3] {
        [
            (GL_GEOMETRY_INPUT_TYPE_EXT, self.input as i32),
            (GL_GEOMETRY_OUTPUT_TYPE_EXT, self.output as i32),
            (GL_GEOMETRY_VERTICES_OUT_EXT, self.vertices_out),
        ]
    }
}

/// One program of the library.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Program {
    /// Short name (gallery file names, `--program`).
    pub name: &'static str,
    pub vertex: &'static [ShaderFile],
    /// The geometry stage, if the program has one.
    pub geometry: Option<Geometry>,
    pub fragment: &'static [ShaderFile],
    /// One line: what it draws.
    pub summary: &'static str,
    pub scene: SceneKind,
}

/// Sphere impostors (the plain effect, spacefill and ball-and-stick atoms).
pub const SPHERE: Program = Program {
    name: "sphere",
    vertex: &[SPHERE_VERT],
    geometry: None,
    fragment: &[SPHERE_FRAG],
    summary: "sphere impostors: ray-cast, true depth, lights, fog (seed 000, example 03)",
    scene: SceneKind::Molecule,
};

/// sphere.geom's stage: one point in, a 4-vertex triangle strip out.
pub const SPHERE_POINTS_GEOMETRY: Geometry = Geometry {
    files: &[SPHERE_GEOM],
    input: GL_POINTS,
    output: GL_TRIANGLE_STRIP,
    vertices_out: 4,
};

/// Sphere impostors from one point per atom, expanded to the quad by a
/// geometry shader (`shaderbox render --atoms points`).
pub const SPHERE_POINTS: Program = Program {
    name: "sphere-points",
    vertex: &[SPHERE_POINT_VERT],
    geometry: Some(SPHERE_POINTS_GEOMETRY),
    fragment: &[SPHERE_FRAG],
    summary: "sphere impostors from one point per atom: a geometry shader (GL_EXT_geometry_shader4) expands it to the quad",
    scene: SceneKind::Molecule,
};

/// The effects' programs on points (sphere-point.vert + sphere.geom with
/// the effect's fragment shader), for `--atoms points --effect ...`; not
/// in the gallery, which shows the effects once (quads) and
/// [`SPHERE_POINTS`].
pub const POINT_EFFECTS: &[Program] = &[
    Program {
        name: "outline-points",
        vertex: &[SPHERE_POINT_VERT],
        geometry: Some(SPHERE_POINTS_GEOMETRY),
        fragment: &[OUTLINE_FRAG],
        summary: "outline on points expanded by sphere.geom",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "x-points",
        vertex: &[SPHERE_POINT_VERT],
        geometry: Some(SPHERE_POINTS_GEOMETRY),
        fragment: &[X_FRAG],
        summary: "x on points expanded by sphere.geom",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "x-red-points",
        vertex: &[SPHERE_POINT_VERT],
        geometry: Some(SPHERE_POINTS_GEOMETRY),
        fragment: &[X_RED_FRAG],
        summary: "x-red on points expanded by sphere.geom",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "transparent-points",
        vertex: &[SPHERE_POINT_VERT],
        geometry: Some(SPHERE_POINTS_GEOMETRY),
        fragment: &[TRANSPARENT_FRAG],
        summary: "transparent on points expanded by sphere.geom",
        scene: SceneKind::Molecule,
    },
];

/// Cylinder impostors (ball-and-stick bonds).
pub const CYLINDER: Program = Program {
    name: "cylinder",
    vertex: &[CYLINDER_VERT],
    geometry: None,
    fragment: &[CYLINDER_FRAG],
    summary: "cylinder impostors for bonds: ray-cast, true depth (ball-and-stick)",
    scene: SceneKind::BallAndStick,
};

/// Every program of the library.
pub const PROGRAMS: &[Program] = &[
    Program {
        name: "trivial",
        vertex: &[TRIVIAL_VERT],
        geometry: None,
        fragment: &[TRIVIAL_FRAG],
        summary: "unlit vertex colour (seed 000, example 01)",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "materials",
        vertex: &[MATERIALS_VERT],
        geometry: None,
        fragment: &[MATERIALS_FRAG],
        summary:
            "per-pixel Blinn-Phong of lights 0 and 1 with the front material (seed 000, example 02)",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "variable-lights",
        vertex: &[MATERIALS_VERT],
        geometry: None,
        fragment: &[VARIABLE_LIGHTS_FRAG],
        summary: "materials with lights 0-7 switched by light_enabled[8] (seed 000)",
        scene: SceneKind::Mesh,
    },
    SPHERE,
    SPHERE_POINTS,
    Program {
        name: "outline",
        vertex: &[SPHERE_VERT],
        geometry: None,
        fragment: &[OUTLINE_FRAG],
        summary: "black sphere interiors, lit rims (seed 000)",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "x",
        vertex: &[X_VERT],
        geometry: None,
        fragment: &[X_FRAG],
        summary: "a dark X on every atom (seed 000)",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "x-red",
        vertex: &[X_VERT],
        geometry: None,
        fragment: &[X_RED_FRAG],
        summary: "a yellow X on red atoms (seed 000)",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "transparent",
        vertex: &[SPHERE_VERT],
        geometry: None,
        fragment: &[TRANSPARENT_FRAG],
        summary: "screen-door transparency of red atoms (seed 000)",
        scene: SceneKind::Molecule,
    },
    CYLINDER,
    Program {
        name: "single-texture",
        vertex: &[TEXTURING_VERT],
        geometry: None,
        fragment: &[SINGLE_TEXTURE_FRAG, TEXTURING_LIB_FRAG],
        summary: "one texture combined by a GL texture environment mode (seed 003)",
        scene: SceneKind::TexturedQuad,
    },
    Program {
        name: "multi-texture",
        vertex: &[TEXTURING_VERT],
        geometry: None,
        fragment: &[MULTI_TEXTURE_FRAG, TEXTURING_LIB_FRAG],
        summary: "two textures, each with its own environment mode (seed 003)",
        scene: SceneKind::TexturedQuad,
    },
    Program {
        name: "one-sided-lighting",
        vertex: &[LIGHTING_VERT],
        geometry: None,
        fragment: &[ONE_SIDED_LIGHTING_FRAG, PHONG_LIGHTING_LIB_FRAG],
        summary: "per-pixel Phong: directional, point and spot lights, front material (seed 003)",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "two-sided-lighting",
        vertex: &[LIGHTING_VERT],
        geometry: None,
        fragment: &[TWO_SIDED_LIGHTING_FRAG, PHONG_LIGHTING_LIB_FRAG],
        summary: "per-pixel Phong of both faces, back material on back faces (seed 003)",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "toon",
        vertex: &[LIGHTING_VERT],
        geometry: None,
        fragment: &[TOON_FRAG],
        summary: "cel shading in four bands of light 0",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "wireframe",
        vertex: &[WIREFRAME_VERT],
        geometry: None,
        fragment: &[WIREFRAME_FRAG],
        summary: "single-pass wireframe over lit triangles (seed 004)",
        scene: SceneKind::WireMesh,
    },
    Program {
        name: "wireframe-geom",
        vertex: &[WIREFRAME_GEOM_VERT],
        geometry: Some(Geometry {
            files: &[WIREFRAME_GEOM],
            input: GL_TRIANGLES,
            output: GL_TRIANGLE_STRIP,
            vertices_out: 3,
        }),
        fragment: &[WIREFRAME_FRAG],
        summary: "single-pass wireframe, edge distances per triangle in a geometry shader: no corner attributes (seed 004)",
        scene: SceneKind::WireMesh,
    },
    Program {
        name: "normals",
        vertex: &[NORMALS_VERT],
        geometry: Some(Geometry {
            files: &[NORMALS_GEOM],
            input: GL_TRIANGLES,
            output: GL_LINE_STRIP,
            vertices_out: 6,
        }),
        fragment: &[TRIVIAL_FRAG],
        summary: "vertex normals as short lines, drawn by a geometry shader over the lit mesh",
        scene: SceneKind::Normals,
    },
    Program {
        name: "volume",
        vertex: &[VOLUME_VERT],
        geometry: None,
        fragment: &[VOLUME_FRAG],
        summary: "volume ray casting through a 3D texture (seed 004)",
        scene: SceneKind::Volume,
    },
];

/// The program called `name` ([`PROGRAMS`], then [`POINT_EFFECTS`]).
pub fn program(name: &str) -> Option<&'static Program> {
    PROGRAMS
        .iter()
        .chain(POINT_EFFECTS)
        .find(|p| p.name == name)
}

/// Compiles every object of `p` and links them on `ctx`, with the
/// geometry stage's program parameters set first; the error names the
/// file whose compile failed, or carries the link log.
pub fn build(ctx: &mut Context, p: &Program) -> Result<u32, String> {
    let mut objects = Vec::new();
    let geometry = p.geometry.map_or(&[][..], |g| g.files);
    for (kind, files) in [
        (GL_VERTEX_SHADER, p.vertex),
        (GL_GEOMETRY_SHADER_EXT, geometry),
        (GL_FRAGMENT_SHADER, p.fragment),
    ] {
        for f in files {
            objects.push((kind, f.name.to_string(), f.source));
        }
    }
    let params = p.geometry.map(|g| g.parameters());
    build_objects(
        ctx,
        p.name,
        &objects,
        params.as_ref().map_or(&[][..], |a| a),
    )
}

/// Compiles shader objects `(kind, name for errors, source)`, sets the
/// program parameters `(pname, value)` (glProgramParameteriEXT) and links
/// them into a program called `name` in errors. A parameter the context
/// refuses is an error naming it.
pub fn build_objects(
    ctx: &mut Context,
    name: &str,
    objects: &[(u32, String, &str)],
    parameters: &[(u32, i32)],
) -> Result<u32, String> {
    let program = ctx.create_program();
    for (kind, file, source) in objects {
        let sh = ctx.create_shader(*kind);
        ctx.shader_source(sh, &[source]);
        ctx.compile_shader(sh);
        if ctx.get_shaderiv(sh, GL_COMPILE_STATUS) == 0 {
            return Err(format!("{file}: {}", ctx.get_shader_info_log(sh)));
        }
        ctx.attach_shader(program, sh);
    }
    for &(pname, value) in parameters {
        ctx.program_parameteri(program, pname, value);
        let code = ctx.get_error();
        if code != GL_NO_ERROR {
            return Err(format!(
                "{name}: program parameter 0x{pname:04x} = {value} refused (GL error 0x{code:04x})"
            ));
        }
    }
    ctx.link_program(program);
    if ctx.get_programiv(program, GL_LINK_STATUS) == 0 {
        return Err(format!("{name}: {}", ctx.get_program_info_log(program)));
    }
    Ok(program)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_program_builds() {
        for p in PROGRAMS.iter().chain(POINT_EFFECTS) {
            let mut ctx = Context::new(4, 4);
            let built = build(&mut ctx, p);
            assert!(built.is_ok(), "{}: {built:?}", p.name);
        }
    }

    #[test]
    fn every_file_is_listed_and_used() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shaders");
        let mut on_disk: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".vert") || n.ends_with(".geom") || n.ends_with(".frag"))
            .collect();
        on_disk.sort();
        let listed: Vec<&str> = FILES.iter().map(|f| f.name).collect();
        assert_eq!(on_disk, listed, "FILES must list shaders/ exactly");
        for f in FILES {
            let used = PROGRAMS.iter().any(|p| {
                p.vertex.contains(f)
                    || p.fragment.contains(f)
                    || p.geometry.is_some_and(|g| g.files.contains(f))
            });
            assert!(used, "{} is in no program", f.name);
        }
    }

    #[test]
    fn every_file_has_a_header() {
        for f in FILES {
            let first = f.source.lines().next().unwrap_or("");
            assert!(
                first.starts_with(&format!("// {}:", f.name)),
                "{}: first line {first:?}",
                f.name
            );
            assert!(f.source.contains("reads"), "{}: no state listed", f.name);
        }
    }

    #[test]
    fn names_are_unique() {
        let all: Vec<&Program> = PROGRAMS.iter().chain(POINT_EFFECTS).collect();
        for p in &all {
            let same = all.iter().filter(|q| q.name == p.name).count();
            assert_eq!(same, 1, "{}", p.name);
            assert_eq!(program(p.name), Some(*p));
        }
    }

    #[test]
    fn a_refused_parameter_is_an_error() {
        let mut ctx = Context::new(4, 4);
        let objects = [
            (GL_VERTEX_SHADER, "v".to_string(), SPHERE_POINT_VERT.source),
            (GL_GEOMETRY_SHADER_EXT, "g".to_string(), SPHERE_GEOM.source),
            (GL_FRAGMENT_SHADER, "f".to_string(), SPHERE_FRAG.source),
        ];
        let bad = [(GL_GEOMETRY_INPUT_TYPE_EXT, GL_QUADS as i32)];
        let e = build_objects(&mut ctx, "p", &objects, &bad).unwrap_err();
        assert!(e.contains("0x8ddb = 7 refused"), "{e}");
        // Without the parameters the link fails: no vertex count.
        let e = build_objects(&mut ctx, "p", &objects, &[]).unwrap_err();
        assert!(e.starts_with("p: "), "{e}");
    }
}
