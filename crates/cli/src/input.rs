//! Reading shader files and telling their stage from their name.

use glsl::Stage;
use std::path::Path;

/// What a file name says about the shader inside.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StageGuess {
    /// A stage shaderbox implements.
    Known(Stage),
    /// No recognised extension.
    Unknown,
}

/// The stage from the file extension: `.vert`/`.vs` are vertex shaders,
/// `.tesc`/`.tese` tessellation control and evaluation shaders,
/// `.geom`/`.gs` geometry shaders, `.frag`/`.fs` fragment shaders,
/// `.comp` compute shaders (case-sensitive, as piglit's are).
pub fn stage_from_path(path: &Path) -> StageGuess {
    match path.extension().and_then(|e| e.to_str()) {
        Some("vert" | "vs") => StageGuess::Known(Stage::Vertex),
        Some("frag" | "fs") => StageGuess::Known(Stage::Fragment),
        Some("geom" | "gs") => StageGuess::Known(Stage::Geometry),
        Some("tesc") => StageGuess::Known(Stage::TessControl),
        Some("tese") => StageGuess::Known(Stage::TessEvaluation),
        Some("comp") => StageGuess::Known(Stage::Compute),
        _ => StageGuess::Unknown,
    }
}

/// Reads a shader file. Bytes that are not UTF-8 become U+FFFD, which the
/// compiler then reports as invalid characters where they are (a shader
/// with such bytes is a compile error, not a usage error).
///
/// At most one byte past `glsl::limits::MAX_SOURCE_BYTES` is read: the
/// compiler refuses such a source whole, with the message every front end
/// gives, and a bigger file costs no more memory than that.
///
/// The error is a complete sentence naming the file.
pub fn read_source(path: &Path) -> Result<String, String> {
    use std::io::Read;
    let cannot = |e: std::io::Error| format!("cannot read `{}': {}", path.display(), e);
    let file = std::fs::File::open(path).map_err(cannot)?;
    let mut bytes = Vec::new();
    file.take(glsl::limits::MAX_SOURCE_BYTES as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    Ok(match String::from_utf8(bytes) {
        Ok(s) => s,
        Err(e) => String::from_utf8_lossy(e.as_bytes()).into_owned(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stages_from_extensions() {
        let g = |p: &str| stage_from_path(Path::new(p));
        assert_eq!(g("a/b.vert"), StageGuess::Known(Stage::Vertex));
        assert_eq!(g("b.vs"), StageGuess::Known(Stage::Vertex));
        assert_eq!(g("x.y.frag"), StageGuess::Known(Stage::Fragment));
        assert_eq!(g("b.fs"), StageGuess::Known(Stage::Fragment));
        assert_eq!(g("b.geom"), StageGuess::Known(Stage::Geometry));
        assert_eq!(g("b.gs"), StageGuess::Known(Stage::Geometry));
        assert_eq!(g("b.comp"), StageGuess::Known(Stage::Compute));
        assert_eq!(g("b.tesc"), StageGuess::Known(Stage::TessControl));
        assert_eq!(g("b.tese"), StageGuess::Known(Stage::TessEvaluation));
        assert_eq!(g("b.glsl"), StageGuess::Unknown);
        assert_eq!(g("frag"), StageGuess::Unknown);
        assert_eq!(g("b.FRAG"), StageGuess::Unknown);
    }

    #[test]
    fn reading_stops_past_the_source_limit() {
        let dir = std::env::temp_dir().join(format!("shaderbox-big-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("big.frag");
        let max = glsl::limits::MAX_SOURCE_BYTES;
        std::fs::write(&p, vec![b'\n'; max + 1000]).unwrap();
        let s = read_source(&p).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(s.len(), max + 1);
        let sh = glsl::compile(&[&s], &glsl::CompileOptions::new(Stage::Fragment));
        assert_eq!(sh.diagnostics[0].message, glsl::source_too_large_message());
    }

    #[test]
    fn missing_file_is_named() {
        let e = read_source(Path::new("/nonexistent/dir/x.frag")).unwrap_err();
        assert!(
            e.starts_with("cannot read `/nonexistent/dir/x.frag': "),
            "{e}"
        );
    }

    #[test]
    fn invalid_utf8_is_kept_as_replacement_characters() {
        let dir = std::env::temp_dir().join(format!("shaderbox-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("bad.frag");
        std::fs::write(&p, b"void main() { \xff }").unwrap();
        let s = read_source(&p).unwrap();
        assert_eq!(s, "void main() { \u{fffd} }");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
