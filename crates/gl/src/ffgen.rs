//! Fixed-function GLSL generation (being written).
