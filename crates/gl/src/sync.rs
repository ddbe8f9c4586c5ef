//! Sync objects (GL 3.3 §5.3, §6.1.8; ARB_sync): fences and the waits on
//! them. Every GL command has completed when it returns (draws are
//! synchronous), so a fence is signaled as soon as glFenceSync creates it:
//! glClientWaitSync answers GL_ALREADY_SIGNALED without blocking and
//! glWaitSync has nothing to wait for. The EGL layer's fences
//! (`shaderbox-egl`, `sync`) rest on the same fact but belong to a display,
//! not a context, so they keep their own table.
//!
//! A sync handle (`GLsync`) is a nonzero `u64` naming an entry of the
//! context's table; a C layer passes it as the pointer value. Handles are
//! never reused within a context, so a deleted handle stays invalid.

use crate::enums::*;
use crate::Context;
use std::collections::BTreeSet;

/// GL_TIMEOUT_IGNORED (GL 3.3 §5.3.1).
pub const GL_TIMEOUT_IGNORED: u64 = u64::MAX;

/// GL_MAX_SERVER_WAIT_TIMEOUT in nanoseconds: glWaitSync never blocks, so
/// any bound holds; this is Mesa's value, which clients have seen.
pub const MAX_SERVER_WAIT_TIMEOUT: i64 = 0x7fff_ffff_7fff_ffff;

/// The context's sync objects.
#[derive(Clone, Debug, Default)]
pub struct Syncs {
    live: BTreeSet<u64>,
    next: u64,
}

impl Context {
    /// Whether `sync` names a live sync object; records GL_INVALID_VALUE
    /// when it does not.
    fn sync_ok(&mut self, sync: u64) -> bool {
        if self.syncs.live.contains(&sync) {
            true
        } else {
            self.set_error(GL_INVALID_VALUE);
            false
        }
    }

    /// glFenceSync: a new, already signaled fence; 0 with GL_INVALID_ENUM
    /// for a condition other than GL_SYNC_GPU_COMMANDS_COMPLETE or
    /// GL_INVALID_VALUE for nonzero flags.
    pub fn fence_sync(&mut self, condition: u32, flags: u32) -> u64 {
        if self.reject_in_begin() {
            return 0;
        }
        if condition != GL_SYNC_GPU_COMMANDS_COMPLETE {
            self.set_error(GL_INVALID_ENUM);
            return 0;
        }
        if flags != 0 {
            self.set_error(GL_INVALID_VALUE);
            return 0;
        }
        self.syncs.next += 1;
        let h = self.syncs.next;
        self.syncs.live.insert(h);
        h
    }

    /// glIsSync.
    pub fn is_sync(&mut self, sync: u64) -> bool {
        !self.reject_in_begin() && self.syncs.live.contains(&sync)
    }

    /// glDeleteSync: 0 is ignored; any other non-sync is GL_INVALID_VALUE.
    pub fn delete_sync(&mut self, sync: u64) {
        if self.reject_in_begin() || sync == 0 || !self.sync_ok(sync) {
            return;
        }
        self.syncs.live.remove(&sync);
    }

    /// glClientWaitSync: GL_ALREADY_SIGNALED for a fence (they are all
    /// signaled); GL_WAIT_FAILED with GL_INVALID_VALUE for a non-sync or
    /// flags other than GL_SYNC_FLUSH_COMMANDS_BIT.
    pub fn client_wait_sync(&mut self, sync: u64, flags: u32, _timeout: u64) -> u32 {
        if self.reject_in_begin() || !self.sync_ok(sync) {
            return GL_WAIT_FAILED;
        }
        if flags & !GL_SYNC_FLUSH_COMMANDS_BIT != 0 {
            self.set_error(GL_INVALID_VALUE);
            return GL_WAIT_FAILED;
        }
        GL_ALREADY_SIGNALED
    }

    /// glWaitSync: flags must be 0 and timeout GL_TIMEOUT_IGNORED
    /// (GL_INVALID_VALUE otherwise, as for a non-sync).
    pub fn wait_sync(&mut self, sync: u64, flags: u32, timeout: u64) {
        if self.reject_in_begin() || !self.sync_ok(sync) {
            return;
        }
        if flags != 0 || timeout != GL_TIMEOUT_IGNORED {
            self.set_error(GL_INVALID_VALUE);
        }
    }

    /// glGetSynciv's one value for `pname` (GL_OBJECT_TYPE, GL_SYNC_STATUS,
    /// GL_SYNC_CONDITION, GL_SYNC_FLAGS); None with GL_INVALID_VALUE for a
    /// non-sync, GL_INVALID_ENUM for another pname. The C layer applies
    /// bufSize.
    pub fn get_synciv(&mut self, sync: u64, pname: u32) -> Option<i32> {
        if self.reject_in_begin() || !self.sync_ok(sync) {
            return None;
        }
        let v = match pname {
            GL_OBJECT_TYPE => GL_SYNC_FENCE,
            GL_SYNC_STATUS => GL_SIGNALED,
            GL_SYNC_CONDITION => GL_SYNC_GPU_COMMANDS_COMPLETE,
            GL_SYNC_FLAGS => 0,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(v as i32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Api;

    #[test]
    fn fences_are_signaled_at_creation() {
        let mut ctx = Context::with_api(4, 4, Api::GL33_CORE);
        let s = ctx.fence_sync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        assert_ne!(s, 0);
        assert!(ctx.is_sync(s));
        assert_eq!(
            ctx.get_synciv(s, GL_OBJECT_TYPE),
            Some(GL_SYNC_FENCE as i32)
        );
        assert_eq!(ctx.get_synciv(s, GL_SYNC_STATUS), Some(GL_SIGNALED as i32));
        assert_eq!(
            ctx.get_synciv(s, GL_SYNC_CONDITION),
            Some(GL_SYNC_GPU_COMMANDS_COMPLETE as i32)
        );
        assert_eq!(ctx.get_synciv(s, GL_SYNC_FLAGS), Some(0));
        assert_eq!(ctx.client_wait_sync(s, 0, 0), GL_ALREADY_SIGNALED);
        assert_eq!(
            ctx.client_wait_sync(s, GL_SYNC_FLUSH_COMMANDS_BIT, 1_000_000),
            GL_ALREADY_SIGNALED
        );
        ctx.wait_sync(s, 0, GL_TIMEOUT_IGNORED);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        let t = ctx.fence_sync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        assert_ne!(t, s);
        ctx.delete_sync(s);
        assert!(!ctx.is_sync(s));
        assert!(ctx.is_sync(t));
        assert_eq!(
            ctx.get_integer64v(GL_MAX_SERVER_WAIT_TIMEOUT),
            vec![MAX_SERVER_WAIT_TIMEOUT]
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn sync_errors() {
        let mut ctx = Context::with_api(4, 4, Api::GL33_CORE);
        assert_eq!(ctx.fence_sync(GL_SYNC_FENCE, 0), 0);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.fence_sync(GL_SYNC_GPU_COMMANDS_COMPLETE, 1), 0);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.delete_sync(0);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.delete_sync(5);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        assert!(!ctx.is_sync(0));
        assert_eq!(ctx.client_wait_sync(5, 0, 0), GL_WAIT_FAILED);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        let s = ctx.fence_sync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        assert_eq!(ctx.client_wait_sync(s, 2, 0), GL_WAIT_FAILED);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.wait_sync(s, 0, 0);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.wait_sync(s, 1, GL_TIMEOUT_IGNORED);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.wait_sync(s + 1, 0, GL_TIMEOUT_IGNORED);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        assert_eq!(ctx.get_synciv(s, GL_SYNC_FENCE), None);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.get_synciv(s + 1, GL_SYNC_STATUS), None);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.delete_sync(s);
        ctx.delete_sync(s);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    }
}
