//! The parser: tokens to [`crate::ast`]. Work in progress.
use crate::ast::TranslationUnit;
use crate::diag::Diagnostic;
use crate::token::{Token, Version};

pub fn parse(_tokens: &[Token], _version: Version) -> (TranslationUnit, Vec<Diagnostic>) {
    todo!("parser")
}
