//! Fuzzes the mmCIF reader (`render::mmcif::parse_mmcif`) on arbitrary
//! bytes, and the format sniffing of `render::parse` that chooses between
//! the readers; a file either accepts is checked and taken through bonds
//! and camera framing (`common/structure.rs`). Any panic, hang or
//! out-of-memory is a bug.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "common/structure.rs"]
mod structure;

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = render::mmcif::parse_mmcif(data, "fuzz.cif") {
        structure::check(&s);
    }
    if let Ok(s) = render::parse(data, "fuzz") {
        structure::check(&s);
    }
});
