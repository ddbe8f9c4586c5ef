//! Chemical elements: symbols, CPK colours and van der Waals radii.
//!
//! Colours are the usual CPK scheme as molecular viewers draw it (carbon
//! grey, nitrogen blue, oxygen red, sulfur yellow, phosphorus orange,
//! hydrogen white). Radii are Bondi's van der Waals radii (J. Phys. Chem.
//! 68, 441, 1964) where he gives one; other elements get
//! [`DEFAULT_RADIUS`].

/// Radius of elements without a tabulated van der Waals radius, in Å.
pub const DEFAULT_RADIUS: f32 = 2.0;

/// Colour of elements the table does not know (a pink that stands out).
pub const UNKNOWN_COLOR: [f32; 3] = [1.0, 0.08, 0.58];

/// One element (or an unknown symbol): an index into the table, or
/// [`Element::UNKNOWN`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Element(u8);

struct Info {
    symbol: &'static str,
    color: [u8; 3],
    /// Van der Waals radius in hundredths of an Å (0: untabulated).
    radius: u16,
}

const fn e(symbol: &'static str, color: u32, radius: u16) -> Info {
    Info {
        symbol,
        color: [(color >> 16) as u8, (color >> 8) as u8, color as u8],
        radius,
    }
}

#[rustfmt::skip]
const TABLE: &[Info] = &[
    e("H", 0xFFFFFF, 120), e("He", 0xD9FFFF, 140), e("Li", 0xCC80FF, 182),
    e("Be", 0xC2FF00, 0), e("B", 0xFFB5B5, 0), e("C", 0x909090, 170),
    e("N", 0x3050F8, 155), e("O", 0xFF0D0D, 152), e("F", 0x90E050, 147),
    e("Ne", 0xB3E3F5, 154), e("Na", 0xAB5CF2, 227), e("Mg", 0x8AFF00, 173),
    e("Al", 0xBFA6A6, 0), e("Si", 0xF0C8A0, 210), e("P", 0xFF8000, 180),
    e("S", 0xFFFF30, 180), e("Cl", 0x1FF01F, 175), e("Ar", 0x80D1E3, 188),
    e("K", 0x8F40D4, 275), e("Ca", 0x3DFF00, 0), e("Mn", 0x9C7AC7, 0),
    e("Fe", 0xE06633, 0), e("Co", 0xF090A0, 0), e("Ni", 0x50D050, 163),
    e("Cu", 0xC88033, 140), e("Zn", 0x7D80B0, 139), e("Ga", 0xC28F8F, 187),
    e("As", 0xBD80E3, 185), e("Se", 0xFFA100, 190), e("Br", 0xA62929, 185),
    e("Kr", 0x5CB8D1, 202), e("Pd", 0x006985, 163), e("Ag", 0xC0C0C0, 172),
    e("Cd", 0xFFD98F, 158), e("In", 0xA67573, 193), e("Sn", 0x668080, 217),
    e("Te", 0xD47A00, 206), e("I", 0x940094, 198), e("Xe", 0x429EB0, 216),
    e("Pt", 0xD0D0E0, 175), e("Au", 0xFFD123, 166), e("Hg", 0xB8B8D0, 155),
    e("Tl", 0xA6544D, 196), e("Pb", 0x575961, 202), e("U", 0x008FFF, 186),
];

/// Covalent radius of elements the table does not know, in Å.
pub const DEFAULT_COVALENT_RADIUS: f32 = 1.5;

/// Covalent radii in hundredths of an Å (Cordero et al. 2008).
#[rustfmt::skip]
const COVALENT: &[(&str, u16)] = &[
    ("H", 31), ("He", 28), ("Li", 128), ("Be", 96), ("B", 84), ("C", 76),
    ("N", 71), ("O", 66), ("F", 57), ("Ne", 58), ("Na", 166), ("Mg", 141),
    ("Al", 121), ("Si", 111), ("P", 107), ("S", 105), ("Cl", 102), ("Ar", 106),
    ("K", 203), ("Ca", 176), ("Mn", 139), ("Fe", 132), ("Co", 126), ("Ni", 124),
    ("Cu", 132), ("Zn", 122), ("Ga", 122), ("As", 119), ("Se", 120), ("Br", 120),
    ("Kr", 116), ("Pd", 139), ("Ag", 145), ("Cd", 144), ("In", 142), ("Sn", 139),
    ("Te", 138), ("I", 139), ("Xe", 140), ("Pt", 136), ("Au", 136), ("Hg", 132),
    ("Tl", 145), ("Pb", 146), ("U", 196),
];

impl Element {
    /// A symbol the table does not know.
    pub const UNKNOWN: Element = Element(u8::MAX);
    pub const HYDROGEN: Element = Element(0);
    pub const CARBON: Element = Element(5);
    pub const OXYGEN: Element = Element(7);

    /// The element with this symbol (case-insensitive, surrounding
    /// spaces ignored), if the table has it.
    pub fn from_symbol(symbol: &str) -> Option<Element> {
        let s = symbol.trim();
        TABLE
            .iter()
            .position(|i| i.symbol.eq_ignore_ascii_case(s))
            .and_then(|p| u8::try_from(p).ok())
            .map(Element)
    }

    fn info(self) -> Option<&'static Info> {
        TABLE.get(self.0 as usize)
    }

    /// The symbol ("C", "Fe"), or "?" for an unknown element.
    pub fn symbol(self) -> &'static str {
        self.info().map_or("?", |i| i.symbol)
    }

    /// CPK colour, RGB in [0, 1].
    pub fn color(self) -> [f32; 3] {
        match self.info() {
            Some(i) => i.color.map(|c| c as f32 / 255.0),
            None => UNKNOWN_COLOR,
        }
    }

    /// Covalent radius in Å (Cordero et al., Dalton Trans. 2832, 2008;
    /// sp3 carbon, low-spin metals), [`DEFAULT_COVALENT_RADIUS`] for an
    /// unknown element.
    pub fn covalent_radius(self) -> f32 {
        COVALENT
            .iter()
            .find(|(sym, _)| *sym == self.symbol())
            .map_or(DEFAULT_COVALENT_RADIUS, |(_, r)| *r as f32 / 100.0)
    }

    /// Van der Waals radius in Å.
    pub fn radius(self) -> f32 {
        match self.info() {
            Some(i) if i.radius > 0 => i.radius as f32 / 100.0,
            _ => DEFAULT_RADIUS,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbols_colors_radii() {
        let c = Element::from_symbol("C").unwrap();
        assert_eq!(c, Element::CARBON);
        assert_eq!(Element::from_symbol(" o ").unwrap(), Element::OXYGEN);
        assert_eq!(Element::from_symbol("FE").unwrap().symbol(), "Fe");
        assert_eq!(c.radius(), 1.7);
        assert_eq!(Element::OXYGEN.radius(), 1.52);
        assert_eq!(Element::from_symbol("Fe").unwrap().radius(), DEFAULT_RADIUS);
        let o = Element::OXYGEN.color();
        assert!(
            o[0] > 0.7 && o[1] < 0.3 && o[2] < 0.3,
            "oxygen is red: {o:?}"
        );
        assert_eq!(Element::from_symbol("Xx"), None);
        assert_eq!(Element::UNKNOWN.symbol(), "?");
        assert_eq!(Element::UNKNOWN.color(), UNKNOWN_COLOR);
        assert_eq!(c.covalent_radius(), 0.76);
        assert_eq!(Element::UNKNOWN.covalent_radius(), DEFAULT_COVALENT_RADIUS);
        // Every tabulated element has a covalent radius.
        for i in 0..=u8::MAX {
            let e = Element(i);
            if e.info().is_some() {
                assert!(
                    COVALENT.iter().any(|(s, _)| *s == e.symbol()),
                    "{}",
                    e.symbol()
                );
            }
        }
    }
}
