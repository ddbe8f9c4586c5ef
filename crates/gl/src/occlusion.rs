//! Query objects (GL 3.3 §2.14, §2.15, §5.1, §6.1.12) and conditional
//! rendering.
//!
//! - Occlusion queries: GL_SAMPLES_PASSED counts the fragments that pass
//!   the per-fragment tests up to and including the depth test (scissor,
//!   alpha, stencil, depth) while the query is active — of every draw and
//!   pixel rectangle, into the default framebuffer or a framebuffer
//!   object; GL_ANY_SAMPLES_PASSED (3.3) answers whether any did. One of
//!   the two is active at a time. The count comes from the rasterizer
//!   ([`raster::Framebuffer::samples_passed`], summed per tile), so it is
//!   exact and the same whatever the number of threads.
//! - Primitive queries (3.0): GL_PRIMITIVES_GENERATED counts the primitives
//!   a draw assembles (before clipping, whether or not rasterization is
//!   discarded); GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN the primitives
//!   transform feedback writes.
//! - Timer queries (3.3, ARB_timer_query): GL_TIME_ELAPSED measures the
//!   wall-clock nanoseconds between glBeginQuery and glEndQuery;
//!   glQueryCounter(GL_TIMESTAMP) records the GL time, which is also
//!   `glGetInteger64v(GL_TIMESTAMP)`: nanoseconds on a monotonic clock
//!   since the first time the process asked.
//! - Conditional rendering (§2.15): while active, draws and clears are
//!   skipped when the occlusion query's result is zero. Every mode waits
//!   (results are never pending), so GL_QUERY_NO_WAIT and
//!   GL_QUERY_BY_REGION_* behave as GL_QUERY_WAIT.
//!
//! Draws are synchronous, so a result is available as soon as glEndQuery
//! returns (GL_QUERY_RESULT_AVAILABLE is always true). Names follow GL 3.3:
//! in a core context glBeginQuery and glQueryCounter take only names from
//! glGenQueries; a compatibility or 2.1 context also accepts unused names,
//! as GL 2.1 did (and as Mesa does).

use crate::enums::*;
use crate::Context;
use std::collections::BTreeMap;
use std::sync::OnceLock;
use std::time::Instant;

/// Bits of every query counter (GL_QUERY_COUNTER_BITS).
pub const QUERY_COUNTER_BITS: i32 = 64;

/// The query targets a context has, in the order of [`Queries::active`].
const TARGETS: [u32; 5] = [
    GL_SAMPLES_PASSED,
    GL_ANY_SAMPLES_PASSED,
    GL_PRIMITIVES_GENERATED,
    GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN,
    GL_TIME_ELAPSED,
];

/// The GL time in nanoseconds (GL_TIMESTAMP).
pub fn timestamp_ns() -> i64 {
    static EPOCH: OnceLock<Instant> = OnceLock::new();
    let epoch = *EPOCH.get_or_init(Instant::now);
    epoch.elapsed().as_nanos().min(i64::MAX as u128) as i64
}

/// One query object.
#[derive(Clone, Debug, Default)]
pub struct QueryObj {
    /// The target glBeginQuery or glQueryCounter first used the name with
    /// (0: a name from glGenQueries alone, not yet an object; glIsQuery is
    /// false for it).
    pub target: u32,
    pub result: u64,
    /// When an active GL_TIME_ELAPSED query began (ns, [`timestamp_ns`]).
    started: i64,
}

/// The query objects of a context, the active query of each target and
/// the conditional-rendering query.
#[derive(Clone, Debug, Default)]
pub struct Queries {
    pub objects: BTreeMap<u32, QueryObj>,
    pub next: u32,
    /// The active query of each of `TARGETS` (0: none).
    pub active: [u32; 5],
    /// The query of the active conditional render (0: none).
    pub condition: u32,
}

impl Queries {
    /// The slot of `target` in [`Queries::active`].
    fn slot(target: u32) -> Option<usize> {
        TARGETS.iter().position(|&t| t == target)
    }

    fn is_active(&self, id: u32) -> bool {
        id != 0 && self.active.contains(&id)
    }

    /// Adds `n` to the active query of `target`, if any.
    fn add(&mut self, target: u32, n: u64) {
        let Some(slot) = Self::slot(target) else {
            return;
        };
        let id = self.active[slot];
        if id == 0 {
            return;
        }
        if let Some(q) = self.objects.get_mut(&id) {
            q.result = q.result.saturating_add(n);
        }
    }
}

/// The primitives `n` vertices of `mode` assemble (GL 3.3 §2.6.1).
pub(crate) fn primitive_count(mode: u32, n: u64) -> u64 {
    match mode {
        GL_POINTS => n,
        GL_LINES => n / 2,
        GL_LINE_STRIP => n.saturating_sub(1),
        GL_LINE_LOOP if n >= 2 => n,
        GL_TRIANGLES => n / 3,
        GL_TRIANGLE_STRIP | GL_TRIANGLE_FAN => n.saturating_sub(2),
        GL_QUADS => n / 4,
        GL_QUAD_STRIP => (n / 2).saturating_sub(1),
        GL_POLYGON if n >= 3 => 1,
        _ => 0,
    }
}

impl Context {
    /// Whether `target` is a glBeginQuery target of this context's
    /// version; records GL_INVALID_ENUM when not.
    fn query_target_ok(&mut self, target: u32) -> bool {
        let ok = match target {
            GL_SAMPLES_PASSED => true,
            GL_PRIMITIVES_GENERATED | GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN => {
                self.api.at_least(3, 0)
            }
            GL_ANY_SAMPLES_PASSED | GL_TIME_ELAPSED => self.api.at_least(3, 3),
            _ => false,
        };
        if !ok {
            self.set_error(GL_INVALID_ENUM);
        }
        ok
    }

    /// Adds `n` samples to the active occlusion query (draws call this
    /// with the fragments they let through).
    pub(crate) fn count_samples(&mut self, n: u64) {
        self.queries.add(GL_SAMPLES_PASSED, n);
        self.queries.add(GL_ANY_SAMPLES_PASSED, n);
    }

    /// Adds the primitives of `n` vertices of `mode` to the active
    /// GL_PRIMITIVES_GENERATED query.
    pub(crate) fn count_primitives(&mut self, mode: u32, n: usize) {
        if self.queries.active[2] != 0 {
            self.queries
                .add(GL_PRIMITIVES_GENERATED, primitive_count(mode, n as u64));
        }
    }

    /// Adds `n` to the active GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN
    /// query.
    pub(crate) fn count_primitives_written(&mut self, n: u64) {
        self.queries
            .add(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, n);
    }

    /// Whether conditional rendering discards rendering commands now: it
    /// is active and its query's result is zero (GL 3.3 §2.15).
    pub(crate) fn render_discarded(&self) -> bool {
        let id = self.queries.condition;
        id != 0 && self.queries.objects.get(&id).is_some_and(|q| q.result == 0)
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

    /// glDeleteQueries: unknown names and 0 are ignored; deleting an
    /// active query ends it.
    pub fn delete_queries(&mut self, names: &[u32]) {
        if self.reject_in_begin() {
            return;
        }
        for &n in names {
            if n != 0 && self.queries.objects.remove(&n).is_some() {
                for a in self.queries.active.iter_mut() {
                    if *a == n {
                        *a = 0;
                    }
                }
            }
        }
    }

    /// glIsQuery: true for a name glBeginQuery or glQueryCounter has used.
    pub fn is_query(&mut self, name: u32) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        self.queries
            .objects
            .get(&name)
            .is_some_and(|q| q.target != 0)
    }

    /// The query object `id` as one of `target`, made so if it is a name
    /// not yet used; None with GL_INVALID_OPERATION for 0, a name of
    /// another type, or (core) a name glGenQueries did not return.
    fn query_for(&mut self, target: u32, id: u32) -> Option<&mut QueryObj> {
        let known = self.queries.objects.get(&id).map(|q| q.target);
        let ok = match known {
            _ if id == 0 => false,
            Some(t) => t == 0 || t == target,
            None => !self.is_core(),
        };
        if !ok {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        let q = self.queries.objects.entry(id).or_default();
        q.target = target;
        Some(q)
    }

    /// glBeginQuery: the query's result restarts at 0 (a timer query
    /// notes the time).
    pub fn begin_query(&mut self, target: u32, id: u32) {
        if self.reject_in_begin() || !self.query_target_ok(target) {
            return;
        }
        let slot = Queries::slot(target).unwrap_or(0);
        // The two occlusion targets share one active query.
        let busy = match target {
            GL_SAMPLES_PASSED | GL_ANY_SAMPLES_PASSED => {
                self.queries.active[0] != 0 || self.queries.active[1] != 0
            }
            _ => self.queries.active[slot] != 0,
        };
        if busy || self.queries.is_active(id) || (id != 0 && self.queries.condition == id) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        // Timer queries time what the GL does between begin and end: the
        // draws queued before it run now, not within it.
        if target == GL_TIME_ELAPSED {
            self.flush_draws();
        }
        let Some(q) = self.query_for(target, id) else {
            return;
        };
        q.result = 0;
        q.started = if target == GL_TIME_ELAPSED {
            timestamp_ns()
        } else {
            0
        };
        self.queries.active[slot] = id;
    }

    /// glEndQuery: the result becomes available (GL_ANY_SAMPLES_PASSED
    /// as 0 or 1; GL_TIME_ELAPSED as the nanoseconds since glBeginQuery).
    pub fn end_query(&mut self, target: u32) {
        if self.reject_in_begin() || !self.query_target_ok(target) {
            return;
        }
        let slot = Queries::slot(target).unwrap_or(0);
        let id = std::mem::take(&mut self.queries.active[slot]);
        if id == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if target == GL_TIME_ELAPSED {
            self.flush_draws();
        }
        if let Some(q) = self.queries.objects.get_mut(&id) {
            match target {
                GL_ANY_SAMPLES_PASSED => q.result = (q.result != 0) as u64,
                GL_TIME_ELAPSED => q.result = timestamp_ns().saturating_sub(q.started) as u64,
                _ => {}
            }
        }
    }

    /// glQueryCounter(id, GL_TIMESTAMP): the query's result is the GL time
    /// now. GL_INVALID_ENUM for another target; GL_INVALID_OPERATION for an
    /// active query or a name of another type.
    pub fn query_counter(&mut self, id: u32, target: u32) {
        if self.reject_in_begin() {
            return;
        }
        if target != GL_TIMESTAMP || !self.api.at_least(3, 3) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if self.queries.is_active(id) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        // The time when the commands before it are done.
        self.flush_draws();
        if let Some(q) = self.query_for(GL_TIMESTAMP, id) {
            q.result = timestamp_ns() as u64;
        }
    }

    /// glGetQueryiv: GL_CURRENT_QUERY or GL_QUERY_COUNTER_BITS of a
    /// glBeginQuery target or GL_TIMESTAMP (never current).
    pub fn get_queryiv(&mut self, target: u32, pname: u32) -> Option<i32> {
        if self.reject_in_begin() {
            return None;
        }
        let current = if target == GL_TIMESTAMP && self.api.at_least(3, 3) {
            0
        } else if self.query_target_ok(target) {
            self.queries.active[Queries::slot(target).unwrap_or(0)]
        } else {
            return None;
        };
        match pname {
            GL_CURRENT_QUERY => Some(current as i32),
            GL_QUERY_COUNTER_BITS => Some(QUERY_COUNTER_BITS),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// `glGetQueryObject{i,ui,i64,ui64}v`: GL_QUERY_RESULT (the full
    /// value; the C layer clamps it to the variant's type) or
    /// GL_QUERY_RESULT_AVAILABLE (always true). GL_INVALID_OPERATION for
    /// a name that is not a query object or is an active query.
    pub fn get_query_object(&mut self, id: u32, pname: u32) -> Option<u64> {
        if self.reject_in_begin() {
            return None;
        }
        let result = match self.queries.objects.get(&id) {
            Some(q) if q.target != 0 && !self.queries.is_active(id) => q.result,
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

    /// glBeginConditionalRender (GL 3.3 §2.15): draws and clears until
    /// glEndConditionalRender are skipped if the occlusion query `id`'s
    /// result is zero. GL_INVALID_ENUM for an unknown mode;
    /// GL_INVALID_OPERATION while one is active, for a query of another
    /// type or an active query; GL_INVALID_VALUE for a name that is not a
    /// query object.
    pub fn begin_conditional_render(&mut self, id: u32, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !matches!(
            mode,
            GL_QUERY_WAIT | GL_QUERY_NO_WAIT | GL_QUERY_BY_REGION_WAIT | GL_QUERY_BY_REGION_NO_WAIT
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if self.queries.condition != 0 {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let Some(target) = self
            .queries
            .objects
            .get(&id)
            .map(|q| q.target)
            .filter(|&t| t != 0)
        else {
            self.set_error(GL_INVALID_VALUE);
            return;
        };
        if !matches!(target, GL_SAMPLES_PASSED | GL_ANY_SAMPLES_PASSED)
            || self.queries.is_active(id)
        {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.queries.condition = id;
    }

    /// glEndConditionalRender (GL_INVALID_OPERATION when none is active).
    pub fn end_conditional_render(&mut self) {
        if self.reject_in_begin() {
            return;
        }
        if self.queries.condition == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.queries.condition = 0;
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

    #[test]
    fn any_samples_passed_and_conditional_rendering() {
        let mut ctx = Context::with_api(10, 10, crate::Api::GL33_COMPAT);
        ctx.enable(GL_DEPTH_TEST);
        ctx.clear(GL_DEPTH_BUFFER_BIT);
        let q = ctx.gen_queries(2);
        // A quad in front: some samples pass.
        ctx.begin_query(GL_ANY_SAMPLES_PASSED, q[0]);
        assert_eq!(
            ctx.get_queryiv(GL_ANY_SAMPLES_PASSED, GL_CURRENT_QUERY),
            Some(q[0] as i32)
        );
        // The occlusion targets share their active query.
        ctx.begin_query(GL_SAMPLES_PASSED, q[1]);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        quad(&mut ctx, -1.0, 1.0, 0.0);
        ctx.end_query(GL_ANY_SAMPLES_PASSED);
        assert_eq!(ctx.get_query_object(q[0], GL_QUERY_RESULT), Some(1));
        // Behind it: none pass.
        ctx.begin_query(GL_ANY_SAMPLES_PASSED, q[1]);
        quad(&mut ctx, -1.0, 1.0, 0.5);
        ctx.end_query(GL_ANY_SAMPLES_PASSED);
        assert_eq!(ctx.get_query_object(q[1], GL_QUERY_RESULT), Some(0));
        assert_eq!(ctx.get_error(), GL_NO_ERROR);

        ctx.disable(GL_DEPTH_TEST);
        ctx.clear_color(0.0, 0.0, 1.0, 1.0);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        let pixel = |ctx: &mut Context| ctx.read_pixels_f32(5, 5, 1, 1)[0];
        for mode in [
            GL_QUERY_WAIT,
            GL_QUERY_NO_WAIT,
            GL_QUERY_BY_REGION_WAIT,
            GL_QUERY_BY_REGION_NO_WAIT,
        ] {
            // Zero result: the clear and the draw are skipped.
            ctx.begin_conditional_render(q[1], mode);
            ctx.clear_color(1.0, 0.0, 0.0, 1.0);
            ctx.clear(GL_COLOR_BUFFER_BIT);
            ctx.color_4f(0.0, 1.0, 0.0, 1.0);
            quad(&mut ctx, -1.0, 1.0, 0.0);
            // Pixel rectangles too; a bitmap does not move the raster
            // position.
            ctx.window_pos_3f(5.0, 5.0, 0.0);
            let t = crate::pixel_transfer::PixelTransfer::default();
            let red = [255u8, 0, 0, 255];
            ctx.draw_pixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&red), 4, &t);
            ctx.copy_pixels(0, 0, 10, 10, GL_COLOR, &t);
            ctx.bitmap(1, 1, 0.0, 0.0, 2.0, 0.0, Some(&[0x80]), 1);
            assert_eq!(ctx.raster_pos().window[0], 5.0);
            ctx.end_conditional_render();
            assert_eq!(pixel(&mut ctx), [0.0, 0.0, 1.0, 1.0]);
        }
        // Nonzero result: they happen.
        ctx.begin_conditional_render(q[0], GL_QUERY_WAIT);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        assert_eq!(pixel(&mut ctx), [1.0, 0.0, 0.0, 1.0]);
        quad(&mut ctx, -1.0, 1.0, 0.0);
        ctx.window_pos_3f(5.0, 5.0, 0.0);
        ctx.bitmap(1, 1, 0.0, 0.0, 2.0, 0.0, Some(&[0x80]), 1);
        assert_eq!(ctx.raster_pos().window[0], 7.0);
        ctx.end_conditional_render();
        assert_eq!(pixel(&mut ctx), [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn conditional_render_errors() {
        let mut ctx = Context::with_api(4, 4, crate::Api::GL33_CORE);
        let q = ctx.gen_queries(3);
        ctx.begin_query(GL_SAMPLES_PASSED, q[0]);
        ctx.end_query(GL_SAMPLES_PASSED);
        ctx.begin_query(GL_PRIMITIVES_GENERATED, q[1]);
        ctx.end_query(GL_PRIMITIVES_GENERATED);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.begin_conditional_render(q[0], GL_QUERY_RESULT);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.begin_conditional_render(99, GL_QUERY_WAIT);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.begin_conditional_render(q[2], GL_QUERY_WAIT);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.begin_conditional_render(q[1], GL_QUERY_WAIT);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.end_conditional_render();
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.begin_query(GL_SAMPLES_PASSED, q[0]);
        ctx.begin_conditional_render(q[0], GL_QUERY_WAIT);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.end_query(GL_SAMPLES_PASSED);
        ctx.begin_conditional_render(q[0], GL_QUERY_WAIT);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.begin_conditional_render(q[0], GL_QUERY_WAIT);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        // The condition's query cannot begin again while in use.
        ctx.begin_query(GL_SAMPLES_PASSED, q[0]);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.end_conditional_render();
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn primitive_and_timer_queries() {
        let mut ctx = Context::with_api(8, 8, crate::Api::GL33_COMPAT);
        let q = ctx.gen_queries(5);
        ctx.begin_query(GL_PRIMITIVES_GENERATED, q[0]);
        ctx.begin_query(GL_TIME_ELAPSED, q[1]);
        ctx.begin_query(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, q[4]);
        // Rasterizer discard does not stop primitives being generated.
        ctx.enable(GL_RASTERIZER_DISCARD);
        for (mode, n) in [
            (GL_TRIANGLE_STRIP, 5), // 3
            (GL_LINE_LOOP, 4),      // 4
            (GL_POINTS, 2),         // 2
            (GL_TRIANGLES, 7),      // 2
        ] {
            ctx.begin(mode);
            for k in 0..n {
                ctx.vertex_2f(k as f32 * 0.1, (k % 2) as f32 * 0.5);
            }
            ctx.end();
        }
        ctx.disable(GL_RASTERIZER_DISCARD);
        ctx.end_query(GL_PRIMITIVES_GENERATED);
        ctx.end_query(GL_TIME_ELAPSED);
        ctx.end_query(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
        assert_eq!(ctx.get_query_object(q[0], GL_QUERY_RESULT), Some(11));
        assert_eq!(ctx.get_query_object(q[4], GL_QUERY_RESULT), Some(0));
        let elapsed = ctx.get_query_object(q[1], GL_QUERY_RESULT).unwrap();
        assert!(elapsed > 0);
        // Timestamps: increasing, around glGetInteger64v(GL_TIMESTAMP).
        let t0 = ctx.get_integer64v(GL_TIMESTAMP)[0];
        ctx.query_counter(q[2], GL_TIMESTAMP);
        ctx.query_counter(q[3], GL_TIMESTAMP);
        let t1 = ctx.get_integer64v(GL_TIMESTAMP)[0];
        let (a, b) = (
            ctx.get_query_object(q[2], GL_QUERY_RESULT).unwrap() as i64,
            ctx.get_query_object(q[3], GL_QUERY_RESULT).unwrap() as i64,
        );
        assert!(t0 <= a && a <= b && b <= t1, "{t0} {a} {b} {t1}");
        assert!(ctx.is_query(q[2]));
        assert_eq!(ctx.get_queryiv(GL_TIMESTAMP, GL_CURRENT_QUERY), Some(0));
        assert_eq!(
            ctx.get_queryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS),
            Some(64)
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        // A timestamp query is not a GL_TIME_ELAPSED query, nor the reverse.
        ctx.begin_query(GL_TIME_ELAPSED, q[2]);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.query_counter(q[1], GL_TIMESTAMP);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.begin_query(GL_TIMESTAMP, q[2]);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.query_counter(q[2], GL_TIME_ELAPSED);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        // An active query cannot take a timestamp.
        ctx.begin_query(GL_TIME_ELAPSED, q[1]);
        ctx.query_counter(q[1], GL_TIMESTAMP);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        // Nor be queried, nor begin on another target.
        assert_eq!(ctx.get_query_object(q[1], GL_QUERY_RESULT), None);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.end_query(GL_TIME_ELAPSED);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn core_queries_need_generated_names_and_2_1_lacks_3_x_targets() {
        let mut core = Context::with_api(4, 4, crate::Api::GL33_CORE);
        core.begin_query(GL_SAMPLES_PASSED, 5);
        assert_eq!(core.get_error(), GL_INVALID_OPERATION);
        core.query_counter(6, GL_TIMESTAMP);
        assert_eq!(core.get_error(), GL_INVALID_OPERATION);
        let mut old = Context::new(4, 4);
        for t in [
            GL_ANY_SAMPLES_PASSED,
            GL_TIME_ELAPSED,
            GL_PRIMITIVES_GENERATED,
        ] {
            old.begin_query(t, 1);
            assert_eq!(old.get_error(), GL_INVALID_ENUM);
        }
        old.query_counter(1, GL_TIMESTAMP);
        assert_eq!(old.get_error(), GL_INVALID_ENUM);
        old.get_integer64v(GL_TIMESTAMP);
        assert_eq!(old.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn primitive_counts() {
        for (mode, n, want) in [
            (GL_POINTS, 3, 3),
            (GL_LINES, 5, 2),
            (GL_LINE_STRIP, 1, 0),
            (GL_LINE_STRIP, 4, 3),
            (GL_LINE_LOOP, 1, 0),
            (GL_LINE_LOOP, 3, 3),
            (GL_TRIANGLES, 8, 2),
            (GL_TRIANGLE_FAN, 2, 0),
            (GL_TRIANGLE_FAN, 6, 4),
            (GL_QUADS, 9, 2),
            (GL_QUAD_STRIP, 7, 2),
            (GL_POLYGON, 2, 0),
            (GL_POLYGON, 9, 1),
        ] {
            assert_eq!(primitive_count(mode, n), want, "{mode:#x} {n}");
        }
    }
}
