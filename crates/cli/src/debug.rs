//! `shaderbox debug`: why one pixel of a `.shader_test` came out as it did.
//!
//! Runs the test's `[test]` section on a fresh context with the pixel
//! probe on (see the `debugger` crate) and prints, for every draw that
//! touched the pixel (or the one chosen with `--draw`), each fragment with
//! its primitive, inputs, executed statements and stored values,
//! `discard`, outputs and per-fragment operations — as text with source
//! lines, or as JSON.

use crate::shader_runner;
use crate::Exit;
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The `.shader_test` file.
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
    let (name, script) = shader_runner::load(&args.file)?;
    let window = shader_runner::window_config(&script);
    let mut ctx = gl::Context::new(window.width, window.height);
    ctx.set_debug(Some(gl::debug::DebugRequest {
        pixel: args.pixel,
        draw: args.draw,
        print_rect: args.print_rect,
    }));
    let opts = shader_runner::Options {
        file: args.file.clone(),
        ..Default::default()
    };
    // The verdict of the test's own probes does not matter here.
    let _ = shader_runner::execute_on(&mut ctx, &opts, &name, &script);
    let records = ctx.take_debug_records();
    Ok(debugger::Report::from_records(args.pixel, &records))
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
