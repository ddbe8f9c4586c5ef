//! A strict reader of PDB coordinate files.
//!
//! The reader takes the ATOM and HETATM records of a PDB file (wwPDB
//! format 3.3, fixed columns) and ignores every other record:
//! - x, y, z are columns 31-38, 39-46, 47-54 and must be there and be
//!   finite numbers; a record shorter than 54 columns (a truncated file)
//!   is an error naming the line;
//! - the element is columns 77-78 when present, else it is read from the
//!   atom name (columns 13-14: a two-letter symbol starting in column 13
//!   for HETATM records, else the first letter of the name);
//! - only the first MODEL is read; of alternate locations (column 17) only
//!   blank and the first one seen are kept;
//! - control characters other than tab/CR, or text that is not ASCII in an
//!   atom record, are errors (binary data is not a PDB file);
//! - CONECT records (columns 7-11 the atom's serial, 12-16, 17-21, 22-26,
//!   27-31 its partners) become bonds between the atoms read; serials of
//!   atoms that were not read (other models, other alternate locations)
//!   are skipped; a field that is neither blank nor a number is an error.
//!
//! Every error names the source (file name) and the 1-based line.

use crate::elements::Element;
use crate::mmcif::is_mmcif;
use crate::structure::{Atom, LoadError, Structure, MAX_ATOMS};

/// Parses PDB text; `source` names it in errors.
pub fn parse_pdb(bytes: &[u8], source: &str) -> Result<Structure, LoadError> {
    let malformed = |line: usize, message: String| LoadError::Malformed {
        file: source.to_string(),
        line,
        message,
    };
    if is_mmcif(bytes) {
        return Err(malformed(
            1,
            "this is an mmCIF file (it starts with data_), not PDB; read it with parse or load_file"
                .into(),
        ));
    }
    let mut atoms = Vec::new();
    // CONECT records: (line, atom serial, partner serials).
    let mut conect_records: Vec<(usize, i64, Vec<i64>)> = Vec::new();
    let mut alt_seen: Option<u8> = None;
    let mut in_first_model = true;
    for (i, raw) in bytes.split(|b| *b == b'\n').enumerate() {
        let line_no = i + 1;
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        if let Some(pos) = raw
            .iter()
            .position(|b| (*b < 0x20 && *b != b'\t' && *b != b'\r') || *b == 0x7f)
        {
            return Err(malformed(
                line_no,
                format!(
                    "control character 0x{:02x} in column {}: binary data, not a PDB file",
                    raw[pos],
                    pos + 1
                ),
            ));
        }
        let is_atom = raw.starts_with(b"ATOM") || raw.starts_with(b"HETATM");
        if raw.starts_with(b"ENDMDL") {
            // Only the first model; CONECT records follow the last model,
            // so keep reading those.
            in_first_model = false;
            continue;
        }
        if raw.starts_with(b"CONECT") {
            conect_records.push(parse_conect(raw, line_no, source)?);
            continue;
        }
        if !in_first_model {
            continue;
        }
        if !is_atom {
            continue;
        }
        if !raw.is_ascii() {
            return Err(malformed(
                line_no,
                "non-ASCII text in an atom record".into(),
            ));
        }
        // ASCII, so byte columns are character columns.
        let text = std::str::from_utf8(raw).unwrap_or("");
        let record = if raw.starts_with(b"ATOM") {
            "ATOM"
        } else {
            "HETATM"
        };
        if text.len() < 54 {
            return Err(malformed(
                line_no,
                format!(
                    "{record} record is {} columns long; its coordinates need 54 (truncated file?)",
                    text.len()
                ),
            ));
        }
        let col = |a: usize, b: usize| text.get(a - 1..b.min(text.len())).unwrap_or("");
        let coord = |a: usize, b: usize, axis: &str| -> Result<f32, LoadError> {
            let field = col(a, b);
            match field.trim().parse::<f32>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(malformed(
                    line_no,
                    format!("{axis} coordinate (columns {a}-{b}) is not a number: {field:?}"),
                )),
            }
        };
        let position = [
            coord(31, 38, "x")?,
            coord(39, 46, "y")?,
            coord(47, 54, "z")?,
        ];
        let alt = col(17, 17).as_bytes().first().copied().unwrap_or(b' ');
        if alt != b' ' {
            match alt_seen {
                None => alt_seen = Some(alt),
                Some(a) if a != alt => continue,
                Some(_) => {}
            }
        }
        let name = col(13, 16);
        let element = element_of(col(77, 78), name, record == "HETATM");
        if atoms.len() >= MAX_ATOMS {
            return Err(LoadError::TooManyAtoms {
                file: source.to_string(),
            });
        }
        atoms.push(Atom {
            element,
            position,
            name: name.trim().to_string(),
            residue: col(18, 20).trim().to_string(),
            line: line_no,
            serial: col(7, 11).trim().parse().ok(),
        });
    }
    if atoms.is_empty() {
        return Err(LoadError::Empty {
            file: source.to_string(),
        });
    }
    let conect = resolve_conect(&atoms, &conect_records);
    Ok(Structure {
        source: source.to_string(),
        atoms,
        conect,
    })
}

/// Reads one CONECT record: the atom's serial and its partners'.
fn parse_conect(
    raw: &[u8],
    line: usize,
    source: &str,
) -> Result<(usize, i64, Vec<i64>), LoadError> {
    let text = std::str::from_utf8(raw).ok().filter(|t| t.is_ascii());
    let Some(text) = text else {
        return Err(LoadError::Malformed {
            file: source.to_string(),
            line,
            message: "non-ASCII text in a CONECT record".into(),
        });
    };
    let mut serials = Vec::new();
    for (a, b) in [(7, 11), (12, 16), (17, 21), (22, 26), (27, 31)] {
        let field = text.get(a - 1..b.min(text.len())).unwrap_or("").trim();
        if field.is_empty() {
            continue;
        }
        match field.parse::<i64>() {
            Ok(v) => serials.push(v),
            Err(_) => {
                return Err(LoadError::Malformed {
                    file: source.to_string(),
                    line,
                    message: format!(
                        "CONECT serial number (columns {a}-{b}) is not a number: {field:?}"
                    ),
                })
            }
        }
    }
    if serials.is_empty() {
        return Err(LoadError::Malformed {
            file: source.to_string(),
            line,
            message: "CONECT record without an atom serial number (columns 7-11)".into(),
        });
    }
    let atom = serials.remove(0);
    Ok((line, atom, serials))
}

/// CONECT serials to sorted, unique index pairs; unknown serials skipped.
fn resolve_conect(atoms: &[Atom], records: &[(usize, i64, Vec<i64>)]) -> Vec<(usize, usize)> {
    if records.is_empty() {
        return Vec::new();
    }
    let mut by_serial: Vec<(i64, usize)> = atoms
        .iter()
        .enumerate()
        .filter_map(|(i, a)| a.serial.map(|s| (s, i)))
        .collect();
    by_serial.sort_unstable();
    let find = |s: i64| -> Option<usize> {
        by_serial
            .binary_search_by_key(&s, |(k, _)| *k)
            .ok()
            .and_then(|p| by_serial.get(p))
            .map(|(_, i)| *i)
    };
    let mut out = Vec::new();
    for (_, a, partners) in records {
        let Some(i) = find(*a) else { continue };
        for p in partners {
            if let Some(j) = find(*p) {
                if i != j {
                    out.push((i.min(j), i.max(j)));
                }
            }
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// The element of an atom record: columns 77-78, else from the name.
fn element_of(symbol_field: &str, name: &str, hetatm: bool) -> Element {
    let sym = symbol_field.trim();
    if !sym.is_empty() {
        // Strip a charge written into the symbol field by some programs.
        let letters: String = sym.chars().filter(|c| c.is_ascii_alphabetic()).collect();
        if let Some(e) = Element::from_symbol(&letters) {
            return e;
        }
    }
    let b = name.as_bytes();
    let first = b.first().copied().unwrap_or(b' ');
    if first.is_ascii_alphabetic() {
        // Name starts in column 13: a two-letter element (HETATM "FE  ")
        // or a four-character name whose first letter is the element
        // (hydrogens such as "HG21").
        if hetatm {
            if let Some(e) = name.get(0..2).and_then(Element::from_symbol) {
                return e;
            }
        }
        return name
            .get(0..1)
            .and_then(Element::from_symbol)
            .unwrap_or(Element::UNKNOWN);
    }
    // Column 13 blank or a digit ("1HG2"): the element is column 14.
    name.get(1..2)
        .and_then(Element::from_symbol)
        .unwrap_or(Element::UNKNOWN)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::load::crambin;

    const TWO: &str = "\
HEADER    TEST
ATOM      1  N   THR A   1      17.047  14.099   3.625  1.00 13.79           N
HETATM    2 FE   HEM A 100       1.000   2.000   3.000  1.00  0.00
END
";

    #[test]
    fn reads_atoms_and_elements() {
        let s = parse_pdb(TWO.as_bytes(), "t.pdb").unwrap();
        assert_eq!(s.atoms.len(), 2);
        assert_eq!(s.atoms[0].element.symbol(), "N");
        assert_eq!(s.atoms[0].position, [17.047, 14.099, 3.625]);
        assert_eq!(s.atoms[0].line, 2);
        assert_eq!(s.atoms[0].name, "N");
        assert_eq!(s.atoms[1].element.symbol(), "Fe");
        assert_eq!(s.atoms[1].residue, "HEM");
    }

    #[test]
    fn crambin_is_embedded() {
        let s = crambin();
        assert_eq!(s.atoms.len(), 327);
        let sulfur = s.atoms.iter().filter(|a| a.element.symbol() == "S").count();
        assert_eq!(sulfur, 6, "three disulfide bridges");
    }

    #[test]
    fn truncated_record_names_line() {
        let text =
            "ATOM      1  N   THR A   1      17.047  14.099   3.625  1.00 13.79           N\n\
                    ATOM      2  CA  THR A   1      16.967  12.7";
        let e = parse_pdb(text.as_bytes(), "cut.pdb").unwrap_err();
        let m = e.to_string();
        assert!(m.starts_with("cut.pdb:2: ATOM record is 44 columns"), "{m}");
    }

    #[test]
    fn bad_number_names_line_and_columns() {
        let text = "REMARK\nATOM      1  N   THR A   1      17.0x7  14.099   3.625\n";
        let m = parse_pdb(text.as_bytes(), "b.pdb").unwrap_err().to_string();
        assert!(
            m.starts_with("b.pdb:2: x coordinate (columns 31-38)"),
            "{m}"
        );
        let nan = "ATOM      1  N   THR A   1         NaN  14.099   3.625\n";
        assert!(parse_pdb(nan.as_bytes(), "n").is_err());
    }

    #[test]
    fn empty_and_binary_and_mmcif() {
        let e = parse_pdb(b"HEADER x\nEND\n", "e.pdb").unwrap_err();
        assert_eq!(
            e.to_string(),
            "e.pdb: has no atoms (no ATOM or HETATM records)"
        );
        assert!(matches!(
            parse_pdb(b"", "e").unwrap_err(),
            LoadError::Empty { .. }
        ));
        let m = parse_pdb(b"\x89PNG\r\n\x1a\n\0\0", "p.png")
            .unwrap_err()
            .to_string();
        assert!(m.starts_with("p.png:2: control character 0x1a"), "{m}");
        let m = parse_pdb(b"data_1CRN\nloop_\n", "c.cif")
            .unwrap_err()
            .to_string();
        assert!(m.contains("mmCIF"), "{m}");
        let utf = "ATOM      1  N   THR A   1      17.047  14.099   3.625  1.00 13.79   é\n";
        assert!(parse_pdb(utf.as_bytes(), "u").is_err());
    }

    #[test]
    fn first_model_and_first_altloc_only() {
        let text = "\
MODEL        1
ATOM      1  CA AALA A   1       1.000   1.000   1.000  0.50  0.00           C
ATOM      2  CA BALA A   1       2.000   2.000   2.000  0.50  0.00           C
ATOM      3  N   ALA A   1       3.000   3.000   3.000  1.00  0.00
ENDMDL
MODEL        2
ATOM      1  CA  ALA A   1       9.000   9.000   9.000  1.00  0.00           C
";
        let s = parse_pdb(text.as_bytes(), "m").unwrap();
        assert_eq!(s.atoms.len(), 2);
        assert_eq!(s.atoms[0].position, [1.0, 1.0, 1.0]);
        assert_eq!(s.atoms[1].element.symbol(), "N");
    }

    #[test]
    fn conect_records_become_bonds() {
        let text = "\
ATOM      1  SG  CYS A   3       1.000   1.000   1.000  1.00  0.00           S
ATOM      2  SG  CYS A  40       3.000   1.000   1.000  1.00  0.00           S
ATOM      3  N   ALA A   1       9.000   1.000   1.000  1.00  0.00           N
CONECT    1    2
CONECT    2    1   99
";
        let s = parse_pdb(text.as_bytes(), "c").unwrap();
        assert_eq!(s.conect, vec![(0, 1)]);
        assert_eq!(s.atoms[2].serial, Some(3));
        let bad = format!("{text}CONECT    1   x2\n");
        let m = parse_pdb(bad.as_bytes(), "c").unwrap_err().to_string();
        assert!(
            m.starts_with("c:6: CONECT serial number (columns 12-16)"),
            "{m}"
        );
        let crambin_bonds = crambin().conect;
        assert_eq!(
            crambin_bonds.len(),
            3,
            "three disulfide bridges: {crambin_bonds:?}"
        );
    }
}
