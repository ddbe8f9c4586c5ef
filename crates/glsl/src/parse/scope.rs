//! Which identifiers currently name struct types.
//!
//! GLSL's grammar needs the lexer hack of C: `S x;` declares a variable only
//! if `S` names a type at that point. Struct names follow the ordinary
//! scoping rules (GLSL 1.20 §4.2.2): a later declaration of the same name in
//! an inner scope hides the type ("If a nested scope redeclares a name used
//! in an outer scope, it hides all existing uses of that name"), and the
//! type comes back when that scope ends.

use smol_str::SmolStr;
// FxHash: symbol names are short and trusted to be few; SipHash showed
// up at 4% of compile time.
use rustc_hash::FxHashMap as HashMap;

/// A stack of scopes recording, for every name, whether its innermost
/// visible declaration is a struct type.
///
/// Lookups are O(1) (a map from each name to its stack of shadowing
/// declarations) so pathological inputs with many names stay linear. The map
/// is only queried, never iterated, so its order cannot leak into output.
#[derive(Debug)]
pub(super) struct Scopes {
    names: HashMap<SmolStr, Vec<bool>>,
    /// Names declared in each open scope, innermost last. The first frame is
    /// the global scope and is never popped.
    frames: Vec<Vec<SmolStr>>,
}

impl Scopes {
    /// The scopes at the start of a shader: the built-in struct types of
    /// GLSL 1.10/1.20 §7.5 (`gl_LightSourceParameters`...) already name
    /// types, in a scope outside the global one.
    pub(super) fn new() -> Scopes {
        let mut names = HashMap::default();
        for name in crate::builtins::BUILTIN_STRUCT_NAMES {
            names.insert(SmolStr::new_static(name), vec![true]);
        }
        Scopes {
            names,
            frames: vec![Vec::new()],
        }
    }

    pub(super) fn push(&mut self) {
        self.frames.push(Vec::new());
    }

    /// Closes the innermost scope, forgetting its declarations. The global
    /// scope stays.
    pub(super) fn pop(&mut self) {
        if self.frames.len() <= 1 {
            return;
        }
        let Some(frame) = self.frames.pop() else {
            return;
        };
        for name in frame {
            if let Some(stack) = self.names.get_mut(&name) {
                stack.pop();
                if stack.is_empty() {
                    self.names.remove(&name);
                }
            }
        }
    }

    /// Declares `name` in the innermost scope: a struct type if `is_type`,
    /// otherwise a variable (or parameter), which hides any type of that
    /// name.
    pub(super) fn declare(&mut self, name: &SmolStr, is_type: bool) {
        self.names.entry(name.clone()).or_default().push(is_type);
        if let Some(frame) = self.frames.last_mut() {
            frame.push(name.clone());
        }
    }

    /// True if `name` currently names a struct type.
    pub(super) fn is_type(&self, name: &str) -> bool {
        self.names
            .get(name)
            .and_then(|stack| stack.last())
            .copied()
            .unwrap_or(false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inner_variable_hides_type_until_scope_ends() {
        let mut s = Scopes::new();
        let n = SmolStr::new("S");
        assert!(!s.is_type("S"));
        s.declare(&n, true);
        assert!(s.is_type("S"));
        s.push();
        s.declare(&n, false);
        assert!(!s.is_type("S"));
        s.push();
        s.declare(&n, true);
        assert!(s.is_type("S"));
        s.pop();
        assert!(!s.is_type("S"));
        s.pop();
        assert!(s.is_type("S"));
        // The global scope is never popped.
        s.pop();
        assert!(s.is_type("S"));
    }
}
