//! glPushAttrib / glPopAttrib (compiled into display lists) and
//! glPushClientAttrib / glPopClientAttrib (client state: executed at
//! once); the context keeps the GL state ([`gl::attrib_stack`]), this
//! layer the client pointers of the vertex arrays that go with it.

use crate::abi::*;
use crate::context::{record_call, with_ctx};
use gl::enums::*;

gl_entry_points! {
    [list] fn glPushAttrib(mask: GLbitfield) => |c| { c.gl.push_attrib(mask) }
    [list] fn glPopAttrib() => |c| { c.gl.pop_attrib() }
    fn glPushClientAttrib(mask: GLbitfield) => |c| {
        let depth = c.gl.get_integerv(GL_CLIENT_ATTRIB_STACK_DEPTH);
        c.gl.push_client_attrib(mask);
        if c.gl.get_integerv(GL_CLIENT_ATTRIB_STACK_DEPTH) != depth {
            c.client_attrib_stack.push((mask, c.arrays.clone()));
        }
    }
    fn glPopClientAttrib() => |c| {
        if let Some(mask) = c.gl.pop_client_attrib() {
            if let Some((_, arrays)) = c.client_attrib_stack.pop() {
                if mask & GL_CLIENT_VERTEX_ARRAY_BIT != 0 {
                    c.arrays = arrays;
                }
            }
        }
    }
}
