//! The sense of rotation of a crank or a cam, as the project file writes it (`ccw`, `cw`) and
//! as `results.json` reports it; the sign it carries is taken only where it multiplies.

use kurbo::Vec2;

/// Counter-clockwise or clockwise, seen with the x axis to the right and the y axis up.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Sense {
    /// Counter-clockwise: positive angles.
    Ccw,
    /// Clockwise.
    Cw,
}

impl Sense {
    /// The sense of an angular velocity (counter-clockwise positive); zero is counter-clockwise.
    pub fn of(omega: f64) -> Sense {
        if omega < 0.0 { Sense::Cw } else { Sense::Ccw }
    }

    /// +1 counter-clockwise, −1 clockwise: the factor of an angle or a turn in this sense.
    pub fn sign(self) -> f64 {
        match self {
            Sense::Ccw => 1.0,
            Sense::Cw => -1.0,
        }
    }

    /// The word for a message: `counter-clockwise` or `clockwise`.
    pub fn word(self) -> &'static str {
        match self {
            Sense::Ccw => "counter-clockwise",
            Sense::Cw => "clockwise",
        }
    }

    /// A point computed for a clockwise rotation, in this sense's picture: itself for `Cw`,
    /// its mirror in the y axis for `Ccw` (the cams domain computes every cam turning
    /// clockwise).
    pub fn apply(self, v: Vec2) -> Vec2 {
        match self {
            Sense::Cw => v,
            Sense::Ccw => Vec2::new(-v.x, v.y),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sign_word_and_picture() {
        assert_eq!((Sense::Ccw.sign(), Sense::Cw.sign()), (1.0, -1.0));
        assert_eq!((Sense::of(-7.33), Sense::of(7.33)), (Sense::Cw, Sense::Ccw));
        assert_eq!(Sense::Cw.word(), "clockwise");
        assert_eq!(Sense::Ccw.apply(Vec2::new(1.0, 2.0)), Vec2::new(-1.0, 2.0));
        assert_eq!(Sense::Cw.apply(Vec2::new(1.0, 2.0)), Vec2::new(1.0, 2.0));
        assert_eq!(serde_json::to_string(&[Sense::Ccw, Sense::Cw]).unwrap(), r#"["ccw","cw"]"#);
    }
}
