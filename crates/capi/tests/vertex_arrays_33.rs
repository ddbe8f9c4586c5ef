//! The GL 3.0-3.3 vertex-array and draw entry points, driven as a C
//! program would: vertex array objects over buffer objects, integer
//! attributes, instanced draws from client memory and buffers,
//! base-vertex draws, primitive restart, and their lookup by name.

use gl::enums::*;
use std::ffi::c_void;
use std::ptr::{null, null_mut};
use OSMesa::*;

mod common;

const W: i32 = 16;
const H: i32 = 4;

/// Every entry point this file covers.
const NAMES: &[&str] = &[
    "glGenVertexArrays",
    "glBindVertexArray",
    "glDeleteVertexArrays",
    "glIsVertexArray",
    "glVertexAttribIPointer",
    "glVertexAttribDivisor",
    "glVertexAttribI1i",
    "glVertexAttribI2i",
    "glVertexAttribI3i",
    "glVertexAttribI4i",
    "glVertexAttribI1ui",
    "glVertexAttribI2ui",
    "glVertexAttribI3ui",
    "glVertexAttribI4ui",
    "glVertexAttribI1iv",
    "glVertexAttribI2iv",
    "glVertexAttribI3iv",
    "glVertexAttribI4iv",
    "glVertexAttribI1uiv",
    "glVertexAttribI2uiv",
    "glVertexAttribI3uiv",
    "glVertexAttribI4uiv",
    "glVertexAttribI4bv",
    "glVertexAttribI4sv",
    "glVertexAttribI4ubv",
    "glVertexAttribI4usv",
    "glGetVertexAttribIiv",
    "glGetVertexAttribIuiv",
    "glDrawArraysInstanced",
    "glDrawElementsInstanced",
    "glDrawElementsBaseVertex",
    "glDrawRangeElementsBaseVertex",
    "glDrawElementsInstancedBaseVertex",
    "glMultiDrawElementsBaseVertex",
    "glPrimitiveRestartIndex",
    "glVertexAttribP1ui",
    "glVertexAttribP2ui",
    "glVertexAttribP3ui",
    "glVertexAttribP4ui",
    "glVertexAttribP1uiv",
    "glVertexAttribP2uiv",
    "glVertexAttribP3uiv",
    "glVertexAttribP4uiv",
    "glVertexP2ui",
    "glVertexP2uiv",
    "glVertexP3ui",
    "glVertexP3uiv",
    "glVertexP4ui",
    "glVertexP4uiv",
    "glTexCoordP1ui",
    "glTexCoordP1uiv",
    "glTexCoordP2ui",
    "glTexCoordP2uiv",
    "glTexCoordP3ui",
    "glTexCoordP3uiv",
    "glTexCoordP4ui",
    "glTexCoordP4uiv",
    "glMultiTexCoordP1ui",
    "glMultiTexCoordP1uiv",
    "glMultiTexCoordP2ui",
    "glMultiTexCoordP2uiv",
    "glMultiTexCoordP3ui",
    "glMultiTexCoordP3uiv",
    "glMultiTexCoordP4ui",
    "glMultiTexCoordP4uiv",
    "glNormalP3ui",
    "glNormalP3uiv",
    "glColorP3ui",
    "glColorP3uiv",
    "glColorP4ui",
    "glColorP4uiv",
    "glSecondaryColorP3ui",
    "glSecondaryColorP3uiv",
    "glDrawRangeElements",
    "glMultiDrawArrays",
    "glMultiDrawElements",
];

/// The locations of [`VS`]'s attributes `corner`, `code` and `shift` in
/// program `p`.
unsafe fn attributes(p: u32) -> [u32; 3] {
    ["corner", "code", "shift"].map(|name| common::attrib_location(p, name))
}

fn px(buf: &[u8], x: i32, y: i32) -> [u8; 4] {
    let i = ((y * W + x) * 4) as usize;
    [buf[i], buf[i + 1], buf[i + 2], buf[i + 3]]
}

/// Squares of 4x4 pixels at x = 4 * k (k = instance or vertex), colour
/// from an integer attribute.
const VS: &str = "#version 140\n\
    in vec2 corner;\n\
    in ivec2 code;\n\
    in float shift;\n\
    flat out vec4 c;\n\
    void main() {\n\
      vec2 o = vec2(-0.75 + 0.5 * (float(gl_InstanceID) + shift), 0.0);\n\
      gl_Position = vec4(corner * vec2(0.25, 1.0) + o, 0.0, 1.0);\n\
      c = code.x == -7 ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(float(code.y) / 255.0, 0.0, 0.0, 1.0);\n\
    }";
const FS: &str = "#version 140\n\
    flat in vec4 c;\n\
    out vec4 color;\n\
    void main() { color = c; }";

const CORNERS: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];

#[test]
fn every_new_entry_point_is_exported() {
    common::assert_exported(NAMES);
}

#[test]
fn instanced_integer_attributes_from_a_vertex_array_object() {
    common::with_context(W, H, None, |buf| unsafe {
        let p = common::program(VS, FS);
        let [corner, code, shift] = attributes(p);
        let mut vao = 0;
        glGenVertexArrays(1, &mut vao);
        assert_eq!(glIsVertexArray(vao), 0);
        glBindVertexArray(vao);
        assert_eq!(glIsVertexArray(vao), 1);
        let corners = common::buffer(GL_ARRAY_BUFFER, &CORNERS);
        glVertexAttribPointer(corner, 2, GL_FLOAT, 0, 0, null());
        glEnableVertexAttribArray(corner);
        // One code per instance: (-7, 0) green, (0, 200) red.
        let codes: [i32; 4] = [-7, 0, 0, 200];
        common::buffer(GL_ARRAY_BUFFER, &codes);
        glVertexAttribIPointer(code, 2, GL_INT, 0, null());
        glVertexAttribDivisor(code, 1);
        glEnableVertexAttribArray(code);
        glVertexAttrib1f(shift, 0.0);
        let elements: [u16; 4] = [0, 1, 2, 3];
        common::buffer(GL_ELEMENT_ARRAY_BUFFER, &elements);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        let mut v = [0i32; 1];
        glGetVertexAttribIiv(code, GL_VERTEX_ATTRIB_ARRAY_INTEGER, v.as_mut_ptr());
        assert_eq!(v[0], 1);
        glGetVertexAttribiv(code, GL_VERTEX_ATTRIB_ARRAY_DIVISOR, v.as_mut_ptr());
        assert_eq!(v[0], 1);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, v.as_mut_ptr());
        assert_eq!(v[0], vao as i32);
        // Client pointers are refused in a vertex array object.
        glVertexAttribPointer(corner, 2, GL_FLOAT, 0, 0, CORNERS.as_ptr() as *const c_void);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        let mut ptr: *mut c_void = null_mut();
        glGetVertexAttribPointerv(corner, GL_VERTEX_ATTRIB_ARRAY_POINTER, &mut ptr);
        assert!(ptr.is_null());

        glClearColor(0.0, 0.0, 0.0, 0.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawElementsInstanced(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_SHORT, null(), 2);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glFinish();
        assert_eq!(px(buf, 2, 2), [0, 255, 0, 255]);
        assert_eq!(px(buf, 6, 2), [200, 0, 0, 255]);
        assert_eq!(px(buf, 10, 2), [0; 4]);

        // The default object: client memory, instanced too.
        glBindVertexArray(0);
        glVertexAttribPointer(corner, 2, GL_FLOAT, 0, 0, CORNERS.as_ptr() as *const c_void);
        glEnableVertexAttribArray(corner);
        let client_codes: [i16; 6] = [0, 10, 0, 20, -7, 0];
        glVertexAttribIPointer(code, 2, GL_SHORT, 0, client_codes.as_ptr() as *const c_void);
        glVertexAttribDivisor(code, 1);
        glEnableVertexAttribArray(code);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 3);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glFinish();
        assert_eq!(px(buf, 2, 2), [10, 0, 0, 255]);
        assert_eq!(px(buf, 6, 2), [20, 0, 0, 255]);
        assert_eq!(px(buf, 10, 2), [0, 255, 0, 255]);
        // The object kept its state; each object answers for its own
        // pointers.
        glGetVertexAttribPointerv(code, GL_VERTEX_ATTRIB_ARRAY_POINTER, &mut ptr);
        assert_eq!(ptr as usize, client_codes.as_ptr() as usize);
        glBindVertexArray(vao);
        glGetVertexAttribPointerv(code, GL_VERTEX_ATTRIB_ARRAY_POINTER, &mut ptr);
        assert!(ptr.is_null());
        glGetVertexAttribiv(
            corner,
            GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING,
            v.as_mut_ptr(),
        );
        assert_eq!(v[0], corners as i32);
        glDeleteVertexArrays(1, &vao);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, v.as_mut_ptr());
        assert_eq!(v[0], 0);
        glBindVertexArray(vao);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
    });
}

#[test]
fn base_vertex_restart_and_current_integer_values() {
    common::with_context(W, H, None, |buf| unsafe {
        let p = common::program(VS, FS);
        let [corner, code, shift] = attributes(p);
        // Two copies of the square's corners, each with a shift: the
        // first at 0, the second at 2 (x = 8..12).
        let corners: Vec<f32> = CORNERS.iter().chain(&CORNERS).copied().collect();
        let shifts: [f32; 8] = [0.0, 0.0, 0.0, 0.0, 2.0, 2.0, 2.0, 2.0];
        glVertexAttribPointer(corner, 2, GL_FLOAT, 0, 0, corners.as_ptr() as *const c_void);
        glEnableVertexAttribArray(corner);
        glVertexAttribPointer(shift, 1, GL_FLOAT, 0, 0, shifts.as_ptr() as *const c_void);
        glEnableVertexAttribArray(shift);
        glVertexAttribI2i(code, -7, 0);
        let mut iv = [0i32; 4];
        glGetVertexAttribIiv(code, GL_CURRENT_VERTEX_ATTRIB, iv.as_mut_ptr());
        assert_eq!(iv, [-7, 0, 0, 1]);
        glClearColor(0.0, 0.0, 0.0, 0.0);
        glClear(GL_COLOR_BUFFER_BIT);
        // Base vertex 4: the second copy (x = 8..12) only.
        let elements: [u8; 4] = [0, 1, 2, 3];
        glDrawElementsBaseVertex(
            GL_TRIANGLE_STRIP,
            4,
            GL_UNSIGNED_BYTE,
            elements.as_ptr() as *const c_void,
            4,
        );
        assert_eq!(glGetError(), GL_NO_ERROR);
        glFinish();
        assert_eq!(px(buf, 2, 2), [0; 4]);
        assert_eq!(px(buf, 10, 2), [0, 255, 0, 255]);
        // Restart: both squares from one strip list, without joining.
        glEnable(GL_PRIMITIVE_RESTART);
        glPrimitiveRestartIndex(0xffff);
        let strip: [u16; 9] = [0, 1, 2, 3, 0xffff, 4, 5, 6, 7];
        glVertexAttribI4ui(code, 0, 50, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawElements(
            GL_TRIANGLE_STRIP,
            9,
            GL_UNSIGNED_SHORT,
            strip.as_ptr() as *const c_void,
        );
        assert_eq!(glGetError(), GL_NO_ERROR);
        glFinish();
        assert_eq!(px(buf, 2, 2), [50, 0, 0, 255]);
        assert_eq!(px(buf, 6, 2), [0; 4]);
        assert_eq!(px(buf, 10, 2), [50, 0, 0, 255]);
        let mut restart = 0u8;
        glGetBooleanv(GL_PRIMITIVE_RESTART, &mut restart);
        assert_eq!(restart, 1);
        let mut index = 0;
        glGetIntegerv(GL_PRIMITIVE_RESTART_INDEX, &mut index);
        assert_eq!(index, 0xffff);
        // Multi-draw with base vertices: both squares again.
        glDisable(GL_PRIMITIVE_RESTART);
        glClear(GL_COLOR_BUFFER_BIT);
        let counts = [4, 4];
        let lists = [
            elements.as_ptr() as *const c_void,
            elements.as_ptr() as *const c_void,
        ];
        let bases = [0, 4];
        glMultiDrawElementsBaseVertex(
            GL_TRIANGLE_STRIP,
            counts.as_ptr(),
            GL_UNSIGNED_BYTE,
            lists.as_ptr(),
            2,
            bases.as_ptr(),
        );
        glDrawRangeElementsBaseVertex(
            GL_TRIANGLE_STRIP,
            0,
            3,
            4,
            GL_UNSIGNED_BYTE,
            elements.as_ptr() as *const c_void,
            0,
        );
        assert_eq!(glGetError(), GL_NO_ERROR);
        glFinish();
        assert_eq!(px(buf, 2, 2), [50, 0, 0, 255]);
        assert_eq!(px(buf, 10, 2), [50, 0, 0, 255]);
    });
}

#[test]
fn errors_the_spec_names() {
    common::with_context(W, H, None, |_| unsafe {
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, -1);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glDrawElementsInstanced(GL_TRIANGLES, 3, GL_FLOAT, null(), 1);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glDrawRangeElementsBaseVertex(GL_TRIANGLES, 3, 2, 3, GL_UNSIGNED_BYTE, null(), 0);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glMultiDrawElementsBaseVertex(GL_TRIANGLES, null(), GL_UNSIGNED_BYTE, null(), -1, null());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glVertexAttribIPointer(0, 4, GL_FLOAT, 0, null());
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glVertexAttribIPointer(1000, 4, GL_INT, 0, null());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glVertexAttribDivisor(1000, 1);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glVertexAttribI4i(1000, 0, 0, 0, 0);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        // Packed current values.
        let word: u32 = 1023 | (1 << 10) | (2 << 20) | (1 << 30);
        glVertexAttribP4uiv(3, GL_UNSIGNED_INT_2_10_10_10_REV, 0, &word);
        let mut f = [0f32; 4];
        glGetVertexAttribfv(3, GL_CURRENT_VERTEX_ATTRIB, f.as_mut_ptr());
        assert_eq!(f, [1023.0, 1.0, 2.0, 1.0]);
        glVertexAttribP2ui(3, GL_INT_2_10_10_10_REV, 1, word);
        glGetVertexAttribfv(3, GL_CURRENT_VERTEX_ATTRIB, f.as_mut_ptr());
        assert_eq!(f, [-1.0 / 1023.0, 3.0 / 1023.0, 0.0, 1.0]);
        glVertexAttribP4ui(3, GL_FLOAT, 0, word);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        // The fixed-function attributes: colours normalized.
        glColorP4ui(GL_UNSIGNED_INT_2_10_10_10_REV, 1023 | (3 << 30));
        glGetFloatv(GL_CURRENT_COLOR, f.as_mut_ptr());
        assert_eq!(f, [1.0, 0.0, 0.0, 1.0]);
        glMultiTexCoordP2uiv(GL_TEXTURE1, GL_INT_2_10_10_10_REV, &word);
        glActiveTexture(GL_TEXTURE1);
        glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f.as_mut_ptr());
        assert_eq!(f, [-1.0, 1.0, 0.0, 1.0]);
        glNormalP3ui(GL_FLOAT, 0);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glGenVertexArrays(-1, null_mut());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glDeleteVertexArrays(-1, null());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glBindVertexArray(42);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        // Null name arrays: nothing happens.
        glGenVertexArrays(2, null_mut());
        glDeleteVertexArrays(2, null());
        assert_eq!(glGetError(), GL_NO_ERROR);
        // Instanced draws are not compiled into display lists.
        glNewList(1, GL_COMPILE);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, 1);
        glEndList();
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
    });
}
