//! The tokens the parser reads: what the preprocessor hands on after macro
//! expansion, with identifiers classified into keywords for the shader's
//! `#version`.

use crate::lang::{Extension, Language, Version};
use crate::source::Span;
use smol_str::SmolStr;

macro_rules! keywords {
    ($($variant:ident = $text:literal $(since $v:ident)?;)*) => {
        /// Keywords of GLSL 1.10 to 3.30 (§3.6 of each spec), each with
        /// the first version that has it.
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
    Flat = "flat" since V130;
    Smooth = "smooth" since V130;
    Noperspective = "noperspective" since V130;
    Switch = "switch" since V130;
    Case = "case" since V130;
    Default = "default" since V130;
    Uint = "uint" since V130;
    Uvec2 = "uvec2" since V130;
    Uvec3 = "uvec3" since V130;
    Uvec4 = "uvec4" since V130;
    Lowp = "lowp" since V130;
    Mediump = "mediump" since V130;
    Highp = "highp" since V130;
    Precision = "precision" since V130;
    SamplerCubeShadow = "samplerCubeShadow" since V130;
    Sampler1DArray = "sampler1DArray" since V130;
    Sampler2DArray = "sampler2DArray" since V130;
    Sampler1DArrayShadow = "sampler1DArrayShadow" since V130;
    Sampler2DArrayShadow = "sampler2DArrayShadow" since V130;
    Isampler1D = "isampler1D" since V130;
    Isampler2D = "isampler2D" since V130;
    Isampler3D = "isampler3D" since V130;
    IsamplerCube = "isamplerCube" since V130;
    Isampler1DArray = "isampler1DArray" since V130;
    Isampler2DArray = "isampler2DArray" since V130;
    Usampler1D = "usampler1D" since V130;
    Usampler2D = "usampler2D" since V130;
    Usampler3D = "usampler3D" since V130;
    UsamplerCube = "usamplerCube" since V130;
    Usampler1DArray = "usampler1DArray" since V130;
    Usampler2DArray = "usampler2DArray" since V130;
    Layout = "layout" since V140;
    // A storage qualifier of compute shaders (GL_ARB_compute_shader): a
    // keyword only where that extension is enabled, `layout(shared)`'s
    // identifier everywhere.
    Shared = "shared" since V110;
    // GL_ARB_shader_storage_buffer_object's storage and memory
    // qualifiers: keywords only where it is enabled.
    Buffer = "buffer" since V110;
    Coherent = "coherent" since V110;
    Volatile = "volatile" since V110;
    Restrict = "restrict" since V110;
    Readonly = "readonly" since V110;
    Writeonly = "writeonly" since V110;
    // The per-patch storage qualifier of tessellation shaders
    // (GL_ARB_tessellation_shader): a keyword only where it is enabled.
    Patch = "patch" since V110;
    Sampler2DRect = "sampler2DRect" since V140;
    Sampler2DRectShadow = "sampler2DRectShadow" since V140;
    Isampler2DRect = "isampler2DRect" since V140;
    Usampler2DRect = "usampler2DRect" since V140;
    SamplerBuffer = "samplerBuffer" since V140;
    IsamplerBuffer = "isamplerBuffer" since V140;
    UsamplerBuffer = "usamplerBuffer" since V140;
    Sampler2DMS = "sampler2DMS" since V150;
    Isampler2DMS = "isampler2DMS" since V150;
    Usampler2DMS = "usampler2DMS" since V150;
    Sampler2DMSArray = "sampler2DMSArray" since V150;
    Isampler2DMSArray = "isampler2DMSArray" since V150;
    Usampler2DMSArray = "usampler2DMSArray" since V150;
    // GL_ARB_texture_cube_map_array's (GLSL 4.00's): keywords only where
    // the extension is enabled (`classify`).
    SamplerCubeArray = "samplerCubeArray" since V130;
    SamplerCubeArrayShadow = "samplerCubeArrayShadow" since V130;
    IsamplerCubeArray = "isamplerCubeArray" since V130;
    UsamplerCubeArray = "usamplerCubeArray" since V130;
}

/// Words reserved for future use (§3.6), with the first version that
/// reserves each: using one is an error. A word that later becomes a
/// keyword (`switch`, `precision`, `sampler2DRect`) is listed here for the
/// versions before; the keyword table wins from its version on.
const RESERVED: &[(&str, Version)] = &{
    use Version::{V110, V120, V130};
    [
        ("asm", V110),
        ("class", V110),
        ("union", V110),
        ("enum", V110),
        ("typedef", V110),
        ("template", V110),
        ("this", V110),
        ("packed", V110),
        ("goto", V110),
        ("switch", V110),
        ("default", V110),
        ("inline", V110),
        ("noinline", V110),
        ("volatile", V110),
        ("public", V110),
        ("static", V110),
        ("extern", V110),
        ("external", V110),
        ("interface", V110),
        ("long", V110),
        ("short", V110),
        ("double", V110),
        ("half", V110),
        ("fixed", V110),
        ("unsigned", V110),
        ("input", V110),
        ("output", V110),
        ("hvec2", V110),
        ("hvec3", V110),
        ("hvec4", V110),
        ("dvec2", V110),
        ("dvec3", V110),
        ("dvec4", V110),
        ("fvec2", V110),
        ("fvec3", V110),
        ("fvec4", V110),
        ("sampler2DRect", V110),
        ("sampler3DRect", V110),
        ("sampler2DRectShadow", V110),
        ("sizeof", V110),
        ("cast", V110),
        ("namespace", V110),
        ("using", V110),
        // The precision qualifiers of GLSL ES, reserved by 1.20.
        ("lowp", V120),
        ("mediump", V120),
        ("highp", V120),
        ("precision", V120),
        ("common", V130),
        ("partition", V130),
        ("active", V130),
        ("superp", V130),
        ("samplerBuffer", V130),
        ("filter", V130),
        ("image1D", V130),
        ("image2D", V130),
        ("image3D", V130),
        ("imageCube", V130),
        ("iimage1D", V130),
        ("iimage2D", V130),
        ("iimage3D", V130),
        ("iimageCube", V130),
        ("uimage1D", V130),
        ("uimage2D", V130),
        ("uimage3D", V130),
        ("uimageCube", V130),
        ("image1DArray", V130),
        ("image2DArray", V130),
        ("iimage1DArray", V130),
        ("iimage2DArray", V130),
        ("uimage1DArray", V130),
        ("uimage2DArray", V130),
        ("image1DShadow", V130),
        ("image2DShadow", V130),
        ("image1DArrayShadow", V130),
        ("image2DArrayShadow", V130),
        ("imageBuffer", V130),
        ("iimageBuffer", V130),
        ("uimageBuffer", V130),
        ("row_major", V130),
    ]
};

/// How the lexer classifies an identifier-shaped word.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WordClass {
    Keyword(Keyword),
    /// Reserved for future use in this version: an error wherever it appears.
    Reserved,
    Identifier,
}

/// Classifies `word` for `lang`. A keyword of a later version is reserved
/// in an earlier one when §3.6 reserves it there, and a plain identifier
/// otherwise (`invariant` is an identifier in 1.10).
pub fn classify(word: &str, lang: Language) -> WordClass {
    let version = lang.version;
    if let Some(k) = Keyword::lookup(word) {
        let cube_array = matches!(
            k,
            Keyword::SamplerCubeArray
                | Keyword::SamplerCubeArrayShadow
                | Keyword::IsamplerCubeArray
                | Keyword::UsamplerCubeArray
        );
        if cube_array {
            if k.since() <= version && lang.has(Extension::ArbTextureCubeMapArray) {
                return WordClass::Keyword(k);
            }
        } else if k == Keyword::Shared {
            if lang.has(Extension::ArbComputeShader) {
                return WordClass::Keyword(k);
            }
        } else if k == Keyword::Patch {
            if lang.has(Extension::ArbTessellationShader) {
                return WordClass::Keyword(k);
            }
        } else if matches!(
            k,
            Keyword::Buffer
                | Keyword::Coherent
                | Keyword::Volatile
                | Keyword::Restrict
                | Keyword::Readonly
                | Keyword::Writeonly
        ) {
            if lang.has(Extension::ArbShaderStorageBufferObject) {
                return WordClass::Keyword(k);
            }
        } else if k.since() <= version || (k == Keyword::Layout && lang.has_layout_keyword()) {
            return WordClass::Keyword(k);
        }
    }
    if RESERVED
        .iter()
        .any(|&(w, since)| w == word && since <= version)
    {
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
    /// An integer literal with the `u`/`U` suffix (GLSL 1.30 on).
    UintLiteral(u32),
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
            TokenKind::UintLiteral(v) => format!("unsigned integer `{v}u'"),
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
        let l = |v| Language::new(v, true);
        assert_eq!(
            classify("invariant", l(Version::V110)),
            WordClass::Identifier
        );
        assert_eq!(
            classify("invariant", l(Version::V120)),
            WordClass::Keyword(Keyword::Invariant)
        );
        assert_eq!(
            classify("precision", l(Version::V110)),
            WordClass::Identifier
        );
        assert_eq!(classify("precision", l(Version::V120)), WordClass::Reserved);
        assert_eq!(
            classify("precision", l(Version::V130)),
            WordClass::Keyword(Keyword::Precision)
        );
        assert_eq!(classify("switch", l(Version::V110)), WordClass::Reserved);
        assert_eq!(
            classify("switch", l(Version::V130)),
            WordClass::Keyword(Keyword::Switch)
        );
        assert_eq!(classify("case", l(Version::V120)), WordClass::Identifier);
        assert_eq!(
            classify("samplerBuffer", l(Version::V120)),
            WordClass::Identifier
        );
        assert_eq!(
            classify("samplerBuffer", l(Version::V130)),
            WordClass::Reserved
        );
        assert_eq!(
            classify("samplerBuffer", l(Version::V140)),
            WordClass::Keyword(Keyword::SamplerBuffer)
        );
        assert_eq!(classify("layout", l(Version::V130)), WordClass::Identifier);
        let mut ext = l(Version::V120);
        ext.extensions
            .set(crate::lang::Extension::ArbExplicitAttribLocation, true);
        assert_eq!(classify("layout", ext), WordClass::Keyword(Keyword::Layout));
        assert_eq!(
            classify("vec3", l(Version::V110)),
            WordClass::Keyword(Keyword::Vec3)
        );
    }
}
