//! Unit tests of the analyzer (through `crate::compile`).
