//! The one font of every sheet: DejaVu Sans Condensed 2.37, vendored under
//! `assets/fonts/` with its licence. It covers Uzbek Latin (ʻ U+02BB), Cyrillic and Greek.
//! Advance widths are read with `skrifa` (maintained, and already compiled in by krilla).
//!
//! **Invariant:** system fonts are never loaded, so output does not depend on the host.

use skrifa::charmap::Charmap;
use skrifa::instance::{LocationRef, Size};
use skrifa::metrics::GlyphMetrics;
use skrifa::{FontRef, MetadataProvider};

/// The family name written into SVG.
/// (The file's family is "DejaVu Sans" with a semi-condensed stretch.)
pub const FAMILY: &str = "DejaVu Sans";

/// The font's full name, for messages.
pub const NAME: &str = "DejaVu Sans Condensed";

/// The font-stretch written into SVG to select the condensed face.
pub const STRETCH: &str = "semi-condensed";

/// The font file, embedded in the binary.
pub const BYTES: &[u8] = include_bytes!("../assets/fonts/DejaVuSansCondensed.ttf");

/// Capital height as a fraction of the font size (DejaVu: 1493 / 2048 units).
pub const CAP_HEIGHT: f64 = 1493.0 / 2048.0;

/// Characters below this code point have their advances in a table (Latin, Greek,
/// Cyrillic, punctuation, sub- and superscripts, arrows, mathematical operators).
const TABLE_END: u32 = 0x2400;

/// In [`Metrics`]'s short advances: ask the full table.
const ASK_TABLE: u16 = u16::MAX;

/// One glyph of the font: its id and its advance in font units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Glyph {
    pub id: u32,
    pub advance: f64,
}

/// Advance widths of the font, for laying out and measuring text without a renderer.
pub struct Metrics {
    font: FontRef<'static>,
    /// Glyph and advance in font units of each code point below [`TABLE_END`]; `None`: no
    /// glyph.
    table: Vec<Option<Glyph>>,
    /// The same advances as whole font units in two bytes ([`ASK_TABLE`]: no glyph, or an
    /// advance that does not fit), so that measuring a text reads a table that stays in
    /// the cache; summed as `f64`, whole numbers add up exactly as `table`'s do.
    advances: Vec<u16>,
    /// The advance of `.notdef`, the missing-glyph box.
    notdef: f64,
    units_per_em: f64,
}

/// The glyph of `c` in `charmap` and its advance in `metrics`; `None` if it has no glyph.
fn lookup_in(charmap: &Charmap, metrics: &GlyphMetrics, c: char) -> Option<Glyph> {
    // Some cmap formats answer glyph 0 (.notdef) for an unmapped character.
    let glyph = charmap.map(c).filter(|g| g.to_u32() != 0)?;
    // Unscaled advances are whole font units.
    Some(Glyph { id: glyph.to_u32(), advance: f64::from(metrics.advance_width(glyph)?) })
}

impl Metrics {
    pub fn load() -> Metrics {
        let font = FontRef::new(BYTES).expect("the vendored font parses");
        let units_per_em = f64::from(font.metrics(Size::unscaled(), LocationRef::default()).units_per_em);
        let notdef = font.glyph_metrics(Size::unscaled(), LocationRef::default()).advance_width(Default::default());
        // The character map and the metrics read once for the whole table (made for each
        // character, they were 5 % of building sheet 1).
        let (charmap, metrics) = (font.charmap(), font.glyph_metrics(Size::unscaled(), LocationRef::default()));
        let table: Vec<Option<Glyph>> =
            (0..TABLE_END).map(|c| char::from_u32(c).and_then(|c| lookup_in(&charmap, &metrics, c))).collect();
        let short = |g: &Option<Glyph>| {
            let a = g.map(|g| g.advance).filter(|&a| a >= 0.0 && a < f64::from(ASK_TABLE) && a.fract() == 0.0);
            a.map_or(ASK_TABLE, |a| a as u16)
        };
        let advances = table.iter().map(short).collect();
        Metrics { font, table, advances, notdef: f64::from(notdef.unwrap_or(0.0)), units_per_em }
    }

    /// The glyph of `c` and its advance from the font's tables; `None` if it has no glyph.
    fn lookup(&self, c: char) -> Option<Glyph> {
        let metrics = self.font.glyph_metrics(Size::unscaled(), LocationRef::default());
        lookup_in(&self.font.charmap(), &metrics, c)
    }

    fn entry(&self, c: char) -> Option<Glyph> {
        match self.table.get(c as usize) {
            Some(&g) => g,
            None => self.lookup(c),
        }
    }

    fn advance(&self, c: char) -> Option<f64> {
        self.entry(c).map(|g| g.advance)
    }

    /// Width of `text` set at font size `size` (same unit as `size`); a character without
    /// a glyph counts as the font's missing-glyph box (its `.notdef` advance).
    pub fn width(&self, text: &str, size: f64) -> f64 {
        let units: f64 = text
            .chars()
            .map(|c| match self.advances.get(c as usize) {
                Some(&a) if a != ASK_TABLE => f64::from(a),
                _ => self.advance(c).unwrap_or(self.notdef),
            })
            .sum();
        units * size / self.units_per_em
    }

    /// The glyph that sets `c` and its advance in font units: the advance [`Metrics::width`]
    /// counts, so a backend placing glyphs one after another ends where the layout measured.
    /// A character without a glyph is set as `.notdef` (glyph 0).
    pub fn glyph(&self, c: char) -> Glyph {
        self.entry(c).unwrap_or(Glyph { id: 0, advance: self.notdef })
    }

    /// Font units per em: a glyph's advance in units times size / this is its advance at size.
    pub fn units_per_em(&self) -> f64 {
        self.units_per_em
    }

    /// The parsed font, for drawing glyph outlines.
    pub fn font(&self) -> &FontRef<'static> {
        &self.font
    }

    /// Whether `c` has a glyph (white space always counts as covered).
    pub fn has_glyph(&self, c: char) -> bool {
        c.is_whitespace() || self.advance(c).is_some()
    }

    /// Whether every character of `text` has a glyph.
    pub fn covers(&self, text: &str) -> bool {
        text.chars().all(|c| self.has_glyph(c))
    }
}

/// Font size for a GOST lettering height `h` (the capital height, mm).
pub fn size_for_cap(h: f64) -> f64 {
    h / CAP_HEIGHT
}

/// A shared instance.
pub fn metrics() -> &'static Metrics {
    static M: std::sync::OnceLock<Metrics> = std::sync::OnceLock::new();
    M.get_or_init(Metrics::load)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cap height used for GOST lettering sizes is the height of the glyph 'H'.
    #[test]
    fn cap_height_is_that_of_h() {
        let font = FontRef::new(BYTES).unwrap();
        let h = font.charmap().map('H').unwrap();
        let bb = font.glyph_metrics(Size::unscaled(), LocationRef::default()).bounds(h).unwrap();
        assert_eq!(f64::from(bb.y_max) / metrics().units_per_em, CAP_HEIGHT);
        assert!((size_for_cap(5.0) - 6.86).abs() < 0.01, "STACK.md: 5 mm lettering is 6.86 mm font-size");
    }

    /// The short advances measure every character of the table as the table does.
    #[test]
    fn short_advances_measure_as_the_table_does() {
        let m = metrics();
        for c in (0..TABLE_END).filter_map(char::from_u32) {
            assert_eq!(m.width(&c.to_string(), 1.0), m.advance(c).unwrap_or(m.notdef) / m.units_per_em, "{c:?}");
        }
    }

    /// The embedded bytes are the vendored font whose SHA-256 is recorded beside it.
    #[test]
    fn the_font_is_the_vendored_one() {
        use sha2::{Digest, Sha256};
        let recorded = include_str!("../assets/fonts/DejaVuSansCondensed.ttf.sha256");
        let hash: String = Sha256::digest(BYTES).iter().map(|b| format!("{b:02x}")).collect();
        assert_eq!(recorded.split_whitespace().next(), Some(hash.as_str()));
    }

    /// Widths against the font's own numbers (DejaVu Sans Condensed, 2048 units per em):
    /// 'H' advances 1352 units, 'i' 512, 'ʻ' (U+02BB) 413.
    #[test]
    fn widths_are_the_fonts_advances() {
        let m = metrics();
        assert_eq!(m.units_per_em, 2048.0);
        assert_eq!(m.width("H", 2048.0), m.advance('H').unwrap());
        assert_eq!(m.width("Hi", 2048.0), m.advance('H').unwrap() + m.advance('i').unwrap());
        assert!(m.covers("oʻgʻ Ўў Ҳҳ μ ω ε φ π √ − ² ⁿ ᵗ ᵏ ʳ ′ ⌀"));
        assert!(!m.has_glyph('中') && !m.has_glyph('あ'));
    }
}
