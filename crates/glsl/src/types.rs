//! GLSL types (1.10 to 3.30).
//!
//! [`Type`] is a small `Copy` value: a [`Base`] plus an optional array
//! size. An array of arrays (GL_ARB_arrays_of_arrays, and
//! GL_EXT_geometry_shader4's two-dimensional geometry inputs) is an array
//! of a synthesized one-member struct holding the inner array
//! ([`StructDef::array_row`]), so one array level per type suffices. Struct types are
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

macro_rules! sampler_kinds {
    ($($variant:ident = $name:literal, $dim:ident, $result:ident, $shadow:literal, $array:literal;)*) => {
        /// A sampler type (GLSL 1.30 §4.1.7 and its additions in 1.40 and
        /// 1.50): the texture target it reads, the kind of its results,
        /// whether it compares against a reference (shadow) and whether
        /// the texture is an array. Which version has each is the keyword
        /// table's (`crate::token`); which lookups each takes is
        /// `crate::builtins`'.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
        pub enum SamplerKind { $($variant),* }

        impl SamplerKind {
            pub const ALL: &'static [SamplerKind] = &[$(SamplerKind::$variant),*];

            pub fn name(self) -> &'static str {
                match self { $(SamplerKind::$variant => $name),* }
            }

            pub fn from_name(name: &str) -> Option<SamplerKind> {
                match name { $($name => Some(SamplerKind::$variant),)* _ => None }
            }

            /// The texture target it samples.
            pub fn dim(self) -> SamplerDim {
                match self { $(SamplerKind::$variant => SamplerDim::$dim),* }
            }

            /// The kind of a lookup's result components (`vec4`, `ivec4`
            /// or `uvec4`; a shadow lookup returns one `float`).
            pub fn result(self) -> SamplerResult {
                match self { $(SamplerKind::$variant => SamplerResult::$result),* }
            }

            pub fn is_shadow(self) -> bool {
                match self { $(SamplerKind::$variant => $shadow),* }
            }

            pub fn is_array(self) -> bool {
                match self { $(SamplerKind::$variant => $array),* }
            }
        }
    };
}

sampler_kinds! {
    Sampler1D = "sampler1D", D1, Float, false, false;
    Sampler2D = "sampler2D", D2, Float, false, false;
    Sampler3D = "sampler3D", D3, Float, false, false;
    SamplerCube = "samplerCube", Cube, Float, false, false;
    Sampler1DShadow = "sampler1DShadow", D1, Float, true, false;
    Sampler2DShadow = "sampler2DShadow", D2, Float, true, false;
    SamplerCubeShadow = "samplerCubeShadow", Cube, Float, true, false;
    Sampler1DArray = "sampler1DArray", D1, Float, false, true;
    Sampler2DArray = "sampler2DArray", D2, Float, false, true;
    Sampler1DArrayShadow = "sampler1DArrayShadow", D1, Float, true, true;
    Sampler2DArrayShadow = "sampler2DArrayShadow", D2, Float, true, true;
    ISampler1D = "isampler1D", D1, Int, false, false;
    ISampler2D = "isampler2D", D2, Int, false, false;
    ISampler3D = "isampler3D", D3, Int, false, false;
    ISamplerCube = "isamplerCube", Cube, Int, false, false;
    ISampler1DArray = "isampler1DArray", D1, Int, false, true;
    ISampler2DArray = "isampler2DArray", D2, Int, false, true;
    USampler1D = "usampler1D", D1, Uint, false, false;
    USampler2D = "usampler2D", D2, Uint, false, false;
    USampler3D = "usampler3D", D3, Uint, false, false;
    USamplerCube = "usamplerCube", Cube, Uint, false, false;
    USampler1DArray = "usampler1DArray", D1, Uint, false, true;
    USampler2DArray = "usampler2DArray", D2, Uint, false, true;
    Sampler2DRect = "sampler2DRect", Rect, Float, false, false;
    Sampler2DRectShadow = "sampler2DRectShadow", Rect, Float, true, false;
    ISampler2DRect = "isampler2DRect", Rect, Int, false, false;
    USampler2DRect = "usampler2DRect", Rect, Uint, false, false;
    SamplerBuffer = "samplerBuffer", Buffer, Float, false, false;
    ISamplerBuffer = "isamplerBuffer", Buffer, Int, false, false;
    USamplerBuffer = "usamplerBuffer", Buffer, Uint, false, false;
    Sampler2DMS = "sampler2DMS", Ms, Float, false, false;
    ISampler2DMS = "isampler2DMS", Ms, Int, false, false;
    USampler2DMS = "usampler2DMS", Ms, Uint, false, false;
    Sampler2DMSArray = "sampler2DMSArray", Ms, Float, false, true;
    ISampler2DMSArray = "isampler2DMSArray", Ms, Int, false, true;
    USampler2DMSArray = "usampler2DMSArray", Ms, Uint, false, true;
    SamplerCubeArray = "samplerCubeArray", Cube, Float, false, true;
    SamplerCubeArrayShadow = "samplerCubeArrayShadow", Cube, Float, true, true;
    ISamplerCubeArray = "isamplerCubeArray", Cube, Int, false, true;
    USamplerCubeArray = "usamplerCubeArray", Cube, Uint, false, true;
}

/// The texture target of a [`SamplerKind`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum SamplerDim {
    D1,
    D2,
    D3,
    Cube,
    /// `GL_TEXTURE_RECTANGLE`: unnormalized coordinates, no mipmaps.
    Rect,
    /// `GL_TEXTURE_BUFFER`: texels fetched by index only.
    Buffer,
    /// `GL_TEXTURE_2D_MULTISAMPLE`: texels fetched by sample only.
    Ms,
}

/// What the components of a [`SamplerKind`]'s lookups are.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum SamplerResult {
    Float,
    Int,
    Uint,
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

/// The member name of an ARB_arrays_of_arrays row
/// ([`StructDef::array_row`]): no identifier, so no `.name` in a shader
/// can reach it.
pub const ARRAY_ROW_MEMBER: &str = "";

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
    /// The element of an array of arrays: `float a[2][3]` is an array of 2
    /// of these, each with one member of type `float[3]`. Indexing the
    /// outer array yields that member (the analyzer writes `a[i]` as
    /// `a[i].<member>`), so the struct never appears as a value; its
    /// layout (flattened components, std140) is the member's, so an array
    /// of rows is laid out as the C-style array of arrays it stands for,
    /// inner dimension fastest. Its name is the row type's spelling
    /// (`float[3]`), its member's [`ARRAY_ROW_MEMBER`]: one row struct
    /// per row type, whether the array of arrays is an
    /// ARB_arrays_of_arrays one or a GL_EXT_geometry_shader4
    /// two-dimensional geometry input (`varying in float v[][4]`, one row
    /// per input vertex), so the two are the same type.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub array_row: bool,
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
