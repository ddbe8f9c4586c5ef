//! The IR validator. Work in progress.
use crate::diag::Diagnostic;
use crate::ir::Module;

pub fn validate(_m: &Module) -> Vec<Diagnostic> {
    Vec::new()
}
