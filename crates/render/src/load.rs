//! Reading a structure: a file or bytes in either format (mmCIF when the
//! first text is `data_`, else PDB), and the embedded default molecule.

use crate::mmcif::{is_mmcif, parse_mmcif};
use crate::pdb::parse_pdb;
use crate::structure::{LoadError, Structure};

/// The embedded crambin structure (PDB 1CRN, 327 atoms).
pub const CRAMBIN_PDB: &str = include_str!("../data/1crn.pdb");

/// Crambin (PDB 1CRN), embedded in the binary.
pub fn crambin() -> Structure {
    // The embedded file is checked by a test; an error here cannot happen,
    // but an empty structure is a defined result if it ever did.
    parse_pdb(CRAMBIN_PDB.as_bytes(), "1crn (embedded)").unwrap_or(Structure {
        source: "1crn (embedded)".into(),
        atoms: Vec::new(),
        conect: Vec::new(),
    })
}

/// Reads a PDB or mmCIF file from disk (mmCIF when its first text is
/// `data_`, else PDB).
pub fn load_file(path: &std::path::Path) -> Result<Structure, LoadError> {
    let source = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| LoadError::Io {
        file: source.clone(),
        message: e.to_string(),
    })?;
    parse(&bytes, &source)
}

/// Parses PDB or mmCIF text (mmCIF when its first text is `data_`).
pub fn parse(bytes: &[u8], source: &str) -> Result<Structure, LoadError> {
    if is_mmcif(bytes) {
        parse_mmcif(bytes, source)
    } else {
        parse_pdb(bytes, source)
    }
}
