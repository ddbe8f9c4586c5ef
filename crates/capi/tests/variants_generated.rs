//! `src/variants.rs` is the output of `tools/gen_variants.py`: regenerating
//! it gives the checked-in file (edit the script's table, not the file).

use std::path::Path;
use std::process::Command;

#[test]
fn variants_rs_is_the_generator_output() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = Command::new("python3")
        .arg(dir.join("tools/gen_variants.py"))
        .output()
        .expect("python3 runs tools/gen_variants.py");
    assert!(
        out.status.success(),
        "gen_variants.py failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let generated = String::from_utf8(out.stdout).expect("UTF-8 output");
    let checked_in = std::fs::read_to_string(dir.join("src/variants.rs")).expect("src/variants.rs");
    assert!(
        generated == checked_in,
        "src/variants.rs differs from the generator's output: run \
         `python3 tools/gen_variants.py > src/variants.rs` in crates/capi"
    );
}
