//! Coordinate transformations and clipping (GL 2.1 §2.11, §2.12): the
//! viewport and depth range, the matrix stacks and matrix commands
//! (transpose forms included), and the client clip planes.

use crate::abi::*;
use crate::context::{record_call, record_vector, with_ctx};

gl_entry_points! {
    // ---- viewport ----
    [list] fn glViewport(x: GLint, y: GLint, w: GLsizei, h: GLsizei) => |c| { c.gl.viewport(x, y, w, h) }
    [list] fn glDepthRange(n: GLclampd, f: GLclampd) => |c| { c.gl.depth_range(n, f) }

    // ---- matrices ----
    [list] fn glMatrixMode(mode: GLenum) => |c| { c.gl.matrix_mode(mode) }
    [list] fn glLoadIdentity() => |c| { c.gl.load_identity() }
    [list] fn glPushMatrix() => |c| { c.gl.push_matrix() }
    [list] fn glPopMatrix() => |c| { c.gl.pop_matrix() }
    [list] fn glOrtho(l: GLdouble, r: GLdouble, bo: GLdouble, t: GLdouble, n: GLdouble, f: GLdouble) => |c| {
        c.gl.ortho(l, r, bo, t, n, f)
    }
    [list] fn glFrustum(l: GLdouble, r: GLdouble, bo: GLdouble, t: GLdouble, n: GLdouble, f: GLdouble) => |c| {
        c.gl.frustum(l, r, bo, t, n, f)
    }
    [list] fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) => |c| { c.gl.translatef(x, y, z) }
    [list] fn glTranslated(x: GLdouble, y: GLdouble, z: GLdouble) => |c| {
        c.gl.translatef(x as f32, y as f32, z as f32)
    }
    [list] fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat) => |c| { c.gl.scalef(x, y, z) }
    [list] fn glScaled(x: GLdouble, y: GLdouble, z: GLdouble) => |c| {
        c.gl.scalef(x as f32, y as f32, z as f32)
    }
    [list] fn glRotatef(a: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) => |c| { c.gl.rotatef(a, x, y, z) }
    [list] fn glRotated(a: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) => |c| {
        c.gl.rotatef(a as f32, x as f32, y as f32, z as f32)
    }
    fn glLoadMatrixf(m: *const GLfloat) => |c| {
        if record_vector::<16, f32>(c, m, move |p| unsafe { glLoadMatrixf(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f32>(m) { c.gl.load_matrixf(&m) }
    }
    fn glLoadMatrixd(m: *const GLdouble) => |c| {
        if record_vector::<16, f64>(c, m, move |p| unsafe { glLoadMatrixd(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f64>(m) { c.gl.load_matrixf(&m.map(|x| x as f32)) }
    }
    fn glMultMatrixf(m: *const GLfloat) => |c| {
        if record_vector::<16, f32>(c, m, move |p| unsafe { glMultMatrixf(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f32>(m) { c.gl.mult_matrixf(&m) }
    }
    fn glMultMatrixd(m: *const GLdouble) => |c| {
        if record_vector::<16, f64>(c, m, move |p| unsafe { glMultMatrixd(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f64>(m) { c.gl.mult_matrixf(&m.map(|x| x as f32)) }
    }
    fn glLoadTransposeMatrixf(m: *const GLfloat) => |c| {
        if record_vector::<16, f32>(c, m, move |p| unsafe { glLoadTransposeMatrixf(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f32>(m) { c.gl.load_transpose_matrixf(&m) }
    }
    fn glMultTransposeMatrixf(m: *const GLfloat) => |c| {
        if record_vector::<16, f32>(c, m, move |p| unsafe { glMultTransposeMatrixf(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f32>(m) { c.gl.mult_transpose_matrixf(&m) }
    }
    fn glLoadTransposeMatrixd(m: *const GLdouble) => |c| {
        if record_vector::<16, f64>(c, m, move |p| unsafe { glLoadTransposeMatrixd(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f64>(m) { c.gl.load_transpose_matrixf(&m.map(|x| x as f32)) }
    }
    fn glMultTransposeMatrixd(m: *const GLdouble) => |c| {
        if record_vector::<16, f64>(c, m, move |p| unsafe { glMultTransposeMatrixd(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f64>(m) { c.gl.mult_transpose_matrixf(&m.map(|x| x as f32)) }
    }

    // ---- clip planes ----
    fn glClipPlane(plane: GLenum, eq: *const GLdouble) => |c| {
        if record_vector::<4, f64>(c, eq, move |p| unsafe { glClipPlane(plane, p) }) {
            return;
        }
        if let Some(e) = rd::<4, f64>(eq) { c.gl.clip_plane(plane, &e) }
    }
    fn glGetClipPlane(plane: GLenum, eq: *mut GLdouble) => |c| {
        let e = c.gl.get_clip_plane(plane);
        wr(eq, &e);
    }
}
