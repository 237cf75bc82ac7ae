//! A line of text as runs: its symbol, its subscripts and its tails, each measured with the
//! embedded font.

use super::Anchor;
use kurbo::Point;

/// Subscript height relative to its symbol (GOST 2.304: indices one size smaller; 2.5 mm
/// lettering takes 1.8 mm indices, the smallest size, not 1.75).
pub const SUB: f64 = 0.72;
/// How far a subscript's baseline lies below its symbol's, in the symbol's heights.
pub const SUB_DROP: f64 = 0.3;

/// A line of text: a symbol or words, an optional subscript and an optional tail after it at
/// the symbol's height (v_BA, "μ_l = 0,005 m/mm"). One item, so that every backend sets the
/// subscript after the main text with its own font. `h` is the GOST lettering height
/// (capital height, mm); `at` is the anchor point on the main text's baseline.
#[derive(Debug, Clone, PartialEq)]
pub struct Text {
    pub at: Point,
    pub text: String,
    /// Set at [`SUB`] of `h`, its baseline [`SUB_DROP`]·h lower.
    pub sub: String,
    /// Set after the subscript at `h`, on the main baseline.
    pub tail: String,
    /// Further subscripts, each with the text after it, after the tail: "d=s₄=s₅" is "d=s",
    /// "4", "=s", then ("5", ""). Empty on nearly every text.
    pub then: Vec<(String, String)>,
    pub h: f64,
    pub anchor: Anchor,
    /// Rotation in degrees, counter-clockwise on paper.
    pub rotate: f64,
    /// GOST type B sloped lettering (75°).
    pub sloped: bool,
    /// Width factor of the letters (1: the font's own; below 1 condensed, as GOST 2.304's
    /// narrow type A, to fit a long name into its title-block cell).
    pub stretch: f64,
}

/// One run of a [`Text`]: its text, its lettering height and its baseline's drop below the
/// main baseline, mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run<'a> {
    pub text: &'a str,
    pub h: f64,
    pub drop: f64,
}

impl<'a> Run<'a> {
    /// A run at the text's lettering height `h`, on its baseline.
    fn main(text: &'a str, h: f64) -> Run<'a> {
        Run { text, h, drop: 0.0 }
    }

    /// A subscript of a text at lettering height `h`.
    fn sub(text: &'a str, h: f64) -> Run<'a> {
        Run { text, h: h * SUB, drop: h * SUB_DROP }
    }
}

impl Text {
    pub fn new(at: Point, text: impl Into<String>, h: f64, anchor: Anchor) -> Text {
        Text {
            at,
            text: text.into(),
            sub: String::new(),
            tail: String::new(),
            then: Vec::new(),
            h,
            anchor,
            rotate: 0.0,
            sloped: true,
            stretch: 1.0,
        }
    }

    /// The same text condensed (or widened) by `stretch`.
    pub fn with_stretch(mut self, stretch: f64) -> Text {
        self.stretch = stretch;
        self
    }

    /// A run's advance width as set, mm (its stretch applied).
    fn width_of(&self, r: Run) -> f64 {
        run_width(r) * self.stretch
    }

    /// The same text with a subscript and a tail.
    pub fn with_sub(mut self, sub: impl Into<String>, tail: impl Into<String>) -> Text {
        self.sub = sub.into();
        self.tail = tail.into();
        self
    }

    /// The same text with further subscripts and their tails (see [`Text::then`]).
    pub fn with_then(mut self, then: Vec<(String, String)>) -> Text {
        self.then = then;
        self
    }

    /// The runs in order: the main text, the subscript, the tail, then each further
    /// subscript and its tail (the empty ones left out).
    pub fn runs(&self) -> impl Iterator<Item = Run<'_>> {
        let h = self.h;
        [Run::main(&self.text, h), Run::sub(&self.sub, h), Run::main(&self.tail, h)]
            .into_iter()
            .chain(self.then.iter().flat_map(move |(s, t)| [Run::sub(s, h), Run::main(t, h)]))
            .filter(|r| !r.text.is_empty())
    }

    /// The text as one string for messages: "v_BA = 1", "d=s_4=s_5".
    pub fn plain(&self) -> String {
        let mut out = self.text.clone();
        for (sub, tail) in std::iter::once((&self.sub, &self.tail)).chain(self.then.iter().map(|(s, t)| (s, t))) {
            if !sub.is_empty() {
                out.push('_');
                out.push_str(sub);
            }
            out.push_str(tail);
        }
        out
    }

    /// Advance width of every run together, mm.
    pub fn advance(&self) -> f64 {
        self.runs().map(|r| self.width_of(r)).sum()
    }

    /// Left edge of a box of width `w` placed by the anchor.
    fn left(&self, w: f64) -> f64 {
        match self.anchor {
            Anchor::Start => self.at.x,
            Anchor::Middle => self.at.x - w / 2.0,
            Anchor::End => self.at.x - w,
        }
    }

    /// A run's letters (without its leading spaces), its advance and its letters' width.
    fn measure<'a>(&self, r: Run<'a>) -> (Run<'a>, f64, f64) {
        let letters = Run { text: r.text.trim_start(), ..r };
        let w = self.width_of(r);
        // Without leading spaces the letters are the run: its width.
        let lw = if letters.text.len() == r.text.len() { w } else { self.width_of(letters) };
        (letters, w, lw)
    }

    /// Each run without its leading spaces, with the left end of its baseline, unrotated
    /// (the spaces before a tail are room, not letters), and the width of its letters.
    /// Each run is measured once (a text's boxes are asked for thousands of times while a
    /// sheet is composed, and measuring was 6 % of building sheet 1); the sums and
    /// differences are those of measuring it anew each time, so every box is the same.
    pub(super) fn placed_runs(&self) -> impl Iterator<Item = (Run<'_>, Point, f64)> {
        let measure = |r| self.measure(r);
        let mut measured = [(Run { text: "", h: 0.0, drop: 0.0 }, 0.0, 0.0); MEASURED_RUNS];
        let mut total = 0.0;
        for (k, r) in self.runs().enumerate() {
            let m = measure(r);
            total += m.1;
            if k < MEASURED_RUNS {
                measured[k] = m;
            }
        }
        let mut x = self.left(total);
        self.runs().enumerate().map(move |(k, r)| {
            let (letters, w, lw) = if k < MEASURED_RUNS { measured[k] } else { measure(r) };
            let at = Point::new(x + w - lw, self.at.y + letters.drop);
            x += w;
            (letters, at, lw)
        })
    }
}

/// The runs [`Text::placed_runs`] measures once (a plan's label line of three subscripted
/// names has seven); any further run is measured twice.
const MEASURED_RUNS: usize = 7;

/// A run's advance width, mm.
fn run_width(r: Run) -> f64 {
    crate::font::metrics().width(r.text, crate::font::size_for_cap(r.h))
}
