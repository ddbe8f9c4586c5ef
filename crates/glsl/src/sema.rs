//! Semantic analysis: AST to typed IR. Work in progress.
use crate::ast::TranslationUnit;
use crate::diag::Diagnostic;
use crate::ir::{Module, Stage};
use crate::pp::ExtensionDirective;
use crate::token::Version;

pub struct Context {
    pub version: Version,
    pub stage: Stage,
    pub extensions: Vec<ExtensionDirective>,
}

pub fn analyze(_tu: &TranslationUnit, _ctx: &Context) -> (Module, Vec<Diagnostic>) {
    todo!("sema")
}
