//! The last line of defence against compiler bugs.
//!
//! The compiler must never panic, but if it does, the command reports an
//! internal error (with the panic message and where it happened) instead of
//! Rust's default backtrace chatter. [`guarded`] runs a closure under
//! `catch_unwind` with a panic hook that records the message silently.

use std::cell::{Cell, RefCell};
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

/// What a caught panic said.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Panic {
    pub message: String,
}

thread_local! {
    /// How many [`guarded`] calls are active on this thread.
    static DEPTH: Cell<u32> = const { Cell::new(0) };
    /// The message of the last panic caught on this thread.
    static LAST: RefCell<Option<String>> = const { RefCell::new(None) };
}

static INSTALL: Once = Once::new();

/// Installs (once per process) a hook that records panics inside
/// [`guarded`] quietly and leaves all other panics to the previous hook.
fn install_hook() {
    INSTALL.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if DEPTH.with(Cell::get) == 0 {
                previous(info);
                return;
            }
            let text = match info.location() {
                Some(loc) => format!(
                    "{} (at {}:{})",
                    payload_text(info.payload()),
                    loc.file(),
                    loc.line()
                ),
                None => payload_text(info.payload()),
            };
            LAST.with(|l| *l.borrow_mut() = Some(text));
        }));
    });
}

/// Runs `f`; a panic inside it becomes `Err(Panic)`.
pub fn guarded<T>(f: impl FnOnce() -> T) -> Result<T, Panic> {
    install_hook();
    DEPTH.with(|d| d.set(d.get() + 1));
    let result = panic::catch_unwind(AssertUnwindSafe(f));
    DEPTH.with(|d| d.set(d.get() - 1));
    result.map_err(|payload| {
        let recorded = LAST.with(|l| l.borrow_mut().take());
        Panic {
            message: recorded.unwrap_or_else(|| payload_text(payload.as_ref())),
        }
    })
}

fn payload_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        String::from("panic with a non-text payload")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passes_values_through() {
        assert_eq!(guarded(|| 40 + 2), Ok(42));
    }

    #[test]
    fn catches_panics_with_their_message() {
        let r: Result<(), Panic> = guarded(|| panic!("boom {}", 7));
        let p = r.unwrap_err();
        assert!(p.message.starts_with("boom 7 (at "), "{}", p.message);
        assert!(p.message.contains("guard.rs"), "{}", p.message);
    }
}
