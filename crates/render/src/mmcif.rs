//! A strict reader of the atoms of mmCIF (PDBx/mmCIF) files.
//!
//! Reads the first data block's `_atom_site` category, as a `loop_` or as
//! single `_atom_site.*` items (a one-atom file): `Cartn_x`, `Cartn_y`,
//! `Cartn_z` are required; the element comes from `type_symbol`, else the
//! first letter of the atom name (`auth_atom_id`, else `label_atom_id`);
//! the residue from `auth_comp_id` or `label_comp_id`; the serial from
//! `id`. Only the first model (`pdbx_PDB_model_num`) and, of alternate
//! locations (`label_alt_id`), blank (`.`/`?`) and the first one seen are
//! kept, as the PDB reader does. Everything else in the file is tokenised
//! (so a broken quote anywhere is reported) and skipped; bonds are not
//! read from mmCIF (`_struct_conn` is ignored: ball-and-stick finds bonds
//! by distance).
//!
//! Tokens follow CIF 1.1: whitespace-separated words, `'...'` and `"..."`
//! strings (closed by the quote followed by whitespace or the line end),
//! `;` text fields from a line starting with `;` to the next such line,
//! `#` comments. Errors name the file and the 1-based line: an unclosed
//! quote or text field, a loop whose value count is not a multiple of its
//! columns (a truncated file), a coordinate that is not a number, control
//! characters (binary data), text that is not UTF-8.
//!
//! Why not the `pdbtbx` crate, which the issue suggests: version 0.12
//! panics on some malformed input (`_cell.length_a ?` reaches an
//! `expect`; its lexer slices strings by byte offsets) and reports bad
//! atom rows by row number, not line, while this project promises file and
//! line and never panics. This reader is ~300 lines and reads only what a
//! renderer needs.

use crate::elements::Element;
use crate::structure::{Atom, LoadError, Structure, MAX_ATOMS};

/// One token and the line it starts on.
#[derive(Debug, PartialEq)]
struct Token<'a> {
    text: &'a str,
    line: usize,
    /// Quoted or a text field: never a keyword or a tag.
    quoted: bool,
}

fn malformed(file: &str, line: usize, message: impl Into<String>) -> LoadError {
    LoadError::Malformed {
        file: file.to_string(),
        line,
        message: message.into(),
    }
}

/// Splits CIF text into tokens.
fn tokenize<'a>(text: &'a str, file: &str) -> Result<Vec<Token<'a>>, LoadError> {
    let mut tokens = Vec::new();
    let lines: Vec<&str> = text.split('\n').collect();
    let mut i = 0;
    while i < lines.len() {
        let line_no = i + 1;
        let line = lines.get(i).copied().unwrap_or("");
        let line = line.strip_suffix('\r').unwrap_or(line);
        if let Some((col, c)) = line
            .char_indices()
            .find(|(_, c)| (c.is_control() && *c != '\t') || *c == '\u{7f}')
        {
            return Err(malformed(
                file,
                line_no,
                format!(
                    "control character U+{:04X} in column {}: binary data, not an mmCIF file",
                    c as u32,
                    col + 1
                ),
            ));
        }
        if let Some(first) = line.strip_prefix(';') {
            // Text field: up to the next line that starts with ';'.
            let start = line_no;
            let mut end = None;
            for (j, l) in lines.iter().enumerate().skip(i + 1) {
                if l.starts_with(';') {
                    end = Some(j);
                    break;
                }
            }
            let Some(end) = end else {
                return Err(malformed(
                    file,
                    start,
                    "text field opened by ';' here is never closed (truncated file?)",
                ));
            };
            tokens.push(Token {
                text: first,
                line: start,
                quoted: true,
            });
            // The closing line may carry more tokens after the ';'.
            let rest = lines.get(end).copied().unwrap_or("");
            tokenize_line(rest.get(1..).unwrap_or(""), end + 1, file, &mut tokens)?;
            i = end + 1;
            continue;
        }
        tokenize_line(line, line_no, file, &mut tokens)?;
        i += 1;
    }
    Ok(tokens)
}

/// Tokens of one line (no text fields).
fn tokenize_line<'a>(
    line: &'a str,
    line_no: usize,
    file: &str,
    out: &mut Vec<Token<'a>>,
) -> Result<(), LoadError> {
    let bytes = line.as_bytes();
    let mut p = 0;
    while p < bytes.len() {
        let b = bytes.get(p).copied().unwrap_or(b' ');
        if b == b' ' || b == b'\t' || b == b'\r' {
            p += 1;
            continue;
        }
        if b == b'#' {
            break;
        }
        if b == b'\'' || b == b'"' {
            // Closed by the same quote followed by whitespace or the end.
            let mut q = p + 1;
            let close = loop {
                match bytes.get(q) {
                    None => break None,
                    Some(c) if *c == b => {
                        let next = bytes.get(q + 1).copied();
                        if next.is_none() || matches!(next, Some(b' ' | b'\t' | b'\r')) {
                            break Some(q);
                        }
                    }
                    _ => {}
                }
                q += 1;
            };
            let Some(q) = close else {
                return Err(malformed(
                    file,
                    line_no,
                    format!("string opened by {} is not closed on its line", b as char),
                ));
            };
            out.push(Token {
                text: line.get(p + 1..q).unwrap_or(""),
                line: line_no,
                quoted: true,
            });
            p = q + 1;
            continue;
        }
        let mut q = p;
        while q < bytes.len() && !matches!(bytes.get(q), Some(b' ' | b'\t' | b'\r')) {
            q += 1;
        }
        out.push(Token {
            text: line.get(p..q).unwrap_or(""),
            line: line_no,
            quoted: false,
        });
        p = q;
    }
    Ok(())
}

/// Whether an unquoted token is a CIF reserved word or a tag (ends a loop).
fn is_keyword_or_tag(t: &Token) -> bool {
    if t.quoted {
        return false;
    }
    let lower = t.text.to_ascii_lowercase();
    t.text.starts_with('_')
        || lower == "loop_"
        || lower == "stop_"
        || lower == "global_"
        || lower.starts_with("data_")
        || lower.starts_with("save_")
}

/// The `_atom_site` table: column names (lower case, without the
/// category) and rows of (values, line).
struct AtomSite<'a> {
    columns: Vec<String>,
    rows: Vec<(Vec<&'a Token<'a>>, usize)>,
}

/// Finds `_atom_site` in the first data block.
fn atom_site<'a>(tokens: &'a [Token<'a>], file: &str) -> Result<Option<AtomSite<'a>>, LoadError> {
    let mut i = 0;
    let mut blocks = 0;
    let mut singles: Vec<(String, &Token)> = Vec::new();
    let mut single_line = 0;
    let mut table: Option<AtomSite> = None;
    while let Some(t) = tokens.get(i) {
        let lower = t.text.to_ascii_lowercase();
        if !t.quoted && lower.starts_with("data_") {
            blocks += 1;
            if blocks > 1 {
                break;
            }
            i += 1;
            continue;
        }
        if !t.quoted && lower == "loop_" {
            let loop_line = t.line;
            i += 1;
            let mut columns = Vec::new();
            while let Some(tag) = tokens.get(i) {
                if tag.quoted || !tag.text.starts_with('_') {
                    break;
                }
                columns.push(tag.text.to_ascii_lowercase());
                i += 1;
            }
            if columns.is_empty() {
                return Err(malformed(file, loop_line, "loop_ without column names"));
            }
            let start = i;
            while let Some(v) = tokens.get(i) {
                if is_keyword_or_tag(v) {
                    break;
                }
                i += 1;
            }
            let values = tokens.get(start..i).unwrap_or(&[]);
            let is_atom_site = columns.iter().all(|c| c.starts_with("_atom_site."));
            if values.len() % columns.len() != 0 {
                let last = values.last().map_or(loop_line, |v| v.line);
                return Err(malformed(
                    file,
                    last,
                    format!(
                        "the loop_ of line {loop_line} has {} values, not a multiple of its {} columns (truncated file or a missing value)",
                        values.len(),
                        columns.len()
                    ),
                ));
            }
            if is_atom_site && table.is_none() {
                let rows = values
                    .chunks(columns.len())
                    .map(|row| {
                        (
                            row.iter().collect::<Vec<_>>(),
                            row.first().map_or(0, |v| v.line),
                        )
                    })
                    .collect();
                let columns = columns
                    .iter()
                    .map(|c| c.trim_start_matches("_atom_site.").to_string())
                    .collect();
                table = Some(AtomSite { columns, rows });
            }
            continue;
        }
        if !t.quoted && t.text.starts_with('_') {
            let Some(value) = tokens.get(i + 1).filter(|v| !is_keyword_or_tag(v)) else {
                return Err(malformed(
                    file,
                    t.line,
                    format!("item {} has no value", t.text),
                ));
            };
            if let Some(name) = lower.strip_prefix("_atom_site.") {
                if singles.is_empty() {
                    single_line = t.line;
                }
                singles.push((name.to_string(), value));
            }
            i += 2;
            continue;
        }
        i += 1;
    }
    if table.is_none() && !singles.is_empty() {
        let (columns, values): (Vec<String>, Vec<&Token>) = singles.into_iter().unzip();
        table = Some(AtomSite {
            columns,
            rows: vec![(values, single_line)],
        });
    }
    Ok(table)
}

/// Parses mmCIF text; `source` names it in errors.
pub fn parse_mmcif(bytes: &[u8], source: &str) -> Result<Structure, LoadError> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let line = bytes
            .get(..e.valid_up_to())
            .map_or(1, |b| b.iter().filter(|c| **c == b'\n').count() + 1);
        malformed(source, line, "text that is not UTF-8: not an mmCIF file")
    })?;
    let tokens = tokenize(text, source)?;
    let empty = || LoadError::Empty {
        file: source.to_string(),
    };
    let table = atom_site(&tokens, source)?.ok_or_else(empty)?;
    let col = |name: &str| table.columns.iter().position(|c| c == name);
    let first = |names: &[&str]| names.iter().find_map(|n| col(n));
    let (Some(cx), Some(cy), Some(cz)) = (col("cartn_x"), col("cartn_y"), col("cartn_z")) else {
        let line = table.rows.first().map_or(1, |r| r.1);
        return Err(malformed(
            source,
            line,
            "_atom_site has no Cartn_x, Cartn_y and Cartn_z columns",
        ));
    };
    let c_symbol = col("type_symbol");
    let c_name = first(&["auth_atom_id", "label_atom_id"]);
    let c_residue = first(&["auth_comp_id", "label_comp_id"]);
    let c_model = col("pdbx_pdb_model_num");
    let c_alt = col("label_alt_id");
    let c_id = col("id");
    let missing = |v: &str| v == "." || v == "?";

    let mut atoms = Vec::new();
    let mut first_model: Option<String> = None;
    let mut alt_seen: Option<String> = None;
    for (row, line) in &table.rows {
        let get = |c: Option<usize>| -> &str { c.and_then(|c| row.get(c)).map_or("", |t| t.text) };
        if let Some(model) = c_model.map(|c| get(Some(c))) {
            match &first_model {
                None => first_model = Some(model.to_string()),
                Some(m) if m != model => continue,
                Some(_) => {}
            }
        }
        let alt = get(c_alt);
        if !alt.is_empty() && !missing(alt) {
            match &alt_seen {
                None => alt_seen = Some(alt.to_string()),
                Some(a) if a != alt => continue,
                Some(_) => {}
            }
        }
        let coord = |c: usize, axis: &str| -> Result<f32, LoadError> {
            let t = row.get(c);
            let (v, l) = t.map_or(("", *line), |t| (t.text, t.line));
            match v.parse::<f32>() {
                Ok(x) if x.is_finite() => Ok(x),
                _ => Err(malformed(
                    source,
                    l,
                    format!("{axis} coordinate (_atom_site.Cartn_{axis}) is not a number: {v:?}"),
                )),
            }
        };
        let position = [coord(cx, "x")?, coord(cy, "y")?, coord(cz, "z")?];
        let name = get(c_name);
        let symbol = get(c_symbol);
        let element = Element::from_symbol(symbol)
            .or_else(|| name.get(0..1).and_then(Element::from_symbol))
            .unwrap_or(Element::UNKNOWN);
        if atoms.len() >= MAX_ATOMS {
            return Err(LoadError::TooManyAtoms {
                file: source.to_string(),
            });
        }
        atoms.push(Atom {
            element,
            position,
            name: if missing(name) {
                String::new()
            } else {
                name.to_string()
            },
            residue: get(c_residue).to_string(),
            line: *line,
            serial: get(c_id).parse().ok(),
        });
    }
    if atoms.is_empty() {
        return Err(empty());
    }
    Ok(Structure {
        source: source.to_string(),
        atoms,
        conect: Vec::new(),
    })
}

/// Whether the first non-blank text is `data_` (an mmCIF data block).
pub(crate) fn is_mmcif(bytes: &[u8]) -> bool {
    let first_text = bytes
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .map_or(&[][..], |p| &bytes[p..]);
    first_text.starts_with(b"data_")
}

#[cfg(test)]
mod tests {
    use crate::load::{crambin, parse};

    const CIF: &str = "data_TEST
# a comment
_entry.id TEST
_struct.title 'a title with ''quotes'' inside'
loop_
_atom_site.group_PDB
_atom_site.id
_atom_site.type_symbol
_atom_site.label_atom_id
_atom_site.label_alt_id
_atom_site.label_comp_id
_atom_site.Cartn_x
_atom_site.Cartn_y
_atom_site.Cartn_z
_atom_site.pdbx_PDB_model_num
ATOM 1 N N . THR 17.047 14.099 3.625 1
ATOM 2 C CA A THR 16.967 12.784 4.338 1
ATOM 3 C CA B THR 16.000 12.000 4.000 1
HETATM 4 FE FE . HEM 1.0 2.0 3.0 1
ATOM 5 N N . THR 0 0 0 2
#
loop_
_other.a
_other.b
;
a text field
;
x
";

    #[test]
    fn reads_atom_site() {
        let s = parse(CIF.as_bytes(), "t.cif").unwrap();
        assert_eq!(s.atoms.len(), 3, "altloc B and model 2 skipped");
        assert_eq!(s.atoms[0].element.symbol(), "N");
        assert_eq!(s.atoms[0].position, [17.047, 14.099, 3.625]);
        assert_eq!(s.atoms[0].line, 16);
        assert_eq!(s.atoms[1].name, "CA");
        assert_eq!(s.atoms[2].element.symbol(), "Fe");
        assert_eq!(s.atoms[2].serial, Some(4));
        assert_eq!(s.atoms[2].residue, "HEM");
    }

    #[test]
    fn same_atoms_as_pdb() {
        // Crambin written as mmCIF gives the PDB reader's atoms.
        let pdb = crambin();
        let mut cif = String::from(
            "data_1CRN\nloop_\n_atom_site.id\n_atom_site.type_symbol\n_atom_site.label_atom_id\n_atom_site.Cartn_x\n_atom_site.Cartn_y\n_atom_site.Cartn_z\n",
        );
        for a in &pdb.atoms {
            let [x, y, z] = a.position;
            cif += &format!(
                "{} {} {} {x} {y} {z}\n",
                a.serial.unwrap(),
                a.element.symbol(),
                a.name
            );
        }
        let s = parse(cif.as_bytes(), "1crn.cif").unwrap();
        assert_eq!(s.atoms.len(), pdb.atoms.len());
        for (a, b) in s.atoms.iter().zip(&pdb.atoms) {
            assert_eq!((a.element, a.position), (b.element, b.position));
        }
    }

    #[test]
    fn errors_name_file_and_line() {
        let cut = &CIF[..CIF.find("ATOM 2").unwrap() + 20];
        let m = parse(cut.as_bytes(), "cut.cif").unwrap_err().to_string();
        assert!(m.starts_with("cut.cif:17: the loop_ of line 5 has"), "{m}");
        let bad = CIF.replace("16.967", "16.9x7");
        let m = parse(bad.as_bytes(), "b.cif").unwrap_err().to_string();
        assert!(
            m.starts_with("b.cif:17: x coordinate (_atom_site.Cartn_x)"),
            "{m}"
        );
        let quote = CIF.replace("'a title", "'a title\n");
        let m = parse(quote.as_bytes(), "q.cif").unwrap_err().to_string();
        assert!(m.starts_with("q.cif:4: string opened by '"), "{m}");
        let field = CIF.replace(";\nx\n", "x\n");
        let m = parse(field.as_bytes(), "f.cif").unwrap_err().to_string();
        assert!(m.starts_with("f.cif:25: text field"), "{m}");
        let m = parse(b"data_X\n_cell.length_a ?\n", "e.cif").unwrap_err();
        assert_eq!(
            m.to_string(),
            "e.cif: has no atoms (no ATOM or HETATM records)"
        );
        let m = parse(b"data_X\n_atom_site.id\n", "n.cif")
            .unwrap_err()
            .to_string();
        assert!(
            m.starts_with("n.cif:2: item _atom_site.id has no value"),
            "{m}"
        );
        let m = parse(b"data_X\n\x01\n", "bin.cif").unwrap_err().to_string();
        assert!(m.starts_with("bin.cif:2: control character"), "{m}");
        let m = parse(b"data_X\n\xff\n", "u.cif").unwrap_err().to_string();
        assert!(m.starts_with("u.cif:2: text that is not UTF-8"), "{m}");
        let m = parse(b"data_X\nloop_\n_atom_site.id\n1\n", "c.cif")
            .unwrap_err()
            .to_string();
        assert!(m.contains("no Cartn_x"), "{m}");
    }

    #[test]
    fn single_item_atom() {
        let one = "data_X\n_atom_site.type_symbol O\n_atom_site.Cartn_x 1\n_atom_site.Cartn_y 2\n_atom_site.Cartn_z 3\n";
        let s = parse(one.as_bytes(), "o.cif").unwrap();
        assert_eq!(s.atoms.len(), 1);
        assert_eq!(s.atoms[0].element.symbol(), "O");
    }

    #[test]
    fn no_panic_on_prefixes() {
        // Every prefix of a valid file parses or fails cleanly.
        for end in 0..CIF.len() {
            if let Some(prefix) = CIF.get(..end) {
                let _ = parse(prefix.as_bytes(), "p.cif");
            }
        }
    }
}
