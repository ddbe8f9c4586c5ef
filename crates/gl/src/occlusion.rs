//! Occlusion queries (GL 2.1 §4.1.7, §6.1.12): query objects of target
//! GL_SAMPLES_PASSED count the fragments that pass the per-fragment tests
//! up to and including the depth test (scissor, alpha, stencil, depth)
//! while the query is active — of every draw and pixel rectangle, into
//! the default framebuffer or a framebuffer object.
//!
//! The count comes from the rasterizer ([`raster::Framebuffer::samples_passed`],
//! summed per tile), so it is exact and the same whatever the number of
//! threads. Draws are synchronous, so a result is available as soon as
//! glEndQuery returns (GL_QUERY_RESULT_AVAILABLE is always true).

use crate::enums::*;
use crate::Context;
use std::collections::BTreeMap;

/// Bits of the samples-passed counter (GL_QUERY_COUNTER_BITS).
pub const QUERY_COUNTER_BITS: i32 = 64;

/// One query object.
#[derive(Clone, Debug, Default)]
pub struct QueryObj {
    /// Whether glBeginQuery ever used the name (glIsQuery is true from
    /// then on: a name from glGenQueries alone is not yet an object).
    pub bound: bool,
    pub result: u64,
}

/// The query objects of a context and the active occlusion query.
#[derive(Clone, Debug, Default)]
pub struct Queries {
    pub objects: BTreeMap<u32, QueryObj>,
    pub next: u32,
    /// The active GL_SAMPLES_PASSED query (0: none).
    pub active: u32,
}

impl Context {
    fn query_target_ok(&mut self, target: u32) -> bool {
        if target != GL_SAMPLES_PASSED {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        true
    }

    /// Adds `n` samples to the active occlusion query (draws call this
    /// with the fragments they let through).
    pub(crate) fn count_samples(&mut self, n: u64) {
        let active = self.queries.active;
        if let Some(q) = self.queries.objects.get_mut(&active) {
            q.result = q.result.wrapping_add(n);
        }
    }

    /// glGenQueries: `n` unused names (GL_INVALID_VALUE for n < 0).
    pub fn gen_queries(&mut self, n: i32) -> Vec<u32> {
        if self.reject_in_begin() {
            return Vec::new();
        }
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return Vec::new();
        }
        let mut out = Vec::with_capacity((n as usize).min(1 << 16));
        for _ in 0..n.min(1 << 20) {
            let mut name = self.queries.next.max(1);
            while self.queries.objects.contains_key(&name) {
                name = name.wrapping_add(1).max(1);
            }
            self.queries.next = name.wrapping_add(1).max(1);
            self.queries.objects.insert(name, QueryObj::default());
            out.push(name);
        }
        out
    }

    /// glDeleteQueries: unknown names and 0 are ignored; deleting the
    /// active query ends it.
    pub fn delete_queries(&mut self, names: &[u32]) {
        if self.reject_in_begin() {
            return;
        }
        for &n in names {
            if n != 0 && self.queries.objects.remove(&n).is_some() && self.queries.active == n {
                self.queries.active = 0;
            }
        }
    }

    /// glIsQuery: true for a name glBeginQuery has used.
    pub fn is_query(&mut self, name: u32) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        self.queries.objects.get(&name).is_some_and(|q| q.bound)
    }

    /// glBeginQuery(GL_SAMPLES_PASSED, id): the count restarts at 0.
    pub fn begin_query(&mut self, target: u32, id: u32) {
        if self.reject_in_begin() || !self.query_target_ok(target) {
            return;
        }
        if id == 0 || self.queries.active != 0 {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        // A name not from glGenQueries becomes a query object (GL 2.1
        // allows unused names as for the other object types).
        let q = self.queries.objects.entry(id).or_default();
        q.bound = true;
        q.result = 0;
        self.queries.active = id;
    }

    /// glEndQuery(GL_SAMPLES_PASSED).
    pub fn end_query(&mut self, target: u32) {
        if self.reject_in_begin() || !self.query_target_ok(target) {
            return;
        }
        if self.queries.active == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.queries.active = 0;
    }

    /// glGetQueryiv: GL_CURRENT_QUERY or GL_QUERY_COUNTER_BITS.
    pub fn get_queryiv(&mut self, target: u32, pname: u32) -> Option<i32> {
        if self.reject_in_begin() || !self.query_target_ok(target) {
            return None;
        }
        match pname {
            GL_CURRENT_QUERY => Some(self.queries.active as i32),
            GL_QUERY_COUNTER_BITS => Some(QUERY_COUNTER_BITS),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// `glGetQueryObject[u]iv`: GL_QUERY_RESULT (the full count; the C
    /// layer clamps it for the signed variant) or
    /// GL_QUERY_RESULT_AVAILABLE (always true). GL_INVALID_OPERATION for
    /// a name that is not a query object or is the active query.
    pub fn get_query_object(&mut self, id: u32, pname: u32) -> Option<u64> {
        if self.reject_in_begin() {
            return None;
        }
        let result = match self.queries.objects.get(&id) {
            Some(q) if q.bound && id != self.queries.active => q.result,
            _ => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
        };
        match pname {
            GL_QUERY_RESULT => Some(result),
            GL_QUERY_RESULT_AVAILABLE => Some(1),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quad(ctx: &mut Context, x0: f32, x1: f32, z: f32) {
        ctx.begin(GL_QUADS);
        for (x, y) in [(x0, -1.0), (x1, -1.0), (x1, 1.0), (x0, 1.0)] {
            ctx.vertex_3f(x, y, z);
        }
        ctx.end();
    }

    #[test]
    fn samples_passed_counts_what_passes_the_depth_test() {
        for threads in [1, 3] {
            let mut ctx = Context::new(100, 70);
            ctx.set_threads(threads);
            ctx.enable(GL_DEPTH_TEST);
            ctx.clear(GL_DEPTH_BUFFER_BIT);
            let q = ctx.gen_queries(2);
            assert_eq!(q, vec![1, 2]);
            assert!(!ctx.is_query(q[0]));
            ctx.begin_query(GL_SAMPLES_PASSED, q[0]);
            assert_eq!(
                ctx.get_queryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY),
                Some(1)
            );
            quad(&mut ctx, -1.0, 0.0, 0.0); // left half
            ctx.end_query(GL_SAMPLES_PASSED);
            ctx.begin_query(GL_SAMPLES_PASSED, q[1]);
            quad(&mut ctx, -1.0, 1.0, 0.5); // behind the left half
            ctx.clear(GL_COLOR_BUFFER_BIT); // clears count nothing
            ctx.end_query(GL_SAMPLES_PASSED);
            assert!(ctx.is_query(q[0]));
            assert_eq!(ctx.get_query_object(q[0], GL_QUERY_RESULT), Some(50 * 70));
            assert_eq!(ctx.get_query_object(q[1], GL_QUERY_RESULT), Some(50 * 70));
            assert_eq!(
                ctx.get_query_object(q[1], GL_QUERY_RESULT_AVAILABLE),
                Some(1)
            );
            assert_eq!(ctx.get_error(), GL_NO_ERROR);
        }
    }

    #[test]
    fn query_errors() {
        let mut ctx = Context::new(4, 4);
        ctx.begin_query(GL_SAMPLES_PASSED + 1, 1);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.begin_query(GL_SAMPLES_PASSED, 0);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.end_query(GL_SAMPLES_PASSED);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.begin_query(GL_SAMPLES_PASSED, 7);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.begin_query(GL_SAMPLES_PASSED, 8);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.get_query_object(7, GL_QUERY_RESULT), None);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.delete_queries(&[7]);
        assert_eq!(
            ctx.get_queryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY),
            Some(0)
        );
        assert_eq!(ctx.gen_queries(-1), Vec::<u32>::new());
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        assert_eq!(ctx.get_query_object(99, GL_QUERY_RESULT), None);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    }
}
