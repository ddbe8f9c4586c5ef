//! The directives of GLSL 1.20 §3.3, one method each.
//!
//! Conditional directives are processed in skipped regions too (to track
//! nesting); every other directive, including unknown or malformed ones,
//! is ignored there.

use super::expr::{unexpected, ExprParser};
use super::macros::{Macro, PTok, BUILTIN_MACROS};
use super::{Cond, ExtensionDirective, Line, Preprocessor};
use crate::diag::{did_you_mean, Code, Diagnostic};
use crate::ir::ExtensionBehavior;
use crate::lang::{Extension, ExtensionSet, Feature, Language, Profile, Version};
use crate::lex::{PpKind, PpToken};
use crate::limits;
use crate::source::Span;
use crate::token::Punct;
use smol_str::SmolStr;

const DIRECTIVES: &[&str] = &[
    "define",
    "undef",
    "if",
    "ifdef",
    "ifndef",
    "else",
    "elif",
    "endif",
    "error",
    "pragma",
    "extension",
    "version",
    "line",
];

/// The parts of a directive line.
struct Directive<'a> {
    /// `#` through the directive name.
    span: Span,
    /// The tokens after the name.
    rest: &'a [PpToken],
    /// An empty span at the end of the line.
    end: Span,
}

impl Directive<'_> {
    /// The whole directive line.
    fn full_span(&self) -> Span {
        self.rest.last().map_or(self.span, |t| self.span.to(t.span))
    }
}

fn is_punct(t: Option<&PpToken>, p: Punct) -> bool {
    t.is_some_and(|t| t.kind == PpKind::Punct(p))
}

fn found(t: Option<&PpToken>) -> String {
    match t {
        Some(t) => format!("`{}'", t.text),
        None => "the end of the line".to_string(),
    }
}

impl Preprocessor<'_> {
    /// Runs one directive line (its first token is `#`).
    pub(super) fn directive(&mut self, line: &Line) {
        let toks = &line.toks;
        let Some(name) = toks.get(1) else {
            return; // The null directive.
        };
        let d = Directive {
            span: toks[0].span.to(name.span),
            rest: &toks[2..],
            end: Span::new(line.end, line.end),
        };
        if name.kind != PpKind::Ident {
            if self.active() {
                self.diags.push(Diagnostic::error(
                    Code::PpSyntax,
                    d.span,
                    format!("expected a directive name after `#', found `{}'", name.text),
                ));
            }
            return;
        }
        match name.text.as_str() {
            "if" => self.d_if(&d),
            "ifdef" => self.d_ifdef(&d, true),
            "ifndef" => self.d_ifdef(&d, false),
            "elif" => self.d_elif(&d),
            "else" => self.d_else(&d),
            "endif" => self.d_endif(&d),
            _ if !self.active() => {}
            "define" => self.d_define(&d),
            "undef" => self.d_undef(&d),
            "error" => self.d_error(&d),
            "pragma" => self.d_pragma(&d),
            "extension" => self.d_extension(&d),
            "version" => self.d_version(&d),
            "line" => self.d_line(&d),
            other => {
                let mut diag = Diagnostic::error(
                    Code::PpSyntax,
                    d.span,
                    format!("unknown preprocessor directive `#{other}'"),
                );
                if let Some(s) = did_you_mean(other, DIRECTIVES.iter().copied()) {
                    diag = diag.with_note(format!("did you mean `#{s}'?"));
                }
                self.diags.push(diag);
            }
        }
    }

    fn is_defined(&self, name: &str) -> bool {
        self.macros.contains_key(name) || BUILTIN_MACROS.contains(&name)
    }

    fn warn_extra(&mut self, d: &Directive, what: &str) {
        if let Some(t) = d.rest.first() {
            let span = t.span.to(d.rest.last().map_or(t.span, |l| l.span));
            self.diags.push(Diagnostic::warning(
                Code::PpSyntax,
                span,
                format!("extra tokens at the end of #{what}; they are ignored"),
            ));
        }
    }

    fn push_cond(&mut self, span: Span, active: bool) {
        if self.conds.len() >= limits::MAX_NESTING_DEPTH as usize {
            self.diags.push(Diagnostic::error(
                Code::PpConditional,
                span,
                format!(
                    "conditional directives nest too deeply (the limit is {})",
                    limits::MAX_NESTING_DEPTH
                ),
            ));
        }
        let parent_active = self.active();
        self.conds.push(Cond {
            span,
            parent_active,
            active: parent_active && active,
            taken: !parent_active || active,
            else_seen: None,
        });
    }

    fn d_if(&mut self, d: &Directive) {
        let value = self.active() && self.condition(d, "if");
        self.push_cond(d.span, value);
    }

    fn d_ifdef(&mut self, d: &Directive, want: bool) {
        let what = if want { "ifdef" } else { "ifndef" };
        let mut value = false;
        if self.active() {
            match d.rest.first() {
                Some(t) if t.kind == PpKind::Ident => {
                    value = self.is_defined(&t.text) == want;
                    let extra = Directive {
                        rest: &d.rest[1..],
                        ..*d
                    };
                    self.warn_extra(&extra, what);
                }
                other => self.diags.push(Diagnostic::error(
                    Code::PpSyntax,
                    other.map_or(d.end, |t| t.span),
                    format!(
                        "expected a macro name after #{what}, found {}",
                        found(other)
                    ),
                )),
            }
        }
        self.push_cond(d.span, value);
    }

    fn d_elif(&mut self, d: &Directive) {
        let Some(c) = self.conds.last().cloned() else {
            self.diags.push(Diagnostic::error(
                Code::PpConditional,
                d.span,
                "#elif without a matching #if",
            ));
            return;
        };
        if let Some(else_span) = c.else_seen {
            if c.parent_active {
                self.diags.push(
                    Diagnostic::error(Code::PpConditional, d.span, "#elif after #else")
                        .with_label(else_span, "the #else is here"),
                );
            }
            self.set_branch(false, false);
            return;
        }
        if !c.parent_active || c.taken {
            // Not evaluated: an earlier branch was taken (C++ [cpp.cond]).
            self.set_branch(false, true);
            return;
        }
        let value = self.condition(d, "elif");
        self.set_branch(value, value);
    }

    /// Sets the innermost conditional's current branch.
    fn set_branch(&mut self, active: bool, taken: bool) {
        if let Some(c) = self.conds.last_mut() {
            c.active = c.parent_active && active;
            c.taken |= taken;
        }
    }

    fn d_else(&mut self, d: &Directive) {
        let Some(c) = self.conds.last().cloned() else {
            self.diags.push(Diagnostic::error(
                Code::PpConditional,
                d.span,
                "#else without a matching #if",
            ));
            return;
        };
        if let Some(else_span) = c.else_seen {
            if c.parent_active {
                self.diags.push(
                    Diagnostic::error(Code::PpConditional, d.span, "#else after #else")
                        .with_label(else_span, "the first #else is here"),
                );
            }
            self.set_branch(false, true);
            return;
        }
        if c.parent_active {
            self.warn_extra(d, "else");
        }
        let take = !c.taken;
        self.set_branch(take, true);
        if let Some(c) = self.conds.last_mut() {
            c.else_seen = Some(d.span);
        }
    }

    fn d_endif(&mut self, d: &Directive) {
        match self.conds.pop() {
            Some(c) => {
                if c.parent_active {
                    self.warn_extra(d, "endif");
                }
            }
            None => self.diags.push(Diagnostic::error(
                Code::PpConditional,
                d.span,
                "#endif without a matching #if",
            )),
        }
    }

    /// Evaluates the expression of an `#if`/`#elif`; false after an error.
    fn condition(&mut self, d: &Directive, what: &str) -> bool {
        if d.rest.is_empty() {
            self.diags.push(Diagnostic::error(
                Code::PpSyntax,
                d.span,
                format!("#{what} needs an expression"),
            ));
            return false;
        }
        let toks = match self.replace_defined(d.rest) {
            Ok(t) => t,
            Err(diag) => {
                self.diags.push(diag);
                return false;
            }
        };
        let expanded = self.expander(true).expand(toks);
        let macros = &self.macros;
        let is_defined = |n: &str| macros.contains_key(n) || BUILTIN_MACROS.contains(&n);
        let mut p = ExprParser::new(&expanded, d.end, &is_defined);
        let result = p.expression().and_then(|v| {
            if p.at_end() {
                Ok(v)
            } else {
                Err(unexpected(
                    p.peek(),
                    d.end,
                    "an operator or the end of the line",
                ))
            }
        });
        self.diags.extend(p.take_warnings());
        match result {
            Ok(v) => v != 0,
            Err(diag) => {
                self.diags.push(diag);
                false
            }
        }
    }

    /// Replaces `defined X` and `defined ( X )` by 1 or 0 before macro
    /// expansion, so that `X` itself is not expanded.
    fn replace_defined(&self, toks: &[PpToken]) -> Result<Vec<PTok>, Diagnostic> {
        let mut out = Vec::with_capacity(toks.len());
        let mut i = 0;
        while let Some(t) = toks.get(i) {
            if t.kind != PpKind::Ident || t.text != "defined" {
                out.push(PTok::from(t.clone()));
                i += 1;
                continue;
            }
            let paren = is_punct(toks.get(i + 1), Punct::LeftParen);
            let name_at = if paren { i + 2 } else { i + 1 };
            let name = match toks.get(name_at) {
                Some(n) if n.kind == PpKind::Ident => n,
                other => {
                    return Err(Diagnostic::error(
                        Code::PpSyntax,
                        other.map_or(t.span, |o| o.span),
                        format!(
                            "expected a macro name after `defined', found {}",
                            found(other)
                        ),
                    ))
                }
            };
            let mut last = name.span;
            i = name_at + 1;
            if paren {
                let close = toks.get(i);
                if !is_punct(close, Punct::RightParen) {
                    return Err(Diagnostic::error(
                        Code::PpSyntax,
                        close.map_or(name.span, |c| c.span),
                        format!(
                            "expected `)' after `defined({}', found {}",
                            name.text,
                            found(close)
                        ),
                    ));
                }
                last = close.map_or(last, |c| c.span);
                i += 1;
            }
            let value = u64::from(self.is_defined(&name.text));
            out.push(PTok::number(value, t.span.to(last), t.space_before));
        }
        Ok(out)
    }

    /// Checks a name given to `#define`/`#undef` (§3.3 reserves `GL_`
    /// prefixes and names containing `__`). False when it may not be used.
    fn check_macro_name(&mut self, name: &PpToken, what: &str) -> bool {
        let text = name.text.as_str();
        let problem = if text == "defined" {
            Some("`defined' cannot be used as a macro name".to_string())
        } else if BUILTIN_MACROS.contains(&text) {
            Some(format!("cannot {what} the built-in macro `{text}'"))
        } else if text.starts_with("GL_") {
            Some(format!(
                "cannot {what} `{text}': macro names starting with `GL_' are reserved (§3.3)"
            ))
        } else {
            None
        };
        if let Some(msg) = problem {
            self.diags
                .push(Diagnostic::error(Code::PpMacro, name.span, msg));
            return false;
        }
        if text.contains("__") {
            self.diags.push(Diagnostic::warning(
                Code::PpMacro,
                name.span,
                format!(
                    "macro name `{text}' contains `__'; such names are reserved for the \
                     implementation (§3.3)"
                ),
            ));
        }
        true
    }

    /// The macro name of a `#define`/`#undef`, or an error.
    fn macro_name<'t>(&mut self, d: &Directive<'t>, what: &str) -> Option<&'t PpToken> {
        match d.rest.first() {
            Some(t) if t.kind == PpKind::Ident => self.check_macro_name(t, what).then_some(t),
            other => {
                self.diags.push(Diagnostic::error(
                    Code::PpSyntax,
                    other.map_or(d.end, |t| t.span),
                    format!(
                        "expected a macro name after #{what}, found {}",
                        found(other)
                    ),
                ));
                None
            }
        }
    }

    fn d_define(&mut self, d: &Directive) {
        let Some(name) = self.macro_name(d, "define") else {
            return;
        };
        let after = &d.rest[1..];
        // `#define F(x)` is function-like; `#define F (x)` is not.
        let (params, body) = match after.first() {
            Some(t) if t.kind == PpKind::Punct(Punct::LeftParen) && !t.space_before => {
                match self.parse_params(after, d.end) {
                    Some((params, used)) => (Some(params), &after[used..]),
                    None => return,
                }
            }
            _ => (None, after),
        };
        if !self.check_operators(body) {
            return;
        }
        let mac = Macro {
            params,
            body: body.to_vec(),
            name_span: name.span,
        };
        if let Some(old) = self.macros.get(&name.text) {
            if !old.same_definition(&mac) {
                self.diags.push(
                    Diagnostic::error(
                        Code::PpMacro,
                        name.span,
                        format!(
                            "macro `{}' redefined with a different definition",
                            name.text
                        ),
                    )
                    .with_label(old.name_span, "previous definition")
                    .with_note("use #undef first to change a macro"),
                );
            }
            return;
        }
        self.function_like += usize::from(mac.params.is_some());
        self.macros.insert(name.text.clone(), mac);
    }

    /// Checks the `#` and `##` in a replacement list: `#` (stringizing)
    /// never exists, since GLSL has no strings; `##` (token pasting) exists
    /// from GLSL 1.30 on and needs an operand on each side (C++
    /// [cpp.concat]). Reports the first problem.
    fn check_operators(&mut self, body: &[PpToken]) -> bool {
        for (i, t) in body.iter().enumerate() {
            let d = match t.kind {
                PpKind::Hash => Diagnostic::error(
                    Code::PpMacro,
                    t.span,
                    "`#' is not allowed in a macro definition",
                )
                .with_note("GLSL has no stringizing operator: it has no strings (§3.3)"),
                PpKind::HashHash => match self.lang.gate(Feature::TokenPasting) {
                    Err(why) => {
                        Diagnostic::error(Code::PpMacro, t.span, why.message("`##'", self.lang))
                            .with_note(why.fix())
                    }
                    Ok(()) if i == 0 || i + 1 == body.len() => Diagnostic::error(
                        Code::PpMacro,
                        t.span,
                        format!(
                            "`##' cannot be at the {} of a macro's replacement list",
                            if i == 0 { "start" } else { "end" }
                        ),
                    )
                    .with_note("`##' pastes the tokens on its two sides into one"),
                    Ok(()) => continue,
                },
                _ => continue,
            };
            self.diags.push(d);
            return false;
        }
        true
    }

    /// Parses `( a, b )` at the start of `toks`: the parameter names and how
    /// many tokens they took.
    fn parse_params(&mut self, toks: &[PpToken], end: Span) -> Option<(Vec<SmolStr>, usize)> {
        let mut params: Vec<SmolStr> = Vec::new();
        let mut i = 1;
        if is_punct(toks.get(i), Punct::RightParen) {
            return Some((params, i + 1));
        }
        loop {
            let t = toks.get(i);
            match t {
                Some(p) if p.kind == PpKind::Ident => {
                    if params.contains(&p.text) {
                        self.diags.push(Diagnostic::error(
                            Code::PpMacro,
                            p.span,
                            format!("duplicate macro parameter `{}'", p.text),
                        ));
                        return None;
                    }
                    params.push(p.text.clone());
                }
                other => {
                    self.diags.push(Diagnostic::error(
                        Code::PpMacro,
                        other.map_or(end, |t| t.span),
                        format!("expected a parameter name, found {}", found(other)),
                    ));
                    return None;
                }
            }
            i += 1;
            let sep = toks.get(i);
            if is_punct(sep, Punct::RightParen) {
                return Some((params, i + 1));
            }
            if !is_punct(sep, Punct::Comma) {
                self.diags.push(Diagnostic::error(
                    Code::PpMacro,
                    sep.map_or(end, |t| t.span),
                    format!(
                        "expected `,' or `)' in the macro parameter list, found {}",
                        found(sep)
                    ),
                ));
                return None;
            }
            i += 1;
        }
    }

    fn d_undef(&mut self, d: &Directive) {
        let Some(name) = self.macro_name(d, "undef") else {
            return;
        };
        if let Some(m) = self.macros.remove(&name.text) {
            self.function_like -= usize::from(m.params.is_some());
        }
        let extra = Directive {
            rest: &d.rest[1..],
            ..*d
        };
        self.warn_extra(&extra, "undef");
    }

    /// `#error`: the rest of the line, as written, becomes the message.
    fn d_error(&mut self, d: &Directive) {
        let message = match (d.rest.first(), d.rest.last()) {
            (Some(a), Some(b)) => format!("#error {}", self.map.slice(a.span.to(b.span))),
            _ => "#error".to_string(),
        };
        self.diags
            .push(Diagnostic::error(Code::PpUserError, d.full_span(), message));
    }

    /// `#pragma`: not macro-expanded; `optimize` and `debug` are checked,
    /// anything else is ignored (§3.3).
    fn d_pragma(&mut self, d: &Directive) {
        let Some(first) = d.rest.first() else {
            return;
        };
        let name = first.text.as_str();
        // GLSL 1.20 §4.6.1: `#pragma STDGL invariant(all)` makes every
        // output invariant.
        let texts: Vec<&str> = d.rest.iter().map(|t| t.text.as_str()).collect();
        if texts == ["STDGL", "invariant", "(", "all", ")"] {
            self.invariant_all = true;
            return;
        }
        if name != "optimize" && name != "debug" {
            return;
        }
        let well_formed = d.rest.len() == 4
            && is_punct(d.rest.get(1), Punct::LeftParen)
            && d.rest
                .get(2)
                .is_some_and(|t| t.text == "on" || t.text == "off")
            && is_punct(d.rest.get(3), Punct::RightParen);
        if !well_formed {
            self.diags.push(Diagnostic::warning(
                Code::PpSyntax,
                d.full_span(),
                format!("malformed `#pragma {name}' is ignored; write `#pragma {name}(on)' or `#pragma {name}(off)'"),
            ));
        } else if self.braces.in_function {
            self.diags.push(Diagnostic::error(
                Code::PpSyntax,
                d.full_span(),
                format!("`#pragma {name}' can only be used outside function definitions (§3.3)"),
            ));
        }
    }

    /// `#version N [profile]`: must come first, once (§3.3); a profile word
    /// only from 1.50 on.
    /// GL 3.2+ core contexts remove GLSL 1.10 and 1.20 (GL 3.3 core
    /// appendix E.2.2), whether chosen by `#version` or by its absence.
    pub(super) fn check_core_version(&mut self) {
        let v = self.lang.version;
        if self.compatibility_context || v >= Version::V130 {
            return;
        }
        let span = self.version_span.unwrap_or(Span::new(0, 0));
        let how = if self.version_span.is_some() {
            format!("`#version {}'", v.number())
        } else {
            "no #version (so GLSL 1.10)".to_string()
        };
        self.diags.push(
            Diagnostic::error(
                Code::PpVersion,
                span,
                format!(
                    "GLSL {} is not available in a core-profile context: the shader asks for it \
                     with {how}",
                    v.dotted()
                ),
            )
            .with_note(
                "core profiles accept GLSL 1.30 and later: start the shader with \
                 `#version 330 core' (or 130/140/150), or create a compatibility-profile context",
            ),
        );
    }

    fn d_version(&mut self, d: &Directive) {
        if let Some(first) = self.version_span {
            self.diags.push(
                Diagnostic::error(Code::PpVersion, d.span, "#version may appear only once")
                    .with_label(first, "the first #version is here"),
            );
            return;
        }
        self.version_span = Some(d.span);
        if self.seen_content {
            self.diags.push(Diagnostic::error(
                Code::PpVersion,
                d.span,
                "#version must come before anything else in the shader except comments and \
                 whitespace",
            ));
        }
        let number = match d.rest.first() {
            Some(t) if t.kind == PpKind::Number => t,
            other => {
                self.diags.push(Diagnostic::error(
                    Code::PpVersion,
                    other.map_or(d.end, |t| t.span),
                    format!(
                        "expected a version number after #version, found {}",
                        found(other)
                    ),
                ));
                return;
            }
        };
        let version = number
            .text
            .parse::<u32>()
            .ok()
            .filter(|_| number.text.bytes().all(|b| b.is_ascii_digit()))
            .and_then(Version::from_number);
        let Some(version) = version else {
            self.diags.push(
                Diagnostic::error(
                    Code::PpVersion,
                    number.span,
                    format!("GLSL version `{}' is not supported", number.text),
                )
                .with_note(format!(
                    "supported versions are {} (110 is the default)",
                    Version::ALL.map(|v| v.number().to_string()).join(", ")
                )),
            );
            return;
        };
        let mut lang = Language::new(version, self.compatibility_context);
        lang.extensions = self.lang.extensions;
        if let Some(extra) = d.rest.get(1) {
            let profile = match extra.text.as_str() {
                "core" => Some(Profile::Core),
                "compatibility" => Some(Profile::Compatibility),
                _ => None,
            };
            let problem = match (profile, extra.text.as_str()) {
                (_, "es") => {
                    Some("GLSL ES is not supported (`es' after the version number)".to_string())
                }
                (Some(_), _) if !version.has_profiles() => Some(format!(
                    "profile `{}' is not allowed: profiles exist only from GLSL 1.50 on",
                    extra.text
                )),
                (Some(Profile::Compatibility), _) if !self.compatibility_context => Some(
                    "the compatibility profile is not available in a core-profile context"
                        .to_string(),
                ),
                (Some(_), _) => None,
                (None, other) => Some(format!("unexpected `{other}' after the version number")),
            };
            if let Some(msg) = problem {
                let note = if version.has_profiles() {
                    format!(
                        "write `#version {0}', `#version {0} core' or `#version {0} compatibility'",
                        version.number()
                    )
                } else {
                    format!("write `#version {}'", version.number())
                };
                self.diags
                    .push(Diagnostic::error(Code::PpVersion, extra.span, msg).with_note(note));
                return;
            }
            if let Some(p) = profile {
                lang.profile = p;
            }
            if let Some(more) = d.rest.get(2) {
                self.diags.push(Diagnostic::error(
                    Code::PpVersion,
                    more.span,
                    format!("unexpected `{}' after the profile", more.text),
                ));
                return;
            }
        }
        self.set_language(lang);
    }

    /// `#extension name : behavior` (§3.3; not macro-expanded).
    fn d_extension(&mut self, d: &Directive) {
        let Some((name, behavior)) = self.parse_extension(d) else {
            return;
        };
        let span = d.full_span();
        let is_all = name.text == "all";
        // GL_ARB_compatibility exists only in a context that has the
        // compatibility profile.
        let known = Extension::from_name(&name.text)
            .filter(|&e| e != Extension::ArbCompatibility || self.compatibility_context)
            .filter(|&e| self.lang.version >= e.since())
            .filter(|&e| !self.withheld.contains(e));
        let supported = known.is_some();
        if is_all
            && matches!(
                behavior,
                ExtensionBehavior::Require | ExtensionBehavior::Enable
            )
        {
            self.diags.push(Diagnostic::error(
                Code::PpExtension,
                span,
                "`#extension all' can only be used with `warn' or `disable'",
            ));
            return;
        }
        if !is_all && !supported {
            if behavior == ExtensionBehavior::Require {
                let mut d = Diagnostic::error(
                    Code::PpExtension,
                    name.span,
                    format!("extension `{}' is required but not supported", name.text),
                );
                if let Some(e) =
                    Extension::from_name(&name.text).filter(|e| self.lang.version < e.since())
                {
                    d = d.with_note(format!(
                        "shaderbox offers it from GLSL {} on (`#version {}')",
                        e.since().dotted(),
                        e.since().number()
                    ));
                }
                self.diags.push(d);
                return;
            }
            self.diags.push(Diagnostic::warning(
                Code::PpExtension,
                name.span,
                format!("extension `{}' is not supported", name.text),
            ));
        }
        if !self.out.is_empty() {
            self.diags.push(Diagnostic::warning(
                Code::PpExtension,
                span,
                "#extension should come before any shader code (§3.3)",
            ));
        }
        // `enable`, `require` and `warn` turn a named extension on;
        // `disable` turns it (or, for `all`, every one) off. `all : warn`
        // only changes how uses are reported.
        let on = behavior != ExtensionBehavior::Disable;
        match known {
            Some(e) => {
                self.lang.extensions.set(e, on);
                if e == Extension::ArbCompatibility && on {
                    self.lang.profile = Profile::Compatibility;
                }
            }
            None if is_all && !on => self.lang.extensions = ExtensionSet::EMPTY,
            None => {}
        }
        self.extensions.push(ExtensionDirective {
            name: name.text.to_string(),
            behavior,
            span,
        });
    }

    fn parse_extension<'t>(
        &mut self,
        d: &Directive<'t>,
    ) -> Option<(&'t PpToken, ExtensionBehavior)> {
        let r = d.rest;
        let err = |at: Option<&PpToken>, msg: String| {
            Diagnostic::error(Code::PpExtension, at.map_or(d.end, |t| t.span), msg)
                .with_note("the form is `#extension NAME : BEHAVIOR'")
        };
        let name = match r.first() {
            Some(t) if t.kind == PpKind::Ident => t,
            other => {
                let msg = format!(
                    "expected an extension name or `all', found {}",
                    found(other)
                );
                self.diags.push(err(other, msg));
                return None;
            }
        };
        if !is_punct(r.get(1), Punct::Colon) {
            let msg = format!(
                "expected `:' after the extension name, found {}",
                found(r.get(1))
            );
            self.diags.push(err(r.get(1), msg));
            return None;
        }
        let behavior = match r.get(2).map(|t| t.text.as_str()) {
            Some("require") => ExtensionBehavior::Require,
            Some("enable") => ExtensionBehavior::Enable,
            Some("warn") => ExtensionBehavior::Warn,
            Some("disable") => ExtensionBehavior::Disable,
            _ => {
                let at = r.get(2);
                let msg = format!(
                    "expected `require', `enable', `warn' or `disable', found {}",
                    found(at)
                );
                let mut diag = err(at, msg);
                if at.is_some_and(|t| self.macros.contains_key(&t.text)) {
                    diag = diag.with_note("macros are not expanded in #extension lines (§3.3)");
                }
                self.diags.push(diag);
                return None;
            }
        };
        if let Some(extra) = r.get(3) {
            let msg = format!("unexpected `{}' after the #extension behavior", extra.text);
            self.diags.push(err(Some(extra), msg));
            return None;
        }
        Some((name, behavior))
    }

    /// `#line line [source]`, macro-expanded; the next line gets number
    /// line+1 (§3.3 of GLSL 1.10 and 1.20).
    fn d_line(&mut self, d: &Directive) {
        if d.rest.is_empty() {
            self.diags.push(Diagnostic::error(
                Code::PpSyntax,
                d.span,
                "#line needs a line number",
            ));
            return;
        }
        let toks: Vec<PTok> = d.rest.iter().cloned().map(PTok::from).collect();
        let expanded = self.expander(false).expand(toks);
        let is_defined = |_: &str| false;
        let mut p = ExprParser::new(&expanded, d.end, &is_defined).strict();
        let result = (|| {
            let line = p.expression()?;
            let source = if p.at_end() {
                None
            } else {
                Some(p.expression()?)
            };
            if !p.at_end() {
                return Err(unexpected(
                    p.peek(),
                    d.end,
                    "the end of the #line directive",
                ));
            }
            Ok((line, source))
        })();
        self.diags.extend(p.take_warnings());
        let (line, source) = match result {
            Ok(v) => v,
            Err(diag) => {
                self.diags.push(diag);
                return;
            }
        };
        let to_u32 = |v: i64, what: &str| {
            u32::try_from(v).map_err(|_| {
                Diagnostic::error(
                    Code::PpSyntax,
                    d.full_span(),
                    format!("#line {what} {v} is out of range (0 to {})", u32::MAX),
                )
            })
        };
        let line = match to_u32(line, "line number") {
            Ok(l) => l,
            Err(diag) => return self.diags.push(diag),
        };
        let source = match source
            .map(|s| to_u32(s, "source string number"))
            .transpose()
        {
            Ok(s) => s,
            Err(diag) => return self.diags.push(diag),
        };
        let at = self.map.physical_line(d.end.start);
        // The line after the directive is `line + 1` up to GLSL 1.50, and
        // `line` from 3.30 on ("as if it is compiling at line number line",
        // 3.30 §3.3), as Mesa does.
        let next = if self.lang.version >= Version::V330 {
            line
        } else {
            line.wrapping_add(1)
        };
        self.map.add_line_directive(at, next, source);
    }
}
