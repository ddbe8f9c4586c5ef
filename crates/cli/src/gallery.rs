//! `shaderbox gallery -o DIR`: every program of the shader library drawn
//! on a scene that suits it ([`render::gallery`]), as `DIR/NAME.png`, and
//! `DIR/index.html` showing them with their names and settings.
//!
//! Exit status: 0 when every picture and the page were written; 1 when a
//! picture failed to render or a file could not be written (the others
//! are still written); 2 on misuse; 3 on an internal error.

use crate::guard::guarded;
use crate::Exit;
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Directory to write the pictures and index.html into (created).
    #[arg(short = 'o', long = "output", value_name = "DIR")]
    pub output: PathBuf,

    /// Side of each (square) picture in pixels.
    #[arg(long, value_name = "N", default_value_t = 256,
          value_parser = clap::value_parser!(u32).range(8..=2048))]
    pub size: u32,
}

/// Runs `shaderbox gallery`.
pub fn run(args: &Args) -> Exit {
    match guarded(|| run_inner(args)) {
        Ok(exit) => exit,
        Err(p) => {
            eprintln!("shaderbox gallery: internal error: {}", p.message);
            Exit::Internal
        }
    }
}

fn run_inner(args: &Args) -> Exit {
    if let Err(e) = std::fs::create_dir_all(&args.output) {
        eprintln!("shaderbox gallery: {}: {e}", args.output.display());
        return Exit::Misuse;
    }
    let entries = render::gallery::entries();
    let bar = indicatif::ProgressBar::new(entries.len() as u64);
    let mut status = Exit::Ok;
    for e in &entries {
        bar.set_message(e.file.clone());
        let path = args.output.join(format!("{}.png", e.file));
        let result = render::gallery::draw(e, args.size)
            .map_err(|err| err.to_string())
            .and_then(|img| {
                let f = std::fs::File::create(&path).map_err(|err| err.to_string())?;
                img.write_png(std::io::BufWriter::new(f))
                    .map_err(|err| err.to_string())
            });
        if let Err(err) = result {
            bar.println(format!("shaderbox gallery: {}: {err}", path.display()));
            status = Exit::Failed;
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let index = args.output.join("index.html");
    if let Err(e) = std::fs::write(&index, render::gallery::index_html(&entries)) {
        eprintln!("shaderbox gallery: {}: {e}", index.display());
        return Exit::Failed;
    }
    eprintln!("wrote {} pictures and {}", entries.len(), index.display());
    status
}
