//! The tokens the parser reads: what the preprocessor hands on after macro
//! expansion, with identifiers classified into keywords for the shader's
//! `#version`.

use crate::source::Span;
use smol_str::SmolStr;

/// A language version this front end accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
pub enum Version {
    V110,
    V120,
}

impl Version {
    /// The number as written after `#version`.
    pub fn number(self) -> u32 {
        match self {
            Version::V110 => 110,
            Version::V120 => 120,
        }
    }

    pub fn from_number(n: u32) -> Option<Version> {
        match n {
            110 => Some(Version::V110),
            120 => Some(Version::V120),
            _ => None,
        }
    }

    /// "1.10" / "1.20", as error messages spell it.
    pub fn dotted(self) -> &'static str {
        match self {
            Version::V110 => "1.10",
            Version::V120 => "1.20",
        }
    }
}

macro_rules! keywords {
    ($($variant:ident = $text:literal $(since $v:ident)?;)*) => {
        /// Keywords of GLSL 1.10 and 1.20 (§3.6 of each spec).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Keyword { $($variant),* }

        impl Keyword {
            pub fn as_str(self) -> &'static str {
                match self { $(Keyword::$variant => $text),* }
            }

            /// The first version in which this word is a keyword.
            pub fn since(self) -> Version {
                match self { $(Keyword::$variant => keywords!(@v $($v)?)),* }
            }

            fn lookup(s: &str) -> Option<Keyword> {
                match s { $($text => Some(Keyword::$variant),)* _ => None }
            }
        }
    };
    (@v) => { Version::V110 };
    (@v $v:ident) => { Version::$v };
}

keywords! {
    Attribute = "attribute";
    Const = "const";
    Uniform = "uniform";
    Varying = "varying";
    Centroid = "centroid" since V120;
    Break = "break";
    Continue = "continue";
    Do = "do";
    For = "for";
    While = "while";
    If = "if";
    Else = "else";
    In = "in";
    Out = "out";
    Inout = "inout";
    Float = "float";
    Int = "int";
    Void = "void";
    Bool = "bool";
    True = "true";
    False = "false";
    Invariant = "invariant" since V120;
    Discard = "discard";
    Return = "return";
    Mat2 = "mat2";
    Mat3 = "mat3";
    Mat4 = "mat4";
    Mat2x2 = "mat2x2" since V120;
    Mat2x3 = "mat2x3" since V120;
    Mat2x4 = "mat2x4" since V120;
    Mat3x2 = "mat3x2" since V120;
    Mat3x3 = "mat3x3" since V120;
    Mat3x4 = "mat3x4" since V120;
    Mat4x2 = "mat4x2" since V120;
    Mat4x3 = "mat4x3" since V120;
    Mat4x4 = "mat4x4" since V120;
    Vec2 = "vec2";
    Vec3 = "vec3";
    Vec4 = "vec4";
    Ivec2 = "ivec2";
    Ivec3 = "ivec3";
    Ivec4 = "ivec4";
    Bvec2 = "bvec2";
    Bvec3 = "bvec3";
    Bvec4 = "bvec4";
    Sampler1D = "sampler1D";
    Sampler2D = "sampler2D";
    Sampler3D = "sampler3D";
    SamplerCube = "samplerCube";
    Sampler1DShadow = "sampler1DShadow";
    Sampler2DShadow = "sampler2DShadow";
    Struct = "struct";
}

/// Words reserved for future use in both versions (§3.6): using one is an
/// error.
const RESERVED_BOTH: &[&str] = &[
    "asm",
    "class",
    "union",
    "enum",
    "typedef",
    "template",
    "this",
    "packed",
    "goto",
    "switch",
    "default",
    "inline",
    "noinline",
    "volatile",
    "public",
    "static",
    "extern",
    "external",
    "interface",
    "long",
    "short",
    "double",
    "half",
    "fixed",
    "unsigned",
    "input",
    "output",
    "hvec2",
    "hvec3",
    "hvec4",
    "dvec2",
    "dvec3",
    "dvec4",
    "fvec2",
    "fvec3",
    "fvec4",
    "sampler2DRect",
    "sampler3DRect",
    "sampler2DRectShadow",
    "sizeof",
    "cast",
    "namespace",
    "using",
];

/// Words reserved in 1.20 only (§3.6 of the 1.20 spec adds the precision
/// qualifiers of GLSL ES).
const RESERVED_120: &[&str] = &["lowp", "mediump", "highp", "precision"];

/// How the lexer classifies an identifier-shaped word.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WordClass {
    Keyword(Keyword),
    /// Reserved for future use in this version: an error wherever it appears.
    Reserved,
    Identifier,
}

/// Classifies `word` for `version`. Keywords of a later version are plain
/// identifiers in an earlier one (`invariant` is an identifier in 1.10).
pub fn classify(word: &str, version: Version) -> WordClass {
    if let Some(k) = Keyword::lookup(word) {
        if k.since() <= version {
            return WordClass::Keyword(k);
        }
        return WordClass::Identifier;
    }
    if RESERVED_BOTH.contains(&word) || (version >= Version::V120 && RESERVED_120.contains(&word)) {
        return WordClass::Reserved;
    }
    WordClass::Identifier
}

/// Punctuators of the language (after preprocessing).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Punct {
    LeftParen,
    RightParen,
    LeftBracket,
    RightBracket,
    LeftBrace,
    RightBrace,
    Dot,
    Comma,
    Colon,
    Semicolon,
    Question,
    Plus,
    Minus,
    Star,
    Slash,
    Percent,
    Bang,
    Tilde,
    Less,
    Greater,
    LessEq,
    GreaterEq,
    EqEq,
    NotEq,
    Amp,
    Caret,
    Pipe,
    AmpAmp,
    CaretCaret,
    PipePipe,
    Equal,
    PlusEq,
    MinusEq,
    StarEq,
    SlashEq,
    PercentEq,
    ShlEq,
    ShrEq,
    AmpEq,
    CaretEq,
    PipeEq,
    Shl,
    Shr,
    PlusPlus,
    MinusMinus,
}

impl Punct {
    pub fn as_str(self) -> &'static str {
        use Punct::*;
        match self {
            LeftParen => "(",
            RightParen => ")",
            LeftBracket => "[",
            RightBracket => "]",
            LeftBrace => "{",
            RightBrace => "}",
            Dot => ".",
            Comma => ",",
            Colon => ":",
            Semicolon => ";",
            Question => "?",
            Plus => "+",
            Minus => "-",
            Star => "*",
            Slash => "/",
            Percent => "%",
            Bang => "!",
            Tilde => "~",
            Less => "<",
            Greater => ">",
            LessEq => "<=",
            GreaterEq => ">=",
            EqEq => "==",
            NotEq => "!=",
            Amp => "&",
            Caret => "^",
            Pipe => "|",
            AmpAmp => "&&",
            CaretCaret => "^^",
            PipePipe => "||",
            Equal => "=",
            PlusEq => "+=",
            MinusEq => "-=",
            StarEq => "*=",
            SlashEq => "/=",
            PercentEq => "%=",
            ShlEq => "<<=",
            ShrEq => ">>=",
            AmpEq => "&=",
            CaretEq => "^=",
            PipeEq => "|=",
            Shl => "<<",
            Shr => ">>",
            PlusPlus => "++",
            MinusMinus => "--",
        }
    }

    /// All punctuators, longest first (for maximal munch).
    pub const ALL_LONGEST_FIRST: &'static [Punct] = &[
        Punct::ShlEq,
        Punct::ShrEq,
        Punct::LessEq,
        Punct::GreaterEq,
        Punct::EqEq,
        Punct::NotEq,
        Punct::AmpAmp,
        Punct::CaretCaret,
        Punct::PipePipe,
        Punct::PlusEq,
        Punct::MinusEq,
        Punct::StarEq,
        Punct::SlashEq,
        Punct::PercentEq,
        Punct::AmpEq,
        Punct::CaretEq,
        Punct::PipeEq,
        Punct::Shl,
        Punct::Shr,
        Punct::PlusPlus,
        Punct::MinusMinus,
        Punct::LeftParen,
        Punct::RightParen,
        Punct::LeftBracket,
        Punct::RightBracket,
        Punct::LeftBrace,
        Punct::RightBrace,
        Punct::Dot,
        Punct::Comma,
        Punct::Colon,
        Punct::Semicolon,
        Punct::Question,
        Punct::Plus,
        Punct::Minus,
        Punct::Star,
        Punct::Slash,
        Punct::Percent,
        Punct::Bang,
        Punct::Tilde,
        Punct::Less,
        Punct::Greater,
        Punct::Amp,
        Punct::Caret,
        Punct::Pipe,
        Punct::Equal,
    ];
}

/// The kind of a parser token.
#[derive(Clone, Debug, PartialEq)]
pub enum TokenKind {
    Identifier(SmolStr),
    Keyword(Keyword),
    /// A word reserved for future use; the parser reports it where it appears.
    Reserved(SmolStr),
    /// An integer literal, already converted (decimal, octal or hex). Values
    /// that do not fit 32 bits were reported by the preprocessor and are
    /// truncated here.
    IntLiteral(u32),
    FloatLiteral(f32),
    /// A string literal, without its quotes (GL_SHADERBOX_debug_printf only).
    StringLiteral(SmolStr),
    Punct(Punct),
    Eof,
}

/// One token for the parser, with the span it came from. Tokens produced by
/// a macro expansion carry the span of the macro's invocation.
#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    pub kind: TokenKind,
    pub span: Span,
}

impl TokenKind {
    /// How the token reads in an error message ("`vec4'", "end of input").
    pub fn describe(&self) -> String {
        match self {
            TokenKind::Identifier(s) | TokenKind::Reserved(s) => format!("`{s}'"),
            TokenKind::Keyword(k) => format!("`{}'", k.as_str()),
            TokenKind::IntLiteral(v) => format!("integer `{v}'"),
            TokenKind::FloatLiteral(v) => format!("float `{v}'"),
            TokenKind::StringLiteral(s) => format!("string \"{s}\""),
            TokenKind::Punct(p) => format!("`{}'", p.as_str()),
            TokenKind::Eof => "end of input".to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classification_by_version() {
        assert_eq!(classify("invariant", Version::V110), WordClass::Identifier);
        assert_eq!(
            classify("invariant", Version::V120),
            WordClass::Keyword(Keyword::Invariant)
        );
        assert_eq!(classify("precision", Version::V110), WordClass::Identifier);
        assert_eq!(classify("precision", Version::V120), WordClass::Reserved);
        assert_eq!(classify("switch", Version::V110), WordClass::Reserved);
        assert_eq!(
            classify("vec3", Version::V110),
            WordClass::Keyword(Keyword::Vec3)
        );
    }
}
