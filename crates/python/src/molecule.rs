//! `shaderbox.render_molecule` and `shaderbox.MoleculeRenderer`: the
//! options of `shaderbox render` (the CLI) by name, checked, then a
//! [`render::Renderer`] (a fresh one per call for `render_molecule`, one
//! kept across calls for `MoleculeRenderer`).

use render::{Atoms, Background, Effect, Fog, Projection, RenderOptions, Renderer, Style};
use std::path::Path;

/// The options as Python passes them (already typed; names checked here).
#[derive(Clone, Debug, PartialEq)]
pub struct MoleculeArgs<'a> {
    pub width: u32,
    pub height: u32,
    pub projection: &'a str,
    pub fog: &'a str,
    pub lights: Vec<u8>,
    pub rotate: [f32; 3],
    pub supersample: u32,
    /// `None`: transparent.
    pub background: Option<[f32; 3]>,
    pub effect: &'a str,
    /// "spacefill" or "ballstick", as `shaderbox render --style`.
    pub style: &'a str,
    /// "quads" or "points", as `shaderbox render --atoms`.
    pub atoms: &'a str,
}

/// Why `render_molecule` failed; the kinds become Python exceptions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MoleculeError {
    /// A bad option (ValueError).
    Option(String),
    /// The file could not be read (OSError).
    Io(String),
    /// The file is not a usable structure, or rendering failed.
    Failed(String),
}

/// Checks the option names and builds [`RenderOptions`].
pub fn options(a: &MoleculeArgs) -> Result<RenderOptions, MoleculeError> {
    let projection = match a.projection {
        "ortho" | "orthographic" => Projection::Orthographic,
        "perspective" => Projection::Perspective,
        other => {
            return Err(MoleculeError::Option(format!(
                "projection {other:?} is not one of: ortho, perspective"
            )))
        }
    };
    let fog = match a.fog {
        "none" => Fog::None,
        "linear" => Fog::Linear,
        "exp" => Fog::Exp,
        "exp2" => Fog::Exp2,
        other => {
            return Err(MoleculeError::Option(format!(
                "fog {other:?} is not one of: none, linear, exp, exp2"
            )))
        }
    };
    let style = match a.style {
        "spacefill" => Style::Spacefill,
        "ballstick" => Style::BallAndStick,
        other => {
            return Err(MoleculeError::Option(format!(
                "style {other:?} is not one of: spacefill, ballstick"
            )))
        }
    };
    let effect = Effect::from_name(a.effect).ok_or_else(|| {
        let names: Vec<&str> = Effect::ALL.iter().map(|e| e.name()).collect();
        MoleculeError::Option(format!(
            "effect {:?} is not one of: {}",
            a.effect,
            names.join(", ")
        ))
    })?;
    let atoms = Atoms::from_name(a.atoms).ok_or_else(|| {
        let names: Vec<&str> = Atoms::ALL.iter().map(|a| a.name()).collect();
        MoleculeError::Option(format!(
            "atoms {:?} is not one of: {}",
            a.atoms,
            names.join(", ")
        ))
    })?;
    if a.rotate.iter().any(|r| !r.is_finite()) {
        return Err(MoleculeError::Option(format!(
            "rotate {:?} must be three finite angles in degrees",
            a.rotate
        )));
    }
    if let Some(c) = a.background {
        if c.iter().any(|v| !(0.0..=1.0).contains(v)) {
            return Err(MoleculeError::Option(format!(
                "background {c:?} must be RGB values in 0-1"
            )));
        }
    }
    let mut lights = Vec::new();
    for l in &a.lights {
        if !lights.contains(l) {
            lights.push(*l);
        }
    }
    Ok(RenderOptions {
        width: a.width,
        height: a.height,
        projection,
        fog,
        lights,
        rotate: a.rotate,
        supersample: a.supersample,
        background: a
            .background
            .map_or(Background::Transparent, Background::Color),
        effect,
        style,
        atoms,
    })
}

/// Where the structure comes from.
#[derive(Clone, Copy, Debug)]
pub enum Source<'a> {
    /// Crambin, embedded.
    Crambin,
    /// A PDB or mmCIF file.
    File(&'a Path),
    /// PDB or mmCIF text, and the name errors give it.
    Text(&'a [u8], &'a str),
}

/// Loads the structure and renders it with `renderer`.
pub fn render_molecule(
    renderer: &mut Renderer,
    source: Source,
    args: &MoleculeArgs,
) -> Result<render::Image, MoleculeError> {
    let opts = options(args)?;
    let loaded = match source {
        Source::Crambin => Ok(render::crambin()),
        Source::File(p) => render::load_file(p),
        Source::Text(bytes, name) => render::parse(bytes, name),
    };
    let structure = match loaded {
        Ok(s) => s,
        Err(e @ render::LoadError::Io { .. }) => {
            return Err(MoleculeError::Io(format!("cannot read {e}")))
        }
        Err(e) => return Err(MoleculeError::Failed(e.to_string())),
    };
    renderer.render(&structure, &opts).map_err(|e| match e {
        render::RenderError::Size { .. }
        | render::RenderError::Supersample { .. }
        | render::RenderError::Light(_) => MoleculeError::Option(e.to_string()),
        other => MoleculeError::Failed(format!("{}: {other}", structure.source)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args() -> MoleculeArgs<'static> {
        MoleculeArgs {
            width: 24,
            height: 16,
            projection: "ortho",
            fog: "none",
            lights: vec![0, 1],
            rotate: [0.0; 3],
            supersample: 1,
            background: Some([0.0; 3]),
            effect: "plain",
            style: "spacefill",
            atoms: "quads",
        }
    }

    #[test]
    fn names_are_checked() {
        assert!(options(&args()).is_ok());
        for bad in [
            MoleculeArgs {
                projection: "fisheye",
                ..args()
            },
            MoleculeArgs {
                fog: "smog",
                ..args()
            },
            MoleculeArgs {
                effect: "sepia",
                ..args()
            },
            MoleculeArgs {
                style: "wireframe",
                ..args()
            },
            MoleculeArgs {
                atoms: "lines",
                ..args()
            },
            MoleculeArgs {
                rotate: [f32::NAN, 0.0, 0.0],
                ..args()
            },
            MoleculeArgs {
                background: Some([2.0, 0.0, 0.0]),
                ..args()
            },
        ] {
            assert!(
                matches!(options(&bad), Err(MoleculeError::Option(_))),
                "{bad:?}"
            );
        }
    }

    #[test]
    fn renders_crambin_and_reports_bad_sizes_and_files() {
        let r = &mut Renderer::new();
        let img = render_molecule(r, Source::Crambin, &args()).expect("renders");
        assert_eq!((img.width, img.height), (24, 16));
        assert!(img.pixels.iter().any(|p| p[..3] != [0, 0, 0]));
        let big = MoleculeArgs {
            lights: vec![9],
            ..args()
        };
        assert!(matches!(
            render_molecule(r, Source::Crambin, &big),
            Err(MoleculeError::Option(_))
        ));
        let missing = render_molecule(r, Source::File(Path::new("/nonexistent/x.pdb")), &args());
        assert!(matches!(missing, Err(MoleculeError::Io(_))), "{missing:?}");
        let bad = render_molecule(r, Source::Text(b"ATOM  garbage", "bad.pdb"), &args());
        assert!(
            matches!(&bad, Err(MoleculeError::Failed(m)) if m.contains("bad.pdb")),
            "{bad:?}"
        );
    }

    #[test]
    fn text_renders_as_the_file_does() {
        let r = &mut Renderer::new();
        let text = render::load::CRAMBIN_PDB.as_bytes();
        let from_text = render_molecule(r, Source::Text(text, "1crn.pdb"), &args());
        let embedded = render_molecule(r, Source::Crambin, &args());
        assert_eq!(from_text.unwrap().pixels, embedded.unwrap().pixels);
    }
}
