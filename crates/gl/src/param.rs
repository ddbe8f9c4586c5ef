//! A state parameter as the forms of one GL call family pass it
//! (glFog{f,i,fv,iv}, glLight*, glMaterial*, glLightModel*, glTexEnv*,
//! glTexGen*, glTexParameter*, glPointParameter*), and GL's rules for
//! reading it.
//!
//! Contract: each family is one [`crate::Context`] method taking a
//! [`Param`]; the method reads the values as floats with
//! [`Param::floats`] and an enum-valued parameter with [`Param::as_enum`],
//! so the float and integer forms of a call cannot disagree. Integer color
//! components map linearly to [-1, 1] (GL 2.1 §2.14.2, Table 2.9), every
//! other integer converts to the nearest float (§2.3.1).

use crate::enums::*;

/// The values of one parameter call: `F`/`I` from the scalar forms
/// (glFogf, glFogi), `Fv`/`Iv` from the vector forms (glFogfv, glFogiv).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Param<'a> {
    F(f32),
    I(i32),
    Fv(&'a [f32]),
    Iv(&'a [i32]),
}

impl Param<'_> {
    /// True for the scalar forms, which cannot set a parameter of several
    /// values.
    pub fn is_scalar(self) -> bool {
        matches!(self, Param::F(_) | Param::I(_))
    }

    /// The values as floats. Integers of a color parameter (`pname` one of
    /// [`is_color`]) map by [`int_to_unit`]; other integers convert
    /// directly.
    pub fn floats(self, pname: u32) -> Vec<f32> {
        let int = |x: i32| {
            if is_color(pname) {
                int_to_unit(x)
            } else {
                x as f32
            }
        };
        match self {
            Param::F(x) => vec![x],
            Param::I(x) => vec![int(x)],
            Param::Fv(v) => v.to_vec(),
            Param::Iv(v) => v.iter().map(|&x| int(x)).collect(),
        }
    }

    /// The first value read as an enum (0 when there is none): a float
    /// truncates toward zero, saturating; an integer keeps its bits, so a
    /// negative one is no enum.
    pub fn as_enum(self) -> u32 {
        match self {
            Param::F(x) | Param::Fv(&[x, ..]) => x as u32,
            Param::I(x) | Param::Iv(&[x, ..]) => x as u32,
            Param::Fv(_) | Param::Iv(_) => 0,
        }
    }
}

/// The parameters whose values are colors. No call family takes another
/// family's color name as a valid parameter, so one list serves them all.
pub fn is_color(pname: u32) -> bool {
    matches!(
        pname,
        GL_AMBIENT
            | GL_DIFFUSE
            | GL_SPECULAR
            | GL_EMISSION
            | GL_AMBIENT_AND_DIFFUSE
            | GL_LIGHT_MODEL_AMBIENT
            | GL_FOG_COLOR
            | GL_TEXTURE_ENV_COLOR
            | GL_TEXTURE_BORDER_COLOR
    )
}

/// c = (2x + 1) / (2^32 - 1) (GL 2.1 Table 2.9).
pub fn int_to_unit(x: i32) -> f32 {
    ((2.0 * x as f64 + 1.0) / 4294967295.0) as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_colors_are_normalized_and_the_rest_convert() {
        assert_eq!(Param::Iv(&[i32::MAX, 0]).floats(GL_FOG_COLOR)[0], 1.0);
        assert_eq!(Param::Iv(&[i32::MIN]).floats(GL_DIFFUSE), vec![-1.0]);
        assert_eq!(Param::Iv(&[3, -2]).floats(GL_FOG_START), vec![3.0, -2.0]);
        assert_eq!(Param::I(7).floats(GL_FOG_END), vec![7.0]);
        assert_eq!(Param::Fv(&[0.5; 4]).floats(GL_FOG_COLOR), vec![0.5; 4]);
    }

    #[test]
    fn enums_from_every_form() {
        assert_eq!(Param::F(GL_EXP as f32).as_enum(), GL_EXP);
        assert_eq!(Param::I(GL_EXP as i32).as_enum(), GL_EXP);
        assert_eq!(Param::Fv(&[GL_LINEAR as f32, 9.0]).as_enum(), GL_LINEAR);
        assert_eq!(Param::Iv(&[-1]).as_enum(), u32::MAX);
        assert_eq!(Param::Fv(&[-1.0]).as_enum(), 0);
        assert_eq!(Param::Iv(&[]).as_enum(), 0);
    }
}
