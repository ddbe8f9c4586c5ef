//! Source text and positions.
//!
//! A shader object holds one or more source strings (`glShaderSource` takes a
//! count). GL compiles their concatenation, so the compiler works on one
//! [`SourceMap::text`] and every position is a byte range into it: a [`Span`].
//!
//! What the user sees is a *logical* location, [`Loc`]: the source-string
//! number and line as the GLSL spec defines them, which `#line` can change
//! (GLSL 1.20 §3.4: "`#line line source-string-number`"). The preprocessor
//! records each `#line` in the map, and [`SourceMap::loc`] applies them.

use serde::Serialize;

/// A byte range in the concatenated source text of one shader object.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
pub struct Span {
    pub start: u32,
    pub end: u32,
}

impl Span {
    pub const fn new(start: u32, end: u32) -> Span {
        Span { start, end }
    }

    /// The span from the start of `self` to the end of `other`.
    pub fn to(self, other: Span) -> Span {
        Span {
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }

    pub fn is_empty(self) -> bool {
        self.end <= self.start
    }
}

/// A logical location: what GL info logs print as `SOURCE:LINE(COLUMN)`.
/// Lines and columns start at 1.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Loc {
    pub source: u32,
    pub line: u32,
    pub column: u32,
}

/// A `#line` directive seen by the preprocessor: the physical line after
/// `at_line` (0-based physical line of the directive) has logical number
/// `line`, and if `source` is set, the logical source-string number changes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct LineDirective {
    at_line: u32,
    line: u32,
    source: Option<u32>,
}

/// The text of one shader object and the tables that turn spans into
/// locations.
#[derive(Clone, Debug, Default)]
pub struct SourceMap {
    /// An optional name (a file path) used by the terminal renderer.
    pub name: String,
    text: String,
    /// Byte offset where each source string starts.
    string_starts: Vec<u32>,
    /// Byte offset where each physical line starts.
    line_starts: Vec<u32>,
    directives: Vec<LineDirective>,
}

impl SourceMap {
    /// One source string.
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> SourceMap {
        let text = text.into();
        SourceMap::from_strings(name, &[text.as_str()])
    }

    /// Several source strings, concatenated as `glShaderSource` does.
    pub fn from_strings(name: impl Into<String>, strings: &[&str]) -> SourceMap {
        let mut text = String::new();
        let mut string_starts = Vec::with_capacity(strings.len());
        for s in strings {
            string_starts.push(text.len() as u32);
            text.push_str(s);
        }
        if string_starts.is_empty() {
            string_starts.push(0);
        }
        let mut line_starts = vec![0u32];
        for (i, b) in text.bytes().enumerate() {
            if b == b'\n' {
                line_starts.push(i as u32 + 1);
            }
        }
        SourceMap {
            name: name.into(),
            text,
            string_starts,
            line_starts,
            directives: Vec::new(),
        }
    }

    /// The source strings as given to [`SourceMap::from_strings`].
    pub fn strings(&self) -> Vec<&str> {
        let ends = self
            .string_starts
            .iter()
            .skip(1)
            .map(|&e| e as usize)
            .chain(std::iter::once(self.text.len()));
        self.string_starts
            .iter()
            .zip(ends)
            .map(|(&s, e)| self.text.get(s as usize..e).unwrap_or(""))
            .collect()
    }

    pub fn text(&self) -> &str {
        &self.text
    }

    /// The text a span covers (empty if the span is out of range).
    pub fn slice(&self, span: Span) -> &str {
        self.text
            .get(span.start as usize..span.end as usize)
            .unwrap_or("")
    }

    /// 0-based physical line containing byte `offset`.
    pub fn physical_line(&self, offset: u32) -> u32 {
        match self.line_starts.binary_search(&offset) {
            Ok(i) => i as u32,
            Err(i) => i as u32 - 1,
        }
    }

    /// Byte range of a 0-based physical line, without its newline.
    pub fn line_range(&self, line: u32) -> Span {
        let start = self.line_starts.get(line as usize).copied().unwrap_or(0);
        let mut end = self
            .line_starts
            .get(line as usize + 1)
            .map(|e| e - 1)
            .unwrap_or(self.text.len() as u32);
        if end > start && self.text.as_bytes().get(end as usize - 1) == Some(&b'\r') {
            end -= 1;
        }
        Span::new(start, end)
    }

    /// Records a `#line` directive found on physical line `at_line`
    /// (0-based): the next physical line gets logical number `line`.
    pub fn add_line_directive(&mut self, at_line: u32, line: u32, source: Option<u32>) {
        self.directives.push(LineDirective {
            at_line,
            line,
            source,
        });
    }

    /// The logical location of a byte offset.
    pub fn loc(&self, offset: u32) -> Loc {
        let offset = offset.min(self.text.len() as u32);
        let pline = self.physical_line(offset);
        let string = match self.string_starts.binary_search(&offset) {
            Ok(i) => i,
            Err(i) => i.saturating_sub(1),
        };
        let string_start = self.string_starts[string];
        let line_start = self.line_starts[pline as usize].max(string_start);
        let column = offset - line_start + 1;
        // GLSL counts lines per source string (1.20 §3.4, `__LINE__`).
        let mut line = pline - self.physical_line(string_start) + 1;
        let mut source = string as u32;
        // The last directive before this line decides the numbering.
        for d in &self.directives {
            if d.at_line >= pline {
                break;
            }
            line = d.line.wrapping_add(pline - d.at_line - 1);
            if let Some(s) = d.source {
                source = s;
            }
        }
        Loc {
            source,
            line,
            column,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_columns() {
        let m = SourceMap::new("t", "ab\ncd\n\nef");
        assert_eq!(
            m.loc(0),
            Loc {
                source: 0,
                line: 1,
                column: 1
            }
        );
        assert_eq!(
            m.loc(4),
            Loc {
                source: 0,
                line: 2,
                column: 2
            }
        );
        assert_eq!(
            m.loc(7),
            Loc {
                source: 0,
                line: 4,
                column: 1
            }
        );
        assert_eq!(m.slice(m.line_range(1)), "cd");
    }

    #[test]
    fn line_directive() {
        let mut m = SourceMap::new("t", "a\n#line 10 3\nb\nc");
        m.add_line_directive(1, 10, Some(3));
        assert_eq!(m.loc(0).line, 1);
        let b = m.text().find('b').unwrap() as u32;
        assert_eq!(
            m.loc(b),
            Loc {
                source: 3,
                line: 10,
                column: 1
            }
        );
        let c = m.text().find('c').unwrap() as u32;
        assert_eq!(m.loc(c).line, 11);
    }

    #[test]
    fn several_strings() {
        let m = SourceMap::from_strings("t", &["a\n", "b\nc"]);
        assert_eq!(
            m.loc(2),
            Loc {
                source: 1,
                line: 1,
                column: 1
            }
        );
        assert_eq!(
            m.loc(4),
            Loc {
                source: 1,
                line: 2,
                column: 1
            }
        );
    }
}
