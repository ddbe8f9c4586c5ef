//! The cdylib's ELF names: SONAME libEGL.so.1, so the one file serves as
//! libEGL.so.1, libGL.so.1 and libOpenGL.so.0 (symlinks, one inode: the
//! dynamic loader maps it once whichever name a program asks for first,
//! so EGL and GL share one current context), and -Bsymbolic, so the
//! library's own calls stay inside it when another libEGL.so.1 (libglvnd)
//! is loaded in the same process.
fn main() {
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libEGL.so.1");
    println!("cargo:rustc-cdylib-link-arg=-Wl,-Bsymbolic");
    println!("cargo:rerun-if-changed=build.rs");
}
