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
