//! The debugger for unmodified programs: environment variables name a
//! pixel, and the trace of every draw that touches it is appended to a
//! file at each glFinish/glFlush (and when the context is destroyed).
//!
//! - `SHADERBOX_DEBUG_PIXEL=X,Y`: the window pixel (bottom-left origin);
//!   without it nothing is traced and draws pay one `Option` check.
//! - `SHADERBOX_DEBUG_DRAW=N`: only the N-th draw (0 = first).
//! - `SHADERBOX_DEBUG_LAYER=L`: in a draw whose geometry shader writes
//!   `gl_Layer` into a layered framebuffer, the layer (default 0).
//! - `SHADERBOX_DEBUG_OUT=PATH`: where reports go (default
//!   `shaderbox-debug.txt` in the working directory).
//! - `SHADERBOX_DEBUG_FORMAT=text|json` (default text).
//!
//! A malformed value is reported once on stderr and debugging stays off.

use std::io::Write;

/// What the environment asked for.
#[derive(Clone, Debug, PartialEq)]
pub struct DebugEnv {
    pub request: gl::debug::DebugRequest,
    pub out: std::path::PathBuf,
    pub json: bool,
}

/// Reads the variables through `var` (the process environment in
/// practice); `Err` carries the message for stderr.
pub fn parse(var: impl Fn(&str) -> Option<String>) -> Result<Option<DebugEnv>, String> {
    let Some(pixel) = var("SHADERBOX_DEBUG_PIXEL") else {
        return Ok(None);
    };
    let nums: Vec<Option<u32>> = pixel.split(',').map(|p| p.trim().parse().ok()).collect();
    let (x, y) = match nums.as_slice() {
        [Some(x), Some(y)] => (*x, *y),
        _ => {
            return Err(format!(
                "SHADERBOX_DEBUG_PIXEL=`{pixel}': expected two non-negative integers X,Y"
            ))
        }
    };
    let mut request = gl::debug::DebugRequest::pixel(x, y);
    if let Some(d) = var("SHADERBOX_DEBUG_DRAW") {
        request.draw = Some(d.trim().parse().map_err(|_| {
            format!("SHADERBOX_DEBUG_DRAW=`{d}': expected a draw number (0 = the first)")
        })?);
    }
    if let Some(l) = var("SHADERBOX_DEBUG_LAYER") {
        request.layer = l
            .trim()
            .parse::<u16>()
            .map_err(|_| {
                format!("SHADERBOX_DEBUG_LAYER=`{l}': expected a layer number (0 = the first)")
            })?
            .into();
    }
    let json = match var("SHADERBOX_DEBUG_FORMAT").as_deref() {
        None | Some("text") => false,
        Some("json") => true,
        Some(other) => {
            return Err(format!(
                "SHADERBOX_DEBUG_FORMAT=`{other}': expected `text' or `json'"
            ))
        }
    };
    let out = var("SHADERBOX_DEBUG_OUT").unwrap_or_else(|| "shaderbox-debug.txt".into());
    Ok(Some(DebugEnv {
        request,
        out: out.into(),
        json,
    }))
}

/// The process's debugging request, read once.
pub fn from_process() -> Option<DebugEnv> {
    static ENV: std::sync::OnceLock<Option<DebugEnv>> = std::sync::OnceLock::new();
    ENV.get_or_init(|| match parse(|k| std::env::var(k).ok()) {
        Ok(e) => e,
        Err(msg) => {
            eprintln!("shaderbox: {msg}; pixel debugging is off");
            None
        }
    })
    .clone()
}

/// Appends the reports of the draws debugged since the last call.
pub fn flush(gl: &mut gl::Context, env: &DebugEnv) {
    let records = gl.take_debug_records();
    if records.is_empty() {
        return;
    }
    let report = debugger::Report::from_records(env.request.pixel, &records);
    let text = if env.json {
        format!("{}\n", report.json())
    } else {
        report.text()
    };
    let written = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(&env.out)
        .and_then(|mut f| f.write_all(text.as_bytes()));
    if let Err(e) = written {
        eprintln!(
            "shaderbox: cannot write the debug report to {}: {e}",
            env.out.display()
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(pairs: &[(&str, &str)]) -> Result<Option<DebugEnv>, String> {
        let pairs: Vec<(String, String)> = pairs
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        parse(move |k| pairs.iter().find(|p| p.0 == k).map(|p| p.1.clone()))
    }

    #[test]
    fn reads_the_variables() {
        assert_eq!(env(&[]), Ok(None));
        let e = env(&[
            ("SHADERBOX_DEBUG_PIXEL", "3, 4"),
            ("SHADERBOX_DEBUG_DRAW", "2"),
            ("SHADERBOX_DEBUG_LAYER", "3"),
            ("SHADERBOX_DEBUG_FORMAT", "json"),
            ("SHADERBOX_DEBUG_OUT", "/tmp/x.json"),
        ])
        .unwrap()
        .unwrap();
        assert_eq!(e.request.pixel, (3, 4));
        assert_eq!(e.request.draw, Some(2));
        assert_eq!(e.request.layer, 3);
        assert!(e.json);
        assert_eq!(e.out, std::path::PathBuf::from("/tmp/x.json"));
    }

    #[test]
    fn malformed_values_are_named() {
        assert!(env(&[("SHADERBOX_DEBUG_PIXEL", "3")])
            .unwrap_err()
            .contains("X,Y"));
        assert!(env(&[
            ("SHADERBOX_DEBUG_PIXEL", "1,2"),
            ("SHADERBOX_DEBUG_DRAW", "x")
        ])
        .unwrap_err()
        .contains("draw number"));
        assert!(env(&[
            ("SHADERBOX_DEBUG_PIXEL", "1,2"),
            ("SHADERBOX_DEBUG_LAYER", "-1")
        ])
        .unwrap_err()
        .contains("layer number"));
        assert!(env(&[
            ("SHADERBOX_DEBUG_PIXEL", "1,2"),
            ("SHADERBOX_DEBUG_FORMAT", "xml")
        ])
        .unwrap_err()
        .contains("`text' or `json'"));
    }
}
