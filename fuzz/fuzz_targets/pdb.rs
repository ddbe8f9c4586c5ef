//! Fuzzes the PDB reader (`render::parse_pdb`) on arbitrary bytes; a file
//! it accepts is checked and taken through bonds and camera framing
//! (`common/structure.rs`). Any panic, hang or out-of-memory is a bug.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "common/structure.rs"]
mod structure;

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = render::parse_pdb(data, "fuzz.pdb") {
        structure::check(&s);
    }
});
