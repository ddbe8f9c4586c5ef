//! Symbol tables: the nested scopes of a shader and what each name means.
//!
//! All variable, structure and function names of one scope share one name
//! space (GLSL 1.20 §4.2.6); a name declared in an inner scope hides every
//! use of it from outer scopes. The built-ins live in a scope outside the
//! global one (kept in the shared [`super::BuiltinEnv`], not here).

use crate::ir::{FunctionId, GlobalId, LocalId};
use crate::types::StructId;
use smol_str::SmolStr;
// FxHash: symbol names are short and trusted to be few; SipHash showed
// up at 4% of compile time.
use rustc_hash::FxHashMap as HashMap;

/// A variable a name refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Var {
    Global(GlobalId),
    Local(LocalId),
    /// Index into the built-in environment's globals.
    Builtin(u32),
}

/// A function overload a name refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FnRef {
    User(FunctionId),
    /// Index into the built-in environment's function signatures.
    Builtin(u32),
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Symbol {
    Var(Var),
    /// All overloads declared under this name in one scope.
    Funcs(Vec<FnRef>),
    Struct(StructId),
}

/// The stack of user scopes; index 0 is the global scope.
#[derive(Debug, Default)]
pub(crate) struct Scopes {
    levels: Vec<HashMap<SmolStr, Symbol>>,
}

impl Scopes {
    pub fn new() -> Scopes {
        Scopes {
            levels: vec![HashMap::default()],
        }
    }

    pub fn push(&mut self) {
        self.levels.push(HashMap::default());
    }

    pub fn pop(&mut self) {
        if self.levels.len() > 1 {
            self.levels.pop();
        }
    }

    pub fn is_global(&self) -> bool {
        self.levels.len() == 1
    }

    /// The innermost meaning of `name` among the user scopes.
    pub fn lookup(&self, name: &str) -> Option<&Symbol> {
        self.levels.iter().rev().find_map(|l| l.get(name))
    }

    /// The meaning of `name` in the current (innermost) scope only.
    pub fn lookup_current(&self, name: &str) -> Option<&Symbol> {
        self.levels.last().and_then(|l| l.get(name))
    }

    /// Binds `name` in the current scope, replacing any binding there.
    pub fn insert(&mut self, name: SmolStr, sym: Symbol) {
        if let Some(l) = self.levels.last_mut() {
            l.insert(name, sym);
        }
    }

    /// Adds a function overload to `name` in the global scope.
    pub fn add_function(&mut self, name: &SmolStr, f: FnRef) {
        let global = &mut self.levels[0];
        match global.get_mut(name) {
            Some(Symbol::Funcs(v)) => v.push(f),
            _ => {
                global.insert(name.clone(), Symbol::Funcs(vec![f]));
            }
        }
    }

    /// Every name visible from the current scope (for suggestions).
    pub fn names(&self) -> impl Iterator<Item = &SmolStr> {
        self.levels.iter().flat_map(|l| l.keys())
    }

    /// The global scope's table (used to build the built-in environment).
    pub fn into_global(mut self) -> HashMap<SmolStr, Symbol> {
        self.levels.truncate(1);
        self.levels.pop().unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inner_scope_hides_outer() {
        let mut s = Scopes::new();
        s.insert("a".into(), Symbol::Var(Var::Global(GlobalId(0))));
        s.push();
        s.insert("a".into(), Symbol::Var(Var::Local(LocalId(3))));
        assert_eq!(s.lookup("a"), Some(&Symbol::Var(Var::Local(LocalId(3)))));
        s.pop();
        assert_eq!(s.lookup("a"), Some(&Symbol::Var(Var::Global(GlobalId(0)))));
        assert!(s.is_global());
    }

    #[test]
    fn overloads_accumulate() {
        let mut s = Scopes::new();
        s.add_function(&"f".into(), FnRef::User(FunctionId(0)));
        s.add_function(&"f".into(), FnRef::User(FunctionId(1)));
        match s.lookup("f") {
            Some(Symbol::Funcs(v)) => assert_eq!(v.len(), 2),
            other => panic!("{other:?}"),
        }
    }
}
