//! The one font of every sheet: DejaVu Sans Condensed 2.37, vendored under
//! `assets/fonts/` with its licence. It covers Uzbek Latin (ʻ U+02BB), Cyrillic and Greek.
//!
//! **Invariant:** system fonts are never loaded, so output does not depend on the host.

/// The family name written into SVG.
/// (The file's family is "DejaVu Sans" with a semi-condensed stretch.)
pub const FAMILY: &str = "DejaVu Sans";

/// The font-stretch written into SVG to select the condensed face.
pub const STRETCH: &str = "semi-condensed";

/// The font file, embedded in the binary.
pub const BYTES: &[u8] = include_bytes!("../assets/fonts/DejaVuSansCondensed.ttf");

/// Capital height as a fraction of the font size (DejaVu: 1493 / 2048 units).
pub const CAP_HEIGHT: f64 = 1493.0 / 2048.0;

/// Advance widths of the font, for laying out and measuring text without a renderer.
pub struct Metrics {
    face: ttf_parser::Face<'static>,
}

impl Metrics {
    pub fn load() -> Metrics {
        let face = ttf_parser::Face::parse(BYTES, 0).expect("the vendored font parses");
        Metrics { face }
    }

    /// Width of `text` set at font size `size` (same unit as `size`).
    pub fn width(&self, text: &str, size: f64) -> f64 {
        let upm = f64::from(self.face.units_per_em());
        let units: f64 = text
            .chars()
            .map(|c| {
                let g = self.face.glyph_index(c).unwrap_or(ttf_parser::GlyphId(0));
                f64::from(self.face.glyph_hor_advance(g).unwrap_or(0))
            })
            .sum();
        units * size / upm
    }

    /// Whether every character of `text` has a glyph.
    pub fn covers(&self, text: &str) -> bool {
        text.chars().all(|c| c.is_whitespace() || self.face.glyph_index(c).is_some())
    }
}

/// Font size for a GOST lettering height `h` (the capital height, mm).
pub fn size_for_cap(h: f64) -> f64 {
    h / CAP_HEIGHT
}

/// A shared instance; parsing the face is cheap but not free.
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
        let face = ttf_parser::Face::parse(BYTES, 0).unwrap();
        let h = face.glyph_index('H').unwrap();
        let bb = face.glyph_bounding_box(h).unwrap();
        assert_eq!(f64::from(bb.y_max) / f64::from(face.units_per_em()), CAP_HEIGHT);
        assert!((size_for_cap(5.0) - 6.86).abs() < 0.01, "STACK.md: 5 mm lettering is 6.86 mm font-size");
    }

    #[test]
    fn the_font_is_the_vendored_one() {
        let recorded = include_str!("../assets/fonts/DejaVuSansCondensed.ttf.sha256");
        assert!(recorded.starts_with("2d8aa290adcf1ebcbb35f63e57cf32941b012eaab4b65096b904112cf3bac972"));
        assert_eq!(BYTES.len(), 682_828);
        assert!(metrics().covers("oʻgʻ Ўў Ҳҳ μ ω ε φ π √ − ² ⁿ ᵗ ᵏ ʳ ′"));
    }
}
