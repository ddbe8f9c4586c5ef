//! The C types of the GL and OSMesa ABI (x86-64 / aarch64 Linux).

pub type GLenum = u32;
pub type GLboolean = u8;
pub type GLbitfield = u32;
pub type GLbyte = i8;
pub type GLshort = i16;
pub type GLint = i32;
pub type GLsizei = i32;
pub type GLubyte = u8;
pub type GLushort = u16;
pub type GLuint = u32;
pub type GLfloat = f32;
pub type GLclampf = f32;
pub type GLdouble = f64;
pub type GLclampd = f64;
pub type GLchar = std::ffi::c_char;
pub type GLsizeiptr = isize;
pub type GLintptr = isize;

pub const GL_FALSE: GLboolean = 0;
pub const GL_TRUE: GLboolean = 1;
