//! The GLSL preprocessor (GLSL 1.20 §3.3). Work in progress.
use crate::diag::Diagnostic;
use crate::ir::{ExtensionBehavior, Stage};
use crate::source::{SourceMap, Span};
use crate::token::{Token, Version};

pub struct PpOptions {
    pub stage: Stage,
}

/// An `#extension name : behavior` directive.
#[derive(Clone, Debug, PartialEq)]
pub struct ExtensionDirective {
    pub name: String,
    pub behavior: ExtensionBehavior,
    pub span: Span,
}

pub struct PpOutput {
    /// Parser tokens, ending with one `Eof` token.
    pub tokens: Vec<Token>,
    pub version: Version,
    pub extensions: Vec<ExtensionDirective>,
    pub diagnostics: Vec<Diagnostic>,
}

pub fn preprocess(_map: &mut SourceMap, _opts: &PpOptions) -> PpOutput {
    todo!("preprocessor")
}
