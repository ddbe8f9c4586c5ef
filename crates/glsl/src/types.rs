//! GLSL types (1.10 to 3.30).
//!
//! [`Type`] is a small `Copy` value: GLSL 1.20 has no arrays of arrays, so a
//! type is a [`Base`] plus an optional array size. Struct types are
//! referenced by [`StructId`] into the module's struct table; two struct types
//! are the same type only if they are the same declaration (GLSL 1.20 §4.1.8
//! and §6.1.1 for the link-time rule on same-named structs).

use serde::Serialize;
use std::fmt;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum Scalar {
    Float,
    Int,
    /// `uint` (GLSL 1.30 §4.1.3): 32 bits, arithmetic modulo 2^32.
    Uint,
    Bool,
}

impl Scalar {
    pub fn name(self) -> &'static str {
        match self {
            Scalar::Float => "float",
            Scalar::Int => "int",
            Scalar::Uint => "uint",
            Scalar::Bool => "bool",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum SamplerKind {
    Sampler1D,
    Sampler2D,
    Sampler3D,
    SamplerCube,
    Sampler1DShadow,
    Sampler2DShadow,
}

impl SamplerKind {
    pub fn name(self) -> &'static str {
        match self {
            SamplerKind::Sampler1D => "sampler1D",
            SamplerKind::Sampler2D => "sampler2D",
            SamplerKind::Sampler3D => "sampler3D",
            SamplerKind::SamplerCube => "samplerCube",
            SamplerKind::Sampler1DShadow => "sampler1DShadow",
            SamplerKind::Sampler2DShadow => "sampler2DShadow",
        }
    }
}

/// Index of a struct declaration in [`crate::ir::Module::structs`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct StructId(pub u32);

/// A non-array type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum Base {
    Void,
    Scalar(Scalar),
    /// A vector of 2, 3 or 4 components.
    Vector(Scalar, u8),
    /// A float matrix with `cols` columns of `rows` components (2..=4 each).
    Matrix {
        cols: u8,
        rows: u8,
    },
    Sampler(SamplerKind),
    Struct(StructId),
    /// The type of an expression whose analysis failed. It converts to and
    /// from everything silently, so one mistake yields one error.
    Error,
}

/// The size of an array type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum ArraySize {
    Sized(u32),
    /// Declared without a size (`uniform float a[];`): GLSL 1.10 §4.1.9
    /// allows this; the size comes from a later redeclaration or from the
    /// largest constant index used.
    Unsized,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct Type {
    pub base: Base,
    pub array: Option<ArraySize>,
}

impl Type {
    pub const VOID: Type = Type::new(Base::Void);
    pub const FLOAT: Type = Type::new(Base::Scalar(Scalar::Float));
    pub const INT: Type = Type::new(Base::Scalar(Scalar::Int));
    pub const UINT: Type = Type::new(Base::Scalar(Scalar::Uint));
    pub const BOOL: Type = Type::new(Base::Scalar(Scalar::Bool));
    pub const ERROR: Type = Type::new(Base::Error);

    pub const fn new(base: Base) -> Type {
        Type { base, array: None }
    }

    pub const fn vec(s: Scalar, n: u8) -> Type {
        if n == 1 {
            Type::new(Base::Scalar(s))
        } else {
            Type::new(Base::Vector(s, n))
        }
    }

    pub const fn mat(cols: u8, rows: u8) -> Type {
        Type::new(Base::Matrix { cols, rows })
    }

    pub const fn array_of(self, size: ArraySize) -> Type {
        Type {
            base: self.base,
            array: Some(size),
        }
    }

    /// The element type of an array, or `self` for a non-array.
    pub const fn element(self) -> Type {
        Type::new(self.base)
    }

    pub fn is_array(self) -> bool {
        self.array.is_some()
    }

    pub fn is_error(self) -> bool {
        self.base == Base::Error
    }

    pub fn is_void(self) -> bool {
        self.base == Base::Void && self.array.is_none()
    }

    /// The scalar kind of a scalar, vector or matrix.
    pub fn scalar(self) -> Option<Scalar> {
        if self.array.is_some() {
            return None;
        }
        match self.base {
            Base::Scalar(s) | Base::Vector(s, _) => Some(s),
            Base::Matrix { .. } => Some(Scalar::Float),
            _ => None,
        }
    }

    pub fn is_scalar(self) -> bool {
        self.array.is_none() && matches!(self.base, Base::Scalar(_))
    }

    pub fn is_vector(self) -> bool {
        self.array.is_none() && matches!(self.base, Base::Vector(..))
    }

    pub fn is_matrix(self) -> bool {
        self.array.is_none() && matches!(self.base, Base::Matrix { .. })
    }

    pub fn is_sampler(self) -> bool {
        matches!(self.base, Base::Sampler(_))
    }

    pub fn is_struct(self) -> bool {
        self.array.is_none() && matches!(self.base, Base::Struct(_))
    }

    /// Number of components of a scalar or vector (1 for scalars).
    pub fn vector_size(self) -> Option<u8> {
        if self.array.is_some() {
            return None;
        }
        match self.base {
            Base::Scalar(_) => Some(1),
            Base::Vector(_, n) => Some(n),
            _ => None,
        }
    }

    /// Number of scalar components of a scalar, vector or matrix.
    pub fn component_count(self) -> Option<u32> {
        if self.array.is_some() {
            return None;
        }
        match self.base {
            Base::Scalar(_) => Some(1),
            Base::Vector(_, n) => Some(n as u32),
            Base::Matrix { cols, rows } => Some(cols as u32 * rows as u32),
            _ => None,
        }
    }

    /// The same shape with another scalar kind (for conversions).
    pub fn with_scalar(self, s: Scalar) -> Type {
        match self.base {
            Base::Scalar(_) => Type {
                base: Base::Scalar(s),
                ..self
            },
            Base::Vector(_, n) => Type {
                base: Base::Vector(s, n),
                ..self
            },
            _ => self,
        }
    }

    /// Spells the type as GLSL source does. Struct names need the module's
    /// struct table, so they print through [`Type::display`].
    pub fn display<'a>(self, struct_name: &'a dyn Fn(StructId) -> String) -> TypeDisplay<'a> {
        TypeDisplay {
            ty: self,
            struct_name,
        }
    }
}

pub struct TypeDisplay<'a> {
    ty: Type,
    struct_name: &'a dyn Fn(StructId) -> String,
}

impl fmt::Display for TypeDisplay<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.ty.base {
            Base::Void => f.write_str("void")?,
            Base::Error => f.write_str("<error>")?,
            Base::Scalar(s) => f.write_str(s.name())?,
            Base::Vector(s, n) => {
                let p = match s {
                    Scalar::Float => "",
                    Scalar::Int => "i",
                    Scalar::Uint => "u",
                    Scalar::Bool => "b",
                };
                write!(f, "{p}vec{n}")?
            }
            Base::Matrix { cols, rows } if cols == rows => write!(f, "mat{cols}")?,
            Base::Matrix { cols, rows } => write!(f, "mat{cols}x{rows}")?,
            Base::Sampler(k) => f.write_str(k.name())?,
            Base::Struct(id) => f.write_str(&(self.struct_name)(id))?,
        }
        match self.ty.array {
            Some(ArraySize::Sized(n)) => write!(f, "[{n}]"),
            Some(ArraySize::Unsized) => f.write_str("[]"),
            None => Ok(()),
        }
    }
}

/// A member of a struct declaration.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StructMember {
    pub name: String,
    pub ty: Type,
}

/// A struct declaration.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StructDef {
    pub name: String,
    pub members: Vec<StructMember>,
    /// Declared by the implementation (`gl_LightSourceParameters`...).
    pub builtin: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display() {
        let none = |_| String::new();
        assert_eq!(Type::mat(2, 3).display(&none).to_string(), "mat2x3");
        assert_eq!(Type::mat(3, 3).display(&none).to_string(), "mat3");
        assert_eq!(
            Type::vec(Scalar::Int, 3)
                .array_of(ArraySize::Sized(4))
                .display(&none)
                .to_string(),
            "ivec3[4]"
        );
        assert_eq!(
            Type::vec(Scalar::Uint, 2).display(&none).to_string(),
            "uvec2"
        );
        assert_eq!(Type::UINT.display(&none).to_string(), "uint");
    }
}
