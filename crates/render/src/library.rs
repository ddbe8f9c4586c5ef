//! The shader library (`shaders/`): every program it holds, as the files
//! that make it up, embedded in the binary.
//!
//! A program is one vertex and one fragment stage, each of one or more
//! shader objects (seed 003's library objects link a main with a library
//! file). [`PROGRAMS`] lists them in the order of `shaders/README.md`;
//! [`build`] compiles and links one on a [`gl::Context`].

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
    ONE_SIDED_LIGHTING_FRAG = "one-sided-lighting.frag";
    OUTLINE_FRAG = "outline.frag";
    PHONG_LIGHTING_LIB_FRAG = "phong-lighting-lib.frag";
    SINGLE_TEXTURE_FRAG = "single-texture.frag";
    SPHERE_FRAG = "sphere.frag";
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
    WIREFRAME_FRAG = "wireframe.frag";
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
    /// A mesh whose vertices carry their whole triangle (wireframe).
    WireMesh,
    /// A textured quad (texture units 0 and 1).
    TexturedQuad,
    /// The unit cube with a 3D texture.
    Volume,
}

/// One program of the library.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Program {
    /// Short name (gallery file names, `--program`).
    pub name: &'static str,
    pub vertex: &'static [ShaderFile],
    pub fragment: &'static [ShaderFile],
    /// One line: what it draws.
    pub summary: &'static str,
    pub scene: SceneKind,
}

/// Sphere impostors (the plain effect, spacefill and ball-and-stick atoms).
pub const SPHERE: Program = Program {
    name: "sphere",
    vertex: &[SPHERE_VERT],
    fragment: &[SPHERE_FRAG],
    summary: "sphere impostors: ray-cast, true depth, lights, fog (seed 000, example 03)",
    scene: SceneKind::Molecule,
};

/// Cylinder impostors (ball-and-stick bonds).
pub const CYLINDER: Program = Program {
    name: "cylinder",
    vertex: &[CYLINDER_VERT],
    fragment: &[CYLINDER_FRAG],
    summary: "cylinder impostors for bonds: ray-cast, true depth (ball-and-stick)",
    scene: SceneKind::BallAndStick,
};

/// Every program of the library.
pub const PROGRAMS: &[Program] = &[
    Program {
        name: "trivial",
        vertex: &[TRIVIAL_VERT],
        fragment: &[TRIVIAL_FRAG],
        summary: "unlit vertex colour (seed 000, example 01)",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "materials",
        vertex: &[MATERIALS_VERT],
        fragment: &[MATERIALS_FRAG],
        summary:
            "per-pixel Blinn-Phong of lights 0 and 1 with the front material (seed 000, example 02)",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "variable-lights",
        vertex: &[MATERIALS_VERT],
        fragment: &[VARIABLE_LIGHTS_FRAG],
        summary: "materials with lights 0-7 switched by light_enabled[8] (seed 000)",
        scene: SceneKind::Mesh,
    },
    SPHERE,
    Program {
        name: "outline",
        vertex: &[SPHERE_VERT],
        fragment: &[OUTLINE_FRAG],
        summary: "black sphere interiors, lit rims (seed 000)",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "x",
        vertex: &[X_VERT],
        fragment: &[X_FRAG],
        summary: "a dark X on every atom (seed 000)",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "x-red",
        vertex: &[X_VERT],
        fragment: &[X_RED_FRAG],
        summary: "a yellow X on red atoms (seed 000)",
        scene: SceneKind::Molecule,
    },
    Program {
        name: "transparent",
        vertex: &[SPHERE_VERT],
        fragment: &[TRANSPARENT_FRAG],
        summary: "screen-door transparency of red atoms (seed 000)",
        scene: SceneKind::Molecule,
    },
    CYLINDER,
    Program {
        name: "single-texture",
        vertex: &[TEXTURING_VERT],
        fragment: &[SINGLE_TEXTURE_FRAG, TEXTURING_LIB_FRAG],
        summary: "one texture combined by a GL texture environment mode (seed 003)",
        scene: SceneKind::TexturedQuad,
    },
    Program {
        name: "multi-texture",
        vertex: &[TEXTURING_VERT],
        fragment: &[MULTI_TEXTURE_FRAG, TEXTURING_LIB_FRAG],
        summary: "two textures, each with its own environment mode (seed 003)",
        scene: SceneKind::TexturedQuad,
    },
    Program {
        name: "one-sided-lighting",
        vertex: &[LIGHTING_VERT],
        fragment: &[ONE_SIDED_LIGHTING_FRAG, PHONG_LIGHTING_LIB_FRAG],
        summary: "per-pixel Phong: directional, point and spot lights, front material (seed 003)",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "two-sided-lighting",
        vertex: &[LIGHTING_VERT],
        fragment: &[TWO_SIDED_LIGHTING_FRAG, PHONG_LIGHTING_LIB_FRAG],
        summary: "per-pixel Phong of both faces, back material on back faces (seed 003)",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "toon",
        vertex: &[LIGHTING_VERT],
        fragment: &[TOON_FRAG],
        summary: "cel shading in four bands of light 0",
        scene: SceneKind::Mesh,
    },
    Program {
        name: "wireframe",
        vertex: &[WIREFRAME_VERT],
        fragment: &[WIREFRAME_FRAG],
        summary: "single-pass wireframe over lit triangles (seed 004)",
        scene: SceneKind::WireMesh,
    },
    Program {
        name: "volume",
        vertex: &[VOLUME_VERT],
        fragment: &[VOLUME_FRAG],
        summary: "volume ray casting through a 3D texture (seed 004)",
        scene: SceneKind::Volume,
    },
];

/// The program called `name`.
pub fn program(name: &str) -> Option<&'static Program> {
    PROGRAMS.iter().find(|p| p.name == name)
}

/// Compiles every object of `p` and links them on `ctx`; the error names
/// the file whose compile failed, or carries the link log.
pub fn build(ctx: &mut Context, p: &Program) -> Result<u32, String> {
    let mut objects = Vec::new();
    for (kind, files) in [
        (GL_VERTEX_SHADER, p.vertex),
        (GL_FRAGMENT_SHADER, p.fragment),
    ] {
        for f in files {
            objects.push((kind, f.name.to_string(), f.source));
        }
    }
    build_objects(ctx, p.name, &objects)
}

/// Compiles shader objects `(kind, name for errors, source)` and links
/// them into a program called `name` in errors.
pub fn build_objects(
    ctx: &mut Context,
    name: &str,
    objects: &[(u32, String, &str)],
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
        for p in PROGRAMS {
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
            .filter(|n| n.ends_with(".vert") || n.ends_with(".frag"))
            .collect();
        on_disk.sort();
        let listed: Vec<&str> = FILES.iter().map(|f| f.name).collect();
        assert_eq!(on_disk, listed, "FILES must list shaders/ exactly");
        for f in FILES {
            let used = PROGRAMS
                .iter()
                .any(|p| p.vertex.contains(f) || p.fragment.contains(f));
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
        for (i, p) in PROGRAMS.iter().enumerate() {
            assert_eq!(program(p.name), Some(&PROGRAMS[i]));
        }
    }
}
