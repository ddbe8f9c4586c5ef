//! `shaderbox debug`: why one pixel of a `.shader_test` (or of a scene
//! recorded by `shaderbox render --export-scene`) came out as it did.
//!
//! Runs the test's `[test]` section (or replays the scene's GL calls) on a
//! fresh context with the pixel probe on (see the `debugger` crate) and prints, for every draw that
//! touched the pixel (or the one chosen with `--draw`), each fragment with
//! its primitive, inputs, executed statements and stored values,
//! `discard`, outputs and per-fragment operations — as text with source
//! lines, or as JSON.

use crate::shader_runner;
use crate::Exit;
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A `.shader_test` file, or a scene `.json` written by `shaderbox
    /// render --export-scene` (the molecule renders, replayed).
    pub file: PathBuf,
    /// The window pixel to explain, `X,Y` (origin at the bottom left, as
    /// glReadPixels and piglit's probes count).
    #[arg(long, value_parser = parse_pair)]
    pub pixel: (u32, u32),
    /// Only the draw with this index (0 = the first draw of the test).
    #[arg(long)]
    pub draw: Option<usize>,
    /// Also print the `debugPrintfEXT` output of every pixel in the
    /// rectangle `X0,Y0,X1,Y1` (exclusive upper bounds).
    #[arg(long, value_parser = parse_rect)]
    pub print_rect: Option<(u32, u32, u32, u32)>,
    /// In a draw whose geometry shader writes `gl_Layer` into a layered
    /// framebuffer (array, 3D or cube map attachments), the layer to
    /// explain (a cube map's face: 0 = +X ... 5 = -Z).
    #[arg(long, default_value_t = 0)]
    pub layer: i32,
    /// Also trace the vertex shader for this vertex (position in each
    /// debugged draw's vertex list, 0 = the first).
    #[arg(long)]
    pub vertex: Option<usize>,
    /// Write the final image with the outline of every primitive the
    /// debugged draws set up (after the vertex shader and clipping) to this
    /// PNG: where did the vertices go?
    #[arg(long, value_name = "PNG")]
    pub outlines: Option<PathBuf>,
    /// Show this fragment-shader input or variable (a varying, a local,
    /// `gl_FragCoord`...) for the whole frame as a false-colour PNG written
    /// to `--view-png` (the value in the last fragment written at each
    /// pixel; a scalar on a blue→red ramp, a vector's x, y, z as red,
    /// green, blue, each stretched over its range in the frame).
    #[arg(long, requires = "view_png")]
    pub view: Option<String>,
    #[arg(long, value_name = "PNG", requires = "view")]
    pub view_png: Option<PathBuf>,
    /// Report format.
    #[arg(long, value_enum, default_value = "text")]
    pub format: Format,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Text,
    Json,
}

fn numbers(s: &str, n: usize, what: &str) -> Result<Vec<u32>, String> {
    let v: Result<Vec<u32>, _> = s.split(',').map(|p| p.trim().parse::<u32>()).collect();
    match v {
        Ok(v) if v.len() == n => Ok(v),
        _ => Err(format!(
            "expected {what}, e.g. {}",
            if n == 2 { "`10,20'" } else { "`0,0,8,8'" }
        )),
    }
}

fn parse_pair(s: &str) -> Result<(u32, u32), String> {
    let v = numbers(s, 2, "two non-negative integers X,Y")?;
    Ok((v[0], v[1]))
}

fn parse_rect(s: &str) -> Result<(u32, u32, u32, u32), String> {
    let v = numbers(s, 4, "four non-negative integers X0,Y0,X1,Y1")?;
    if v[0] >= v[2] || v[1] >= v[3] {
        return Err("the rectangle is empty: X0 < X1 and Y0 < Y1 are needed".into());
    }
    Ok((v[0], v[1], v[2], v[3]))
}

/// The report for `args`, or an error message.
pub fn report(args: &Args) -> Result<debugger::Report, String> {
    let request = gl::debug::DebugRequest {
        pixel: args.pixel,
        draw: args.draw,
        print_rect: args.print_rect,
        vertex: args.vertex,
        outlines: args.outlines.is_some(),
        view: args.view.clone(),
        layer: args.layer,
    };
    let is_scene = args.file.extension().is_some_and(|e| e == "json");
    let (mut ctx, (w, h)) = if is_scene {
        // A scene recorded by `shaderbox render --export-scene`.
        let text = std::fs::read_to_string(&args.file)
            .map_err(|e| format!("could not read file \"{}\": {e}", args.file.display()))?;
        let scene =
            render::Scene::from_json(&text).map_err(|e| format!("{}: {e}", args.file.display()))?;
        let (w, h) = (
            scene.width.clamp(1, gl::MAX_TEXTURE_SIZE as u32) as i32,
            scene.height.clamp(1, gl::MAX_TEXTURE_SIZE as u32) as i32,
        );
        let mut ctx = gl::Context::new(w, h);
        ctx.set_debug(Some(request));
        let ctx = scene
            .replay_on(ctx)
            .map_err(|e| format!("{}: {e}", args.file.display()))?;
        (ctx, (w, h))
    } else {
        let (name, script) = shader_runner::load(&args.file)?;
        let window = shader_runner::window_config(&script);
        // The context the test asks for (a GLSL 1.50 test needs 3.2+).
        let mut ctx = shader_runner::context(&window);
        ctx.set_debug(Some(request));
        let opts = shader_runner::Options {
            file: args.file.clone(),
            ..Default::default()
        };
        // The verdict of the test's own probes does not matter here.
        let _ = shader_runner::execute_on(&mut ctx, &opts, &name, &script);
        (ctx, (window.width, window.height))
    };
    let records = ctx.take_debug_records();
    let report = debugger::Report::from_records(args.pixel, &records);
    if let Some(path) = &args.outlines {
        let mut pixels = vec![0u8; w as usize * h as usize * 4];
        ctx.read_pixels(
            0,
            0,
            w,
            h,
            gl::enums::GL_RGBA,
            gl::enums::GL_UNSIGNED_BYTE,
            &mut pixels,
        );
        for d in &report.draws {
            for poly in &d.outlines {
                outline(&mut pixels, w as usize, h as usize, poly);
            }
        }
        let png = shader_runner::png::encode_rgba8_bottom_up(w as u32, h as u32, &pixels);
        std::fs::write(path, png).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    if let (Some(name), Some(path)) = (&args.view, &args.view_png) {
        let (png, legend) = view_png(name, &records, w as u32, h as u32)?;
        std::fs::write(path, png).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        eprintln!("{legend}");
    }
    Ok(report)
}

/// The false-colour image of a view over every debugged draw (later draws
/// cover earlier ones) and a legend of the value ranges.
fn view_png(
    name: &str,
    records: &[gl::debug::DrawRecord],
    w: u32,
    h: u32,
) -> Result<(Vec<u8>, String), String> {
    use glsl::types::Scalar;
    let n = w as usize * h as usize;
    let mut values: Vec<Option<[f32; 4]>> = vec![None; n];
    let mut comps = 0usize;
    let mut any = false;
    for r in records {
        match &r.view {
            Some(Ok(v)) => {
                any = true;
                comps = comps.max(v.kinds.len());
                for (dst, src) in values.iter_mut().zip(&v.image.pixels) {
                    if let Some(bits) = src {
                        let mut f = [0.0f32; 4];
                        for (c, k) in v.kinds.iter().enumerate().take(4) {
                            f[c] = match k {
                                Scalar::Float => f32::from_bits(bits[c]),
                                Scalar::Int => bits[c] as i32 as f32,
                                Scalar::Uint => bits[c] as f32,
                                Scalar::Bool => (bits[c] != 0) as u32 as f32,
                            };
                        }
                        *dst = Some(f);
                    }
                }
            }
            Some(Err(e)) => return Err(e.clone()),
            None => {}
        }
    }
    if !any {
        return Err(format!(
            "no draw was debugged, so there is no view of `{name}'"
        ));
    }
    let comps = comps.clamp(1, 4);
    let mut lo = [f32::INFINITY; 4];
    let mut hi = [f32::NEG_INFINITY; 4];
    for v in values.iter().flatten() {
        for c in 0..comps {
            if v[c].is_finite() {
                lo[c] = lo[c].min(v[c]);
                hi[c] = hi[c].max(v[c]);
            }
        }
    }
    let norm = |c: usize, x: f32| -> f32 {
        if !x.is_finite() {
            return 0.0;
        }
        if hi[c] <= lo[c] {
            // One value everywhere: the middle of the ramp.
            return 0.5;
        }
        ((x - lo[c]) / (hi[c] - lo[c])).clamp(0.0, 1.0)
    };
    let mut pixels = vec![0u8; n * 4];
    for (i, v) in values.iter().enumerate() {
        let rgb = match v {
            None => [32.0, 32.0, 32.0],
            Some(v) if comps == 1 => {
                // blue → cyan → green → yellow → red
                let t = norm(0, v[0]) * 4.0;
                let ramp = [
                    [0.0, 0.0, 1.0],
                    [0.0, 1.0, 1.0],
                    [0.0, 1.0, 0.0],
                    [1.0, 1.0, 0.0],
                    [1.0, 0.0, 0.0],
                ];
                let k = (t.floor() as usize).min(3);
                let f = t - k as f32;
                let (a, b) = (ramp[k], ramp[k + 1]);
                [0, 1, 2].map(|j| 255.0 * (a[j] + (b[j] - a[j]) * f))
            }
            Some(v) => [0, 1, 2].map(|j| {
                if j < comps {
                    255.0 * norm(j, v[j])
                } else {
                    0.0
                }
            }),
        };
        pixels[i * 4..i * 4 + 4].copy_from_slice(&[rgb[0] as u8, rgb[1] as u8, rgb[2] as u8, 255]);
    }
    let mut legend = format!("view `{name}':");
    for c in 0..comps {
        let comp = ["x", "y", "z", "w"][c];
        if lo[c] <= hi[c] {
            legend.push_str(&format!(" {comp} in [{}, {}]", lo[c], hi[c]));
        } else {
            legend.push_str(&format!(" {comp}: no finite value"));
        }
    }
    if comps == 1 {
        legend.push_str(" (blue = lowest, red = highest)");
    } else {
        legend.push_str(" (red, green, blue = x, y, z)");
    }
    legend.push_str("; dark grey: no fragment written");
    Ok((
        shader_runner::png::encode_rgba8_bottom_up(w, h, &pixels),
        legend,
    ))
}

/// Draws a closed polygon's edges (window coordinates, bottom-up rows)
/// in magenta; a point is a small cross.
fn outline(pixels: &mut [u8], w: usize, h: usize, poly: &[[f64; 2]]) {
    let mut plot = |x: f64, y: f64| {
        let (x, y) = (x.floor(), y.floor());
        if x >= 0.0 && y >= 0.0 && (x as usize) < w && (y as usize) < h {
            let i = (y as usize * w + x as usize) * 4;
            if let Some(p) = pixels.get_mut(i..i + 4) {
                p.copy_from_slice(&[255, 0, 255, 255]);
            }
        }
    };
    if let [p] = poly {
        for d in -2..=2 {
            plot(p[0] + d as f64, p[1]);
            plot(p[0], p[1] + d as f64);
        }
        return;
    }
    for (i, a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        let steps =
            ((b[0] - a[0]).abs().max((b[1] - a[1]).abs()).ceil() as usize).clamp(1, 1 << 16);
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            plot(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t);
        }
    }
}

pub fn run(args: &Args) -> Exit {
    match crate::guard::guarded(|| report(args)) {
        Ok(Ok(r)) => {
            match args.format {
                Format::Text => print!("{}", r.text()),
                Format::Json => println!("{}", r.json()),
            }
            Exit::Ok
        }
        Ok(Err(e)) => {
            eprintln!("shaderbox debug: {e}");
            Exit::Misuse
        }
        Err(panic) => {
            eprintln!("shaderbox debug: internal error: {}", panic.message);
            Exit::Internal
        }
    }
}
