//! Text set for the backends that place glyphs themselves (PDF, PNG): a [`Text`]'s runs as
//! glyphs at positions from the embedded font's advances — the numbers `font.rs` gives the
//! layout, so an anchor lands where the layout measured it, and the PDF and the PNG put
//! every glyph at the same place. No kerning, for the same reason.
//!
//! The frame follows the SVG writer's `<text>`: `translate(at) rotate(−rotate) skewX(−15)`,
//! then the runs one after another along the baseline, the anchor applied to their whole
//! advance, the subscript smaller and lowered inside the sloped frame (so it slants with it).

use crate::drawing::scene::{Anchor, Text};
use crate::font;
use crate::num::math;
use kurbo::{Affine, Point};
use std::ops::Range;

/// GOST type B lettering slopes 75°: skewX(−15°).
const SLOPE_DEG: f64 = -15.0;

/// One glyph of a run: its id, where its pen position lies along the run (mm from the run's
/// start), its advance (mm) and the bytes of the run's text it sets.
#[derive(Debug, Clone, PartialEq)]
pub struct SetGlyph {
    pub id: u32,
    pub x: f64,
    pub advance: f64,
    pub chars: Range<usize>,
}

/// A run set in the text's frame: its text, font size (mm), the start of its baseline
/// (x along the baseline, y its drop) and its glyphs.
#[derive(Debug, Clone, PartialEq)]
pub struct SetRun<'a> {
    pub text: &'a str,
    pub size: f64,
    pub origin: Point,
    pub glyphs: Vec<SetGlyph>,
}

/// A text ready to draw: the frame's map to paper mm and the runs in that frame.
#[derive(Debug, Clone, PartialEq)]
pub struct SetText<'a> {
    pub transform: Affine,
    pub runs: Vec<SetRun<'a>>,
}

/// Sets a text's runs with the embedded font.
pub fn set(t: &Text) -> SetText<'_> {
    // The runs are set in the text's frame, which the stretch then scales: the anchor's
    // offset is the advance before it (a condensed, centred line set from half its condensed
    // advance stood off its middle by a sixth of its width in the PDF and PNG, not the SVG).
    let advance = t.advance() / t.stretch;
    let mut x = match t.anchor {
        Anchor::Start => 0.0,
        Anchor::Middle => -advance / 2.0,
        Anchor::End => -advance,
    };
    let runs = t
        .runs()
        .map(|r| {
            let run = set_run(r.text, font::size_for_cap(r.h), Point::new(x, r.drop));
            x += font::metrics().width(r.text, run.size);
            run
        })
        .collect();
    SetText { transform: frame(t), runs }
}

fn set_run(text: &str, size: f64, origin: Point) -> SetRun<'_> {
    let m = font::metrics();
    let scale = size / m.units_per_em();
    let mut units = 0.0;
    let glyphs = text
        .char_indices()
        .map(|(i, c)| {
            let g = m.glyph(c);
            let glyph = SetGlyph { id: g.id, x: units * scale, advance: g.advance * scale, chars: i..i + c.len_utf8() };
            units += g.advance;
            glyph
        })
        .collect();
    SetRun { text, size, origin, glyphs }
}

/// The text's frame in paper mm: translate(at) rotate(−rotate) scale(stretch 1) skewX(−15),
/// as the SVG writes.
fn frame(t: &Text) -> Affine {
    let mut a = Affine::translate(t.at.to_vec2());
    if t.rotate != 0.0 {
        // Paper y points down: a counter-clockwise turn on paper is a negative angle here.
        let (s, c) = math::sin_cos(-t.rotate.to_radians());
        a *= Affine::new([c, s, -s, c, 0.0, 0.0]);
    }
    if t.stretch != 1.0 {
        a *= Affine::scale_non_uniform(t.stretch, 1.0);
    }
    if t.sloped {
        a *= Affine::skew(math::tan(SLOPE_DEG.to_radians()), 0.0);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::scene::Text;
    use crate::num::math::Norm;

    fn label() -> Text {
        Text::new(Point::new(100.0, 50.0), "v", 5.0, Anchor::Middle).with_sub("BA", " = 1")
    }

    #[test]
    fn runs_follow_each_other_and_the_anchor_centres_their_whole_advance() {
        let t = label();
        let set = set(&t);
        let m = font::metrics();
        let widths: Vec<f64> = t.runs().map(|r| m.width(r.text, font::size_for_cap(r.h))).collect();
        assert_eq!(set.runs[0].origin.x, -t.advance() / 2.0);
        assert_eq!(set.runs[1].origin.x, set.runs[0].origin.x + widths[0]);
        assert_eq!(set.runs[2].origin.x, set.runs[1].origin.x + widths[1]);
        let end = set.runs[2].origin.x + widths[2];
        assert!((end - t.advance() / 2.0).abs() < 1e-12, "the last run ends at half the advance: {end}");
        assert_eq!(set.runs[1].origin.y, 5.0 * crate::drawing::scene::SUB_DROP);
        assert!(set.runs[1].size < set.runs[0].size);
    }

    #[test]
    fn glyphs_advance_by_the_widths_the_layout_measures() {
        let t = Text::new(Point::ORIGIN, "Tezliklar rejalari", 5.0, Anchor::Start);
        let run = &set(&t).runs[0];
        let last = run.glyphs.last().unwrap();
        let width = font::metrics().width(&t.text, run.size);
        assert_eq!(last.x + last.advance, width);
        assert_eq!(&run.text[last.chars.clone()], "i");
        assert!(run.glyphs.iter().all(|g| g.id != 0), "every letter has a glyph");
    }

    #[test]
    fn the_frame_is_translate_rotate_skew() {
        let mut t = label();
        t.rotate = 90.0;
        let a = set(&t).transform;
        // Sloped: a point one mm above the baseline leans right by tan 15°.
        let p = a * Point::new(0.0, -1.0);
        let q = Point::new(100.0 - 1.0, 50.0 - math::tan(15f64.to_radians()));
        assert!((p - q).norm() < 1e-12, "{p:?}");
        // Turned a quarter counter-clockwise: the baseline runs up the sheet.
        let r = a * Point::new(1.0, 0.0);
        assert!((r - Point::new(100.0, 49.0)).norm() < 1e-12, "{r:?}");
    }
}
