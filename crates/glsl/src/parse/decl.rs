//! Declarations: qualifiers, type specifiers, structs, variable declarator
//! lists, `invariant` redeclarations and functions (GLSL 1.20 §9:
//! `declaration`, `function_prototype`, `function_definition`,
//! `struct_specifier`, `init_declarator_list`).

use super::{PResult, Parser, Reported};
use crate::ast::*;
use crate::source::Span;
use crate::token::{Keyword, Punct, TokenKind};

/// True for the keywords that name a built-in type (`type_specifier_nonarray`
/// minus `struct` and `TYPE_NAME`).
pub(super) fn is_type_keyword(k: Keyword) -> bool {
    use Keyword::*;
    matches!(
        k,
        Void | Float
            | Int
            | Bool
            | Vec2
            | Vec3
            | Vec4
            | Ivec2
            | Ivec3
            | Ivec4
            | Uint
            | Uvec2
            | Uvec3
            | Uvec4
            | Bvec2
            | Bvec3
            | Bvec4
            | Mat2
            | Mat3
            | Mat4
            | Mat2x2
            | Mat2x3
            | Mat2x4
            | Mat3x2
            | Mat3x3
            | Mat3x4
            | Mat4x2
            | Mat4x3
            | Mat4x4
            | Sampler1D
            | Sampler2D
            | Sampler3D
            | SamplerCube
            | Sampler1DShadow
            | Sampler2DShadow
    ) || crate::types::SamplerKind::from_name(k.as_str()).is_some()
}

/// The qualifier a keyword spells, if any (storage, parameter, `centroid`,
/// `invariant`).
pub(super) fn qualifier_of(k: Keyword) -> Option<Qualifier> {
    Some(match k {
        Keyword::Const => Qualifier::Const,
        Keyword::Attribute => Qualifier::Attribute,
        Keyword::Uniform => Qualifier::Uniform,
        Keyword::Varying => Qualifier::Varying,
        Keyword::Centroid => Qualifier::Centroid,
        Keyword::Invariant => Qualifier::Invariant,
        Keyword::In => Qualifier::In,
        Keyword::Out => Qualifier::Out,
        Keyword::Inout => Qualifier::Inout,
        Keyword::Flat => Qualifier::Flat,
        Keyword::Smooth => Qualifier::Smooth,
        Keyword::Noperspective => Qualifier::Noperspective,
        Keyword::Lowp => Qualifier::Lowp,
        Keyword::Mediump => Qualifier::Mediump,
        Keyword::Highp => Qualifier::Highp,
        Keyword::Layout => Qualifier::Layout,
        Keyword::Shared => Qualifier::Shared,
        Keyword::Buffer => Qualifier::Buffer,
        Keyword::Coherent => Qualifier::Coherent,
        Keyword::Volatile => Qualifier::Volatile,
        Keyword::Restrict => Qualifier::Restrict,
        Keyword::Readonly => Qualifier::Readonly,
        Keyword::Writeonly => Qualifier::Writeonly,
        Keyword::Patch => Qualifier::Patch,
        _ => return None,
    })
}

impl Parser<'_> {
    /// True if the current token names a type (a type keyword or a struct
    /// name in scope), or is a near-miss of a type name (`vec`, `Vec3`)
    /// followed by the declared name: that is parsed as a declaration so
    /// analysis reports the one bad type and still declares the variable.
    pub(super) fn at_type_name(&self) -> bool {
        match self.kind() {
            TokenKind::Keyword(k) => is_type_keyword(*k),
            TokenKind::Identifier(name) => {
                self.scopes.is_type(name) || self.at_misspelled_type(name)
            }
            _ => false,
        }
    }

    fn at_misspelled_type(&self, name: &str) -> bool {
        matches!(self.nth(1).kind, TokenKind::Identifier(_))
            && super::type_name_hint(name, self.lang).is_some()
    }

    /// True if the current token can only start a declaration at global
    /// scope: a qualifier, `struct` or a type.
    pub(super) fn at_declaration_keyword_or_type(&self) -> bool {
        match self.kind() {
            TokenKind::Keyword(Keyword::Struct | Keyword::Precision) => true,
            TokenKind::Keyword(k) if qualifier_of(*k).is_some() => true,
            _ => self.at_type_name(),
        }
    }

    /// True if a statement starting here is a declaration rather than an
    /// expression: a type followed by a constructor's `(` (possibly after
    /// an array size, `float[2](...)`) is an expression.
    pub(super) fn at_declaration_start(&self) -> bool {
        if self.at_type_name() {
            return !self.constructor_follows();
        }
        self.at_declaration_keyword_or_type()
    }

    /// With the current token a type name: does `(` follow it, maybe after
    /// one bracketed array size?
    fn constructor_follows(&self) -> bool {
        let mut i = 1;
        if self.nth_is_punct(1, Punct::LeftBracket) {
            let mut depth = 0u32;
            loop {
                match &self.nth(i).kind {
                    TokenKind::Eof => return false,
                    TokenKind::Punct(Punct::LeftBracket) => depth += 1,
                    TokenKind::Punct(Punct::RightBracket) => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    _ => {}
                }
                i += 1;
            }
            i += 1;
        }
        self.nth_is_punct(i, Punct::LeftParen)
    }

    /// A declaration inside a function (`declaration_statement`); function
    /// definitions are rejected here.
    pub(super) fn local_declaration(&mut self) -> PResult<Declaration> {
        match self.declaration(false)? {
            ExternalDecl::Declaration(d) => Ok(d),
            // `declaration(false)` never yields a definition.
            ExternalDecl::FunctionDef(_) => Err(Reported),
        }
    }

    /// `declaration` or (if `allow_definition`) `function_definition`,
    /// starting at a qualifier, `struct` or type.
    pub(super) fn declaration(&mut self, allow_definition: bool) -> PResult<ExternalDecl> {
        let start = self.span();
        if self.at_invariant_list() {
            return self.invariant_list().map(ExternalDecl::Declaration);
        }
        if self.at_keyword(Keyword::Precision) {
            return self.precision_statement().map(ExternalDecl::Declaration);
        }
        let qualifiers = self.qualifiers()?;
        if !qualifiers.is_empty() {
            if self.eat_punct(Punct::Semicolon) {
                return Ok(ExternalDecl::Declaration(Declaration::Qualifiers {
                    qualifiers,
                    span: self.span_from(start),
                }));
            }
            let block_name =
                matches!(self.kind(), TokenKind::Identifier(n) if !self.scopes.is_type(n));
            if block_name && self.nth_is_punct(1, Punct::LeftBrace) {
                return self
                    .interface_block(qualifiers, start)
                    .map(|b| ExternalDecl::Declaration(Declaration::Block(b)));
            }
        }
        let ty = self.type_specifier()?;
        let ty = FullType {
            qualifiers,
            ty,
            span: self.span_from(start),
        };
        if self.eat_punct(Punct::Semicolon) {
            // `struct S { ... };` or the grammar's bare `float;`.
            return Ok(ExternalDecl::Declaration(Declaration::Variables(
                InitDeclaratorList {
                    ty,
                    declarators: Vec::new(),
                    span: self.span_from(start),
                },
            )));
        }
        let name = self.ident("identifier")?;
        if self.at_punct(Punct::LeftParen) {
            return self.function(ty, name, allow_definition);
        }
        let list = self.init_declarator_list(ty, name, start)?;
        Ok(ExternalDecl::Declaration(Declaration::Variables(list)))
    }

    /// `precision lowp float;` (GLSL 1.30 §4.5.3).
    fn precision_statement(&mut self) -> PResult<Declaration> {
        let start = self.bump().span;
        let precision = match self.kind() {
            TokenKind::Keyword(k @ (Keyword::Lowp | Keyword::Mediump | Keyword::Highp)) => {
                let qualifier = qualifier_of(*k).ok_or(Reported)?;
                SpannedQualifier {
                    qualifier,
                    span: self.bump().span,
                    layout: Vec::new(),
                }
            }
            _ => return Err(self.unexpected("`lowp', `mediump' or `highp'")),
        };
        let ty = self.type_specifier()?;
        self.expect_semicolon()?;
        Ok(Declaration::Precision {
            precision,
            ty,
            span: self.span_from(start),
        })
    }

    /// An interface block after its qualifiers: `NAME { members } inst[N]? ;`.
    /// The block name is not a type; the instance name is declared.
    fn interface_block(
        &mut self,
        qualifiers: Vec<SpannedQualifier>,
        start: Span,
    ) -> PResult<InterfaceBlock> {
        let name = self.ident("block name")?;
        self.expect_punct(Punct::LeftBrace)?;
        self.enter()?;
        let members = self.struct_members();
        self.leave();
        if members.is_empty() && self.at_punct(Punct::RightBrace) {
            let _ = self.unexpected("member declaration");
        }
        self.expect_punct(Punct::RightBrace)?;
        let instance = match self.kind() {
            TokenKind::Identifier(_) => {
                let inst = self.ident("instance name")?;
                let array = if self.at_punct(Punct::LeftBracket) {
                    Some(self.array_spec()?)
                } else {
                    None
                };
                self.scopes.declare(&inst.name, false);
                Some((inst, array))
            }
            _ => None,
        };
        self.expect_semicolon()?;
        Ok(InterfaceBlock {
            qualifiers,
            name,
            members,
            instance,
            span: self.span_from(start),
        })
    }

    /// `invariant a, b;` (GLSL 1.20 §4.6.1): `invariant` followed by a name
    /// that is not a type.
    fn at_invariant_list(&self) -> bool {
        self.at_keyword(Keyword::Invariant)
            && matches!(&self.nth(1).kind, TokenKind::Identifier(n) if !self.scopes.is_type(n))
    }

    fn invariant_list(&mut self) -> PResult<Declaration> {
        let start = self.bump().span;
        let mut names = vec![self.ident("identifier")?];
        while self.eat_punct(Punct::Comma) {
            names.push(self.ident("identifier")?);
        }
        self.expect_semicolon()?;
        Ok(Declaration::Invariant {
            names,
            span: self.span_from(start),
        })
    }

    /// An identifier being declared or selected. Struct names are accepted
    /// too: a declaration may hide a type (`vec4 S;` with `struct S` outside).
    pub(super) fn ident(&mut self, what: &str) -> PResult<Ident> {
        match self.kind() {
            TokenKind::Identifier(name) => {
                let span = self.bump().span;
                Ok(Ident {
                    name: name.clone(),
                    span,
                })
            }
            _ => Err(self.unexpected(what)),
        }
    }

    /// Any sequence of qualifier keywords, as written; `layout` with its
    /// parenthesized list.
    pub(super) fn qualifiers(&mut self) -> PResult<Vec<SpannedQualifier>> {
        let mut out = Vec::new();
        while let TokenKind::Keyword(k) = self.kind() {
            let Some(qualifier) = qualifier_of(*k) else {
                break;
            };
            let start = self.bump().span;
            let layout = if qualifier == Qualifier::Layout {
                self.layout_ids()?
            } else {
                Vec::new()
            };
            out.push(SpannedQualifier {
                qualifier,
                span: self.span_from(start),
                layout,
            });
        }
        Ok(out)
    }

    /// `( id (= value)? , ... )` after `layout` (GLSL 1.40 §9
    /// `layout_qualifier_id_list`; the value is parsed as an expression so
    /// analysis can say what is wrong with it).
    fn layout_ids(&mut self) -> PResult<Vec<LayoutId>> {
        self.expect_punct(Punct::LeftParen)?;
        let mut ids = Vec::new();
        loop {
            // `shared` is a keyword of later versions; here any word is a
            // layout identifier.
            let name = match self.kind() {
                TokenKind::Identifier(n) => n.clone(),
                TokenKind::Reserved(w) => w.clone(),
                TokenKind::Keyword(k) => smol_str::SmolStr::new(k.as_str()),
                _ => return Err(self.unexpected("layout qualifier identifier")),
            };
            let span = self.bump().span;
            let value = if self.eat_punct(Punct::Equal) {
                Some(*self.conditional()?)
            } else {
                None
            };
            ids.push(LayoutId {
                name: Ident { name, span },
                value,
                span: self.span_from(span),
            });
            if !self.eat_punct(Punct::Comma) {
                break;
            }
        }
        self.expect_punct(Punct::RightParen)?;
        Ok(ids)
    }

    /// `fully_specified_type`: qualifiers and a type specifier.
    pub(super) fn fully_specified_type(&mut self) -> PResult<FullType> {
        let start = self.span();
        let qualifiers = self.qualifiers()?;
        let ty = self.type_specifier()?;
        Ok(FullType {
            qualifiers,
            ty,
            span: self.span_from(start),
        })
    }

    /// `type_specifier`: a type keyword, struct name or struct specifier,
    /// optionally followed by one array size (`float[3]`, `float[]`).
    /// Analysis judges whether the array type is allowed there (and in the
    /// shader's version).
    pub(super) fn type_specifier(&mut self) -> PResult<TypeSpecifier> {
        let start = self.span();
        let name = match self.kind() {
            TokenKind::Keyword(Keyword::Struct) => TypeName::Struct(self.struct_specifier()?),
            TokenKind::Keyword(k) if is_type_keyword(*k) => {
                self.bump();
                TypeName::Builtin(*k)
            }
            TokenKind::Identifier(name)
                if self.scopes.is_type(name) || self.at_misspelled_type(name) =>
            {
                let span = self.bump().span;
                TypeName::Named(Ident {
                    name: name.clone(),
                    span,
                })
            }
            _ => return Err(self.unexpected("type")),
        };
        let array = if self.at_punct(Punct::LeftBracket) {
            Some(self.array_spec()?)
        } else {
            None
        };
        Ok(TypeSpecifier {
            name,
            array,
            span: self.span_from(start),
        })
    }

    /// `[` constant_expression? `]`, repeated (the `array_specifier` of
    /// GL_ARB_arrays_of_arrays; analysis decides whether more than one
    /// is allowed).
    pub(super) fn array_spec(&mut self) -> PResult<ArraySpec> {
        let start = self.span();
        let mut dims = Vec::new();
        while self.at_punct(Punct::LeftBracket) {
            let dim_start = self.expect_punct(Punct::LeftBracket)?;
            let size = if self.at_punct(Punct::RightBracket) {
                None
            } else {
                Some(self.conditional()?)
            };
            self.expect_punct(Punct::RightBracket)?;
            dims.push(ArrayDim {
                size,
                span: self.span_from(dim_start),
            });
        }
        Ok(ArraySpec {
            dims,
            span: self.span_from(start),
        })
    }

    /// `struct_specifier`: `struct NAME? { members }`. The name is declared
    /// as a type in the current scope after the closing brace.
    fn struct_specifier(&mut self) -> PResult<StructSpecifier> {
        self.enter()?;
        let r = self.struct_specifier_inner();
        self.leave();
        r
    }

    fn struct_specifier_inner(&mut self) -> PResult<StructSpecifier> {
        let start = self.bump().span;
        let name = match self.kind() {
            TokenKind::Identifier(_) => Some(self.ident("identifier")?),
            _ => None,
        };
        self.expect_punct(Punct::LeftBrace)?;
        let members = self.struct_members();
        if members.is_empty() && self.at_punct(Punct::RightBrace) {
            // §9: `struct_declaration_list` has at least one member.
            let _ = self.unexpected("member declaration");
        }
        self.expect_punct(Punct::RightBrace)?;
        if let Some(n) = &name {
            self.scopes.declare(&n.name, true);
        }
        Ok(StructSpecifier {
            name,
            members,
            span: self.span_from(start),
        })
    }

    /// Member lines up to (not including) the closing `}`; a bad line is
    /// reported and skipped.
    fn struct_members(&mut self) -> Vec<StructMemberDecl> {
        let mut members = Vec::new();
        while !self.at_punct(Punct::RightBrace) && !self.at_eof() && !self.aborted {
            let start = self.pos;
            self.recovering = false;
            match self.struct_member() {
                Ok(m) => members.push(m),
                Err(Reported) => self.recover(start),
            }
        }
        members
    }

    /// `struct_declaration`: `type a, b[2];` (qualifiers parsed for analysis
    /// to reject).
    fn struct_member(&mut self) -> PResult<StructMemberDecl> {
        let start = self.span();
        let qualifiers = self.qualifiers()?;
        let ty = self.type_specifier()?;
        let mut declarators = Vec::new();
        loop {
            let name = self.ident("member name")?;
            let array = if self.at_punct(Punct::LeftBracket) {
                Some(self.array_spec()?)
            } else {
                None
            };
            declarators.push(StructDeclarator {
                span: self.span_from(name.span),
                name,
                array,
            });
            if !self.eat_punct(Punct::Comma) {
                break;
            }
        }
        self.expect_semicolon()?;
        Ok(StructMemberDecl {
            qualifiers,
            ty,
            declarators,
            span: self.span_from(start),
        })
    }

    /// `init_declarator_list` after its first name, through the `;`. Each
    /// name enters scope after its initializer (GLSL 1.20 §4.2.2).
    fn init_declarator_list(
        &mut self,
        ty: FullType,
        first: Ident,
        start: Span,
    ) -> PResult<InitDeclaratorList> {
        let mut declarators = vec![self.init_declarator(first)?];
        while self.eat_punct(Punct::Comma) {
            let name = self.ident("identifier")?;
            declarators.push(self.init_declarator(name)?);
        }
        self.expect_semicolon()?;
        Ok(InitDeclaratorList {
            ty,
            declarators,
            span: self.span_from(start),
        })
    }

    /// One declarator after its name: `[size]?` and `= initializer`?.
    fn init_declarator(&mut self, name: Ident) -> PResult<InitDeclarator> {
        let array = if self.at_punct(Punct::LeftBracket) {
            Some(self.array_spec()?)
        } else {
            None
        };
        let init = if self.eat_punct(Punct::Equal) {
            Some(self.initializer()?)
        } else {
            None
        };
        self.scopes.declare(&name.name, false);
        Ok(InitDeclarator {
            span: self.span_from(name.span),
            name,
            array,
            init,
        })
    }

    /// `initializer`: an assignment expression, or a brace-enclosed list
    /// of initializers with an optional trailing comma (GLSL 4.20 §4.1.11,
    /// GL_ARB_shading_language_420pack; analysis checks the extension).
    fn initializer(&mut self) -> PResult<Expr> {
        if !self.at_punct(Punct::LeftBrace) {
            return Ok(*self.assignment()?);
        }
        self.enter()?;
        let start = self.bump().span;
        let mut items = Vec::new();
        let mut closed = Ok(Span::default());
        while !self.at_punct(Punct::RightBrace) {
            match self.initializer() {
                Ok(e) => items.push(e),
                Err(r) => {
                    closed = Err(r);
                    break;
                }
            }
            if !self.eat_punct(Punct::Comma) {
                break;
            }
        }
        if closed.is_ok() {
            closed = self.expect_punct(Punct::RightBrace);
        }
        self.leave();
        closed?;
        Ok(Expr {
            kind: ExprKind::InitList(items),
            span: self.span_from(start),
        })
    }

    /// A function prototype or definition after its name; the parameters
    /// and body share one scope (`compound_statement_no_new_scope`).
    fn function(
        &mut self,
        return_type: FullType,
        name: Ident,
        allow_definition: bool,
    ) -> PResult<ExternalDecl> {
        self.scoped(|p| {
            let start = return_type.span;
            p.expect_punct(Punct::LeftParen)?;
            let params = p.parameter_list()?;
            let proto = FunctionProto {
                return_type,
                name,
                params,
                span: p.span_from(start),
            };
            if p.at_punct(Punct::LeftBrace) {
                if !allow_definition {
                    return Err(p.unexpected_with_note(
                        "`;'",
                        "a function cannot be defined inside another function",
                    ));
                }
                let body = p.compound_body()?;
                return Ok(ExternalDecl::FunctionDef(FunctionDef {
                    proto,
                    body,
                    span: p.span_from(start),
                }));
            }
            p.expect_semicolon()?;
            Ok(ExternalDecl::Declaration(Declaration::Prototype(proto)))
        })
    }

    /// Parameters after `(`, through `)`. `()` and `(void)` are empty.
    fn parameter_list(&mut self) -> PResult<Vec<ParamDecl>> {
        let mut params = Vec::new();
        if self.eat_punct(Punct::RightParen) {
            return Ok(params);
        }
        if self.at_keyword(Keyword::Void) && self.nth_is_punct(1, Punct::RightParen) {
            self.bump();
            self.bump();
            return Ok(params);
        }
        loop {
            params.push(self.parameter()?);
            if !self.eat_punct(Punct::Comma) {
                break;
            }
        }
        self.expect_punct(Punct::RightParen)?;
        Ok(params)
    }

    /// `parameter_declaration`: qualifiers, a type and an optional name with
    /// an optional array size. An unnamed array parameter (`float[3]`, valid
    /// in 1.10 as `parameter_type_specifier`) keeps its size in
    /// [`ParamDecl::array`], not in the type.
    fn parameter(&mut self) -> PResult<ParamDecl> {
        let start = self.span();
        let qualifiers = self.qualifiers()?;
        let mut ty = self.type_specifier()?;
        let (name, array) = match self.kind() {
            TokenKind::Identifier(_) => {
                let name = self.ident("identifier")?;
                let array = if self.at_punct(Punct::LeftBracket) {
                    Some(self.array_spec()?)
                } else {
                    None
                };
                self.scopes.declare(&name.name, false);
                (Some(name), array)
            }
            _ => (None, ty.array.take()),
        };
        if let (None, Some(a)) = (&name, &array) {
            // The type's span ends before the array size it no longer has.
            if let Some(end) = self.end_before(a.span.start) {
                ty.span = Span::new(ty.span.start, end.max(ty.span.start));
            }
        }
        Ok(ParamDecl {
            qualifiers,
            ty,
            name,
            array,
            span: self.span_from(start),
        })
    }

    /// The end of the token just before the one starting at `offset`
    /// (searching back from the current position).
    fn end_before(&self, offset: u32) -> Option<u32> {
        let upto = self.toks.get(..self.pos)?;
        let i = upto.iter().rposition(|t| t.span.start == offset)?;
        Some(upto.get(i.checked_sub(1)?)?.span.end)
    }
}
