//! Molecular structures as the readers give them: atoms with their
//! elements, positions and names, the bonds a file states, and why a file
//! could not be read. The readers are [`crate::pdb`] and [`crate::mmcif`];
//! [`crate::load`] picks one for a file.

use crate::elements::Element;
use thiserror::Error;

/// Most atoms a structure may have (bounds memory: 4 vertices per atom).
pub const MAX_ATOMS: usize = 2_000_000;

/// One atom.
#[derive(Clone, Debug, PartialEq)]
pub struct Atom {
    pub element: Element,
    /// Position in Å.
    pub position: [f32; 3],
    /// Atom name, columns 13-16, trimmed ("CA", "OG1").
    pub name: String,
    /// Residue name, columns 18-20, trimmed.
    pub residue: String,
    /// Line of the record in its file (1-based).
    pub line: usize,
    /// Atom serial number (PDB columns 7-11, mmCIF `_atom_site.id`), when
    /// it is a number.
    pub serial: Option<i64>,
}

/// A set of atoms read from one source.
#[derive(Clone, Debug, PartialEq)]
pub struct Structure {
    /// Where it came from (file name, or "1crn (embedded)").
    pub source: String,
    pub atoms: Vec<Atom>,
    /// Bonds the file states (PDB CONECT), as pairs of indices into
    /// `atoms`, lower index first, sorted, no duplicates.
    pub conect: Vec<(usize, usize)>,
}

/// Why a structure could not be read.
#[derive(Debug, Error, PartialEq)]
pub enum LoadError {
    #[error("{file}:{line}: {message}")]
    Malformed {
        file: String,
        line: usize,
        message: String,
    },
    #[error("{file}: has no atoms (no ATOM or HETATM records)")]
    Empty { file: String },
    #[error("{file}: more than {MAX_ATOMS} atoms")]
    TooManyAtoms { file: String },
    #[error("{file}: {message}")]
    Io { file: String, message: String },
}
