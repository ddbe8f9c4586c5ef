//! `shaderbox render`: draw a molecule with the shader library's sphere
//! impostors and write a PNG.
//!
//! With no FILE it draws crambin (PDB 1CRN), embedded in the binary.
//! FILEs are PDB or mmCIF (told apart by content: mmCIF starts `data_`).
//! Default size 800x800 (rendering is on the CPU; `--size 1024x1024` or
//! `--supersample 2` for print quality).
//!
//! One file and no `--turntable`: one PNG, `-o OUT.png`. Several files or
//! `--turntable N` (N frames turning about the screen's vertical axis,
//! 360/N degrees apart, added to `--rotate`'s Y): numbered PNGs
//! `OUT-0001.png`, `OUT-0002.png`, ... (files in the order given, each
//! file's frames in turn), with a progress bar on standard error when it
//! is a terminal. A file that fails to load is reported and skipped; the
//! exit status is then 1.
//!
//! `--export-scene FILE.json` (one image only) also writes every GL call
//! the render made ([`render::Scene`]), for replaying on another OpenGL:
//! `scripts/regen-references.py` replays them on Mesa.
//!
//! Exit status ([`Exit`]): 0 when the PNG was written; 1 when the structure
//! is malformed (the message names the file and line) or has no atoms, or
//! rendering or writing the PNG failed; 2 on misuse (bad arguments,
//! unreadable file); 3 on an internal error (a panic, reported).

use crate::guard::guarded;
use crate::Exit;
use render::{Atoms, Background, Effect, Fog, Projection, RenderOptions, Structure, Style};
use std::path::{Path, PathBuf};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// PDB or mmCIF files to draw (default: crambin, PDB 1CRN, embedded).
    #[arg(value_name = "FILE")]
    pub files: Vec<PathBuf>,

    /// Spacefill (atoms at van der Waals radii) or ball-and-stick (smaller
    /// atoms, bonds as cylinders from CONECT records and distances).
    #[arg(long, value_enum, default_value_t = StyleArg::Spacefill)]
    pub style: StyleArg,

    /// Render N frames turning once around the vertical axis (numbered
    /// PNGs).
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u32).range(1..=3600))]
    pub turntable: Option<u32>,

    /// Also write the GL calls of the render as JSON (one image only).
    #[arg(long, value_name = "FILE.json")]
    pub export_scene: Option<PathBuf>,

    /// Output PNG.
    #[arg(
        short = 'o',
        long = "output",
        value_name = "OUT.png",
        default_value = "molecule.png"
    )]
    pub output: PathBuf,

    /// Image size in pixels.
    #[arg(long, value_name = "WxH", default_value = "800x800", value_parser = parse_size)]
    pub size: (u32, u32),

    /// Camera projection.
    #[arg(long, value_enum, default_value_t = ProjectionArg::Ortho)]
    pub projection: ProjectionArg,

    /// Fog mode (the fixed-function formulas, per atom).
    #[arg(long, value_enum, default_value_t = FogArg::None)]
    pub fog: FogArg,

    /// GL lights that are on, 0-7, comma-separated; `none` for none.
    #[arg(long, value_name = "LIST", default_value = "0,1", value_parser = parse_lights)]
    pub lights: Lights,

    /// Rotation of the molecule about X, then Y, then Z, in degrees.
    #[arg(long, value_name = "X,Y,Z", default_value = "0,0,0", value_parser = parse_rotate,
          allow_hyphen_values = true)]
    pub rotate: Rotation,

    /// Render N times larger and box-filter down (smooth edges), 1-8.
    #[arg(long, value_name = "N", default_value_t = 1,
          value_parser = clap::value_parser!(u32).range(1..=8))]
    pub supersample: u32,

    /// Background: black, white, gray, a #RRGGBB colour, or `transparent`.
    #[arg(long, value_name = "COLOR", default_value = "black", value_parser = parse_background)]
    pub background: BackgroundArg,

    /// Effect of the seed talk: plain spheres, outlines, a dark X on every
    /// atom, a yellow X on red (oxygen) atoms, or red atoms 50% transparent.
    #[arg(long, value_name = "EFFECT", default_value = "plain", value_parser = parse_effect)]
    pub effect: Effect,

    /// How each atom is sent to GL: `quads` (four vertices, the corner in
    /// a texture coordinate) or `points` (one vertex, expanded to the same
    /// quad by a geometry shader, GL_EXT_geometry_shader4). Same image.
    #[arg(long, value_name = "ATOMS", default_value = "quads", value_parser = parse_atoms)]
    pub atoms: Atoms,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum StyleArg {
    Spacefill,
    Ballstick,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProjectionArg {
    Ortho,
    Perspective,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FogArg {
    None,
    Linear,
    Exp,
    Exp2,
}

/// Parsed `--lights`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lights(pub Vec<u8>);

/// Parsed `--rotate`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rotation(pub [f32; 3]);

/// Parsed `--background`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BackgroundArg(pub Background);

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("`{s}` is not WIDTHxHEIGHT (e.g. 800x600)");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    if w == 0 || h == 0 || w > render::MAX_SIDE || h > render::MAX_SIDE {
        return Err(format!("each side must be 1-{}", render::MAX_SIDE));
    }
    Ok((w, h))
}

fn parse_lights(s: &str) -> Result<Lights, String> {
    if s.trim().eq_ignore_ascii_case("none") {
        return Ok(Lights(Vec::new()));
    }
    let mut out = Vec::new();
    for part in s.split(',') {
        let n: u8 = part
            .trim()
            .parse()
            .ok()
            .filter(|n| *n < 8)
            .ok_or_else(|| format!("`{part}` is not a light number 0-7"))?;
        if !out.contains(&n) {
            out.push(n);
        }
    }
    Ok(Lights(out))
}

fn parse_rotate(s: &str) -> Result<Rotation, String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != 3 {
        return Err(format!("`{s}` is not X,Y,Z (three angles in degrees)"));
    }
    let mut v = [0.0f32; 3];
    for (slot, p) in v.iter_mut().zip(&parts) {
        *slot = p
            .trim()
            .parse::<f32>()
            .ok()
            .filter(|a| a.is_finite())
            .ok_or_else(|| format!("`{p}` is not an angle in degrees"))?;
    }
    Ok(Rotation(v))
}

fn parse_effect(s: &str) -> Result<Effect, String> {
    Effect::from_name(s.trim()).ok_or_else(|| {
        let names: Vec<&str> = Effect::ALL.iter().map(|e| e.name()).collect();
        format!("`{s}` is not an effect: {}", names.join(", "))
    })
}

fn parse_atoms(s: &str) -> Result<Atoms, String> {
    Atoms::from_name(s.trim()).ok_or_else(|| {
        let names: Vec<&str> = Atoms::ALL.iter().map(|a| a.name()).collect();
        format!("`{s}` is not a way to draw atoms: {}", names.join(", "))
    })
}

fn parse_background(s: &str) -> Result<BackgroundArg, String> {
    let t = s.trim().to_ascii_lowercase();
    let c = match t.as_str() {
        "transparent" => return Ok(BackgroundArg(Background::Transparent)),
        "black" => [0.0, 0.0, 0.0],
        "white" => [1.0, 1.0, 1.0],
        "gray" | "grey" => [0.5, 0.5, 0.5],
        _ => {
            let hex = t.strip_prefix('#').unwrap_or(&t);
            if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
                return Err(format!(
                    "`{s}` is not a colour: black, white, gray, #RRGGBB or transparent"
                ));
            }
            let byte = |i: usize| {
                u8::from_str_radix(hex.get(i..i + 2).unwrap_or("00"), 16).unwrap_or(0) as f32
                    / 255.0
            };
            [byte(0), byte(2), byte(4)]
        }
    };
    Ok(BackgroundArg(Background::Color(c)))
}

/// Runs `shaderbox render`.
pub fn run(args: &Args) -> Exit {
    match guarded(|| run_inner(args)) {
        Ok(exit) => exit,
        Err(p) => {
            eprintln!("shaderbox render: internal error: {}", p.message);
            Exit::Internal
        }
    }
}

fn options(args: &Args) -> RenderOptions {
    RenderOptions {
        width: args.size.0,
        height: args.size.1,
        projection: match args.projection {
            ProjectionArg::Ortho => Projection::Orthographic,
            ProjectionArg::Perspective => Projection::Perspective,
        },
        fog: match args.fog {
            FogArg::None => Fog::None,
            FogArg::Linear => Fog::Linear,
            FogArg::Exp => Fog::Exp,
            FogArg::Exp2 => Fog::Exp2,
        },
        lights: args.lights.0.clone(),
        rotate: args.rotate.0,
        supersample: args.supersample,
        background: args.background.0,
        effect: args.effect,
        atoms: args.atoms,
        style: match args.style {
            StyleArg::Spacefill => Style::Spacefill,
            StyleArg::Ballstick => Style::BallAndStick,
        },
    }
}

/// `OUT.png` -> `OUT-0007.png` (numbered outputs).
fn numbered(out: &Path, n: usize, digits: usize) -> PathBuf {
    let stem = out
        .file_stem()
        .map_or_else(|| "molecule".into(), |s| s.to_string_lossy().into_owned());
    let ext = out
        .extension()
        .map_or_else(|| "png".into(), |s| s.to_string_lossy().into_owned());
    out.with_file_name(format!("{stem}-{n:0digits$}.{ext}"))
}

/// Loads one structure; the error line is printed here.
fn load(path: Option<&Path>) -> Result<Structure, Exit> {
    let Some(path) = path else {
        return Ok(render::crambin());
    };
    match render::load_file(path) {
        Ok(s) => Ok(s),
        Err(e @ render::LoadError::Io { .. }) => {
            eprintln!("shaderbox render: cannot read {e}");
            Err(Exit::Misuse)
        }
        Err(e) => {
            eprintln!("shaderbox render: {e}");
            Err(Exit::Failed)
        }
    }
}

/// One job: which file, which rotation, where to write.
struct Job {
    file: Option<PathBuf>,
    rotate: [f32; 3],
    output: PathBuf,
}

fn jobs(args: &Args) -> Vec<Job> {
    let files: Vec<Option<PathBuf>> = if args.files.is_empty() {
        vec![None]
    } else {
        args.files.iter().cloned().map(Some).collect()
    };
    let frames = args.turntable.unwrap_or(1) as usize;
    let total = files.len() * frames;
    let digits = total.to_string().len().max(4);
    let mut out = Vec::with_capacity(total);
    for file in &files {
        for frame in 0..frames {
            let mut rotate = args.rotate.0;
            if args.turntable.is_some() {
                rotate[1] += 360.0 * frame as f32 / frames as f32;
            }
            let output = if total == 1 && args.turntable.is_none() {
                args.output.clone()
            } else {
                numbered(&args.output, out.len() + 1, digits)
            };
            out.push(Job {
                file: file.clone(),
                rotate,
                output,
            });
        }
    }
    out
}

fn run_inner(args: &Args) -> Exit {
    let jobs = jobs(args);
    if args.export_scene.is_some() && jobs.len() != 1 {
        eprintln!(
            "shaderbox render: --export-scene needs exactly one image (one FILE, no --turntable)"
        );
        return Exit::Misuse;
    }
    let base = options(args);
    let progress = if jobs.len() > 1 {
        let bar = indicatif::ProgressBar::new(jobs.len() as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} images, {elapsed} elapsed, about {eta} left {msg}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        Some(bar)
    } else {
        None
    };
    let report = |line: String| match &progress {
        Some(bar) => bar.println(line),
        None => eprintln!("{line}"),
    };
    let mut status = Exit::Ok;
    let mut loaded: Option<(Option<PathBuf>, Structure)> = None;
    // One context and its compiled programs for every image.
    let mut renderer = render::Renderer::new();
    for job in &jobs {
        let structure = match &loaded {
            Some((f, s)) if *f == job.file => s,
            _ => match load(job.file.as_deref()) {
                Ok(s) => &loaded.insert((job.file.clone(), s)).1,
                Err(e) => {
                    if status == Exit::Ok || e == Exit::Misuse {
                        status = e;
                    }
                    loaded = None;
                    if let Some(bar) = &progress {
                        bar.inc(1);
                    }
                    continue;
                }
            },
        };
        let opts = RenderOptions {
            rotate: job.rotate,
            ..base.clone()
        };
        let result = write_one(
            &mut renderer,
            structure,
            &opts,
            &job.output,
            args.export_scene.as_deref(),
        );
        match result {
            Ok(line) => {
                if progress.is_none() {
                    report(line);
                }
            }
            Err((exit, line)) => {
                report(line);
                status = exit;
                if exit == Exit::Misuse {
                    break;
                }
            }
        }
        if let Some(bar) = &progress {
            bar.inc(1);
        }
    }
    if let Some(bar) = &progress {
        bar.finish_and_clear();
        if status == Exit::Ok {
            eprintln!(
                "wrote {} images ({} to {})",
                jobs.len(),
                jobs.first()
                    .map_or(String::new(), |j| j.output.display().to_string()),
                jobs.last()
                    .map_or(String::new(), |j| j.output.display().to_string())
            );
        }
    }
    status
}

/// Renders one image and writes it (and the scene); the message to print.
fn write_one(
    renderer: &mut render::Renderer,
    structure: &Structure,
    opts: &RenderOptions,
    output: &Path,
    export_scene: Option<&Path>,
) -> Result<String, (Exit, String)> {
    let (image, scene) = match renderer.render_scene(structure, opts) {
        Ok(r) => r,
        Err(
            e @ (render::RenderError::Size { .. }
            | render::RenderError::Supersample { .. }
            | render::RenderError::Light(_)),
        ) => return Err((Exit::Misuse, format!("shaderbox render: {e}"))),
        Err(e) => {
            return Err((
                Exit::Failed,
                format!("shaderbox render: {}: {e}", structure.source),
            ))
        }
    };
    let written = std::fs::File::create(output)
        .map_err(|e| e.to_string())
        .and_then(|f| {
            image
                .write_png(std::io::BufWriter::new(f))
                .map_err(|e| e.to_string())
        });
    if let Err(e) = written {
        return Err((
            Exit::Failed,
            format!("shaderbox render: {}: {e}", output.display()),
        ));
    }
    if let Some(path) = export_scene {
        let json = scene.to_json();
        if let Err(e) = std::fs::write(path, json) {
            return Err((
                Exit::Failed,
                format!("shaderbox render: {}: {e}", path.display()),
            ));
        }
    }
    Ok(format!(
        "wrote {} ({}x{}, {} atoms from {})",
        output.display(),
        image.width,
        image.height,
        structure.atoms.len(),
        structure.source
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn argument_parsers() {
        assert_eq!(parse_size("800x600"), Ok((800, 600)));
        assert!(parse_size("0x5").is_err() && parse_size("big").is_err());
        assert!(parse_size("9000x10").is_err());
        assert_eq!(parse_lights("0, 1,1"), Ok(Lights(vec![0, 1])));
        assert_eq!(parse_lights("none"), Ok(Lights(vec![])));
        assert!(parse_lights("8").is_err() && parse_lights("").is_err());
        assert_eq!(parse_rotate("90,-45,0.5"), Ok(Rotation([90.0, -45.0, 0.5])));
        assert!(parse_rotate("1,2").is_err() && parse_rotate("1,2,inf").is_err());
        assert_eq!(
            parse_background("#ff0080"),
            Ok(BackgroundArg(Background::Color([1.0, 0.0, 128.0 / 255.0])))
        );
        assert_eq!(
            parse_background("Transparent"),
            Ok(BackgroundArg(Background::Transparent))
        );
        assert!(parse_background("#12345").is_err() && parse_background("mauve").is_err());
        assert_eq!(parse_atoms("points"), Ok(Atoms::Points));
        assert_eq!(parse_atoms(" quads"), Ok(Atoms::Quads));
        assert!(parse_atoms("lines").unwrap_err().contains("quads, points"));
        assert_eq!(parse_effect("x-red"), Ok(Effect::XRed));
        assert_eq!(parse_effect("outline"), Ok(Effect::Outline));
        let e = parse_effect("sepia").unwrap_err();
        assert!(e.contains("plain, outline, x, x-red, transparent"), "{e}");
    }

    #[test]
    fn numbered_outputs() {
        assert_eq!(
            numbered(Path::new("out/m.png"), 7, 4),
            PathBuf::from("out/m-0007.png")
        );
        assert_eq!(numbered(Path::new("m"), 12, 2), PathBuf::from("m-12.png"));
    }
}
