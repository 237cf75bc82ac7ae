//! A small deterministic DXF writer: the scene as DXF R2000 (AC1015, the default: current
//! AutoCAD refuses R14 and older) or R12 (AC1009), in paper millimetres at 1:1, y flipped up
//! (`dxf_y = height − y`). Same scene, same bytes: fixed decimals, no dates, handles in a
//! fixed order.
//!
//! **Why our own writer and not the `dxf` crate.** Measured with `tools/dxf_audit.py`
//! (ezdxf 1.4.5: `readfile`, then `audit()`; a fix counts as a failure) on a drawing of one
//! LINE, one CIRCLE and one TEXT written by the `dxf` crate 0.6.2:
//! - R2000: loads, 0 errors, **7 fixes**, "invalid table head handle" in VPORT, LTYPE,
//!   LAYER, STYLE, APPID, DIMSTYLE and BLOCK_RECORD: the crate writes every TABLE head
//!   without its handle (5) and owner (330). Those heads come from the crate's generated
//!   writer; its API has no way to give them one, so the fixes cannot be made through it.
//! - R12: `ezdxf.readfile` **refuses the file** (DXFTypeError: an APPID without a name; the
//!   crate writes R13 subclass markers, 100, into R12 table records); only `ezdxf.recover`
//!   reads it.
//!
//! This writer (no dependency) passes with 0 errors and 0 fixes in both versions on every
//! fixture's sheets, the worked example in three languages: 44 files (tests/dxf.rs).
//!
//! What is written:
//! - HEADER: `$ACADVER`, `$DWGCODEPAGE` ANSI_1251, extents and limits of the sheet,
//!   `$INSUNITS` 4 (mm) and `$MEASUREMENT` 1 (R2000), `$HANDSEED`; no dates.
//! - TABLES: VPORT `*Active` zoomed on the sheet; LTYPE `CONTINUOUS`, `DASHED` and `CENTER`
//!   with the GOST dashes of [`shapes::dash_array`]; a LAYER per group and line kind
//!   (`{group}-contour|vector|thin|dashed|centre|fill|text`, a colour per line kind, with
//!   a lineweight in R2000);
//!   STYLE `TMM` on DejaVuSansCondensed.ttf; the other tables R2000 requires (ezdxf's
//!   "minimal DXF content"). Handles are fixed for the structure and counted up from
//!   `FIRST_FREE` in scene order for layers and entities.
//! - ENTITIES: LINE for one segment; LWPOLYLINE (R2000) or POLYLINE/VERTEX/SEQEND (R12) for
//!   the rest, arcs as bulges and cubics flattened within 0.005 mm; ARC and CIRCLE
//!   for a path that is one arc; CIRCLE for a circle; HATCH SOLID (R2000) or SOLID
//!   triangles (R12) for a fill and a dot; TEXT for each run of a text, at the start of its
//!   baseline as [`text::set`] places it (left-aligned, so no DXF alignment), height the
//!   run's cap height, oblique 15° when sloped, width factor the stretch; every character
//!   outside printable ASCII as `\U+XXXX`, so the file is ASCII whatever the reader's code
//!   page (AutoCAD and LibreCAD decode the escapes; ezdxf's `readfile` keeps them as written
//!   and `ezdxf.decode_dxf_unicode` or `ezdxf.recover` decodes them).
//! - OBJECTS (R2000): the root dictionary, ACAD_GROUP, ACAD_LAYOUT (Model, Layout1),
//!   ACAD_MLINESTYLE, ACAD_PLOTSTYLENAME.

use super::{BackendError, shapes, text};
use crate::drawing::scene::{Item, LineType, Pen, Scene};
use crate::num::math;
use crate::num::work::{self, Step};
use kurbo::Point;
use std::collections::BTreeMap;
use std::f64::consts::{PI, TAU};
use std::fmt::Write as _;

/// The DXF version written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DxfVersion {
    /// AC1015: the oldest version current AutoCAD opens; LWPOLYLINE, HATCH, lineweights.
    #[default]
    R2000,
    /// AC1009: for old programs; POLYLINE, SOLID, no lineweights.
    R12,
}

/// How far the polyline of a cubic may stray from it, mm.
const FLATTEN_MM: f64 = 0.005;

/// Digits after the point: paper mm (1 µm), angles in degrees, bulges.
const MM: usize = 3;
const DEG: usize = 6;
const BULGE: usize = 9;

/// The oblique angle of GOST type B sloped lettering, degrees (75° to the baseline).
const OBLIQUE_DEG: f64 = 15.0;

/// The one text style.
const STYLE: &str = "TMM";
const FONT_FILE: &str = "DejaVuSansCondensed.ttf";

/// Fixed handles of the structure (hex when written).
mod h {
    pub const VPORT_TABLE: u32 = 0x1;
    pub const LTYPE_TABLE: u32 = 0x2;
    pub const LAYER_TABLE: u32 = 0x3;
    pub const STYLE_TABLE: u32 = 0x4;
    pub const VIEW_TABLE: u32 = 0x5;
    pub const UCS_TABLE: u32 = 0x6;
    pub const APPID_TABLE: u32 = 0x7;
    pub const DIMSTYLE_TABLE: u32 = 0x8;
    pub const BLOCK_RECORD_TABLE: u32 = 0x9;
    pub const VPORT_ACTIVE: u32 = 0x10;
    pub const LTYPE_BYBLOCK: u32 = 0x11;
    pub const LTYPE_BYLAYER: u32 = 0x12;
    pub const LTYPE_CONTINUOUS: u32 = 0x13;
    pub const LTYPE_DASHED: u32 = 0x14;
    pub const LTYPE_CENTER: u32 = 0x15;
    pub const LAYER_0: u32 = 0x16;
    pub const STYLE_STANDARD: u32 = 0x17;
    pub const STYLE_TMM: u32 = 0x18;
    pub const APPID_ACAD: u32 = 0x19;
    pub const DIMSTYLE_STANDARD: u32 = 0x1A;
    pub const MODEL_RECORD: u32 = 0x1B;
    pub const PAPER_RECORD: u32 = 0x1C;
    pub const MODEL_BLOCK: u32 = 0x1D;
    pub const MODEL_ENDBLK: u32 = 0x1E;
    pub const PAPER_BLOCK: u32 = 0x1F;
    pub const PAPER_ENDBLK: u32 = 0x20;
    pub const ROOT_DICT: u32 = 0x21;
    pub const GROUP_DICT: u32 = 0x22;
    pub const LAYOUT_DICT: u32 = 0x23;
    pub const MLINESTYLE_DICT: u32 = 0x24;
    pub const PLOTSTYLE_DICT: u32 = 0x25;
    pub const PLOTSTYLE_NORMAL: u32 = 0x26;
    pub const MODEL_LAYOUT: u32 = 0x27;
    pub const PAPER_LAYOUT: u32 = 0x28;
    pub const MLINESTYLE_STANDARD: u32 = 0x29;
}

/// The first handle of the layers and entities, counted up in scene order.
const FIRST_FREE: u32 = 0x30;

/// The scene as a DXF file.
pub fn write(scene: &Scene, version: DxfVersion) -> Result<Vec<u8>, BackendError> {
    work::count(Step::Dxf);
    shapes::check_finite(scene)?;
    Ok(Writer::run(scene, version).0.into_bytes())
}

/// How many entities of each kind [`write()`] emits for `scene` (the POLYLINE's VERTEX and
/// SEQEND not counted, as a reader's model space does not list them).
pub fn entity_counts(scene: &Scene, version: DxfVersion) -> BTreeMap<&'static str, usize> {
    Writer::run(scene, version).1
}

/// What a layer holds: a line kind of a group.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    Contour,
    Vector,
    Thin,
    Dashed,
    Centre,
    Fill,
    Text,
}

impl Kind {
    const ALL: [Kind; 7] =
        [Kind::Contour, Kind::Vector, Kind::Thin, Kind::Dashed, Kind::Centre, Kind::Fill, Kind::Text];

    fn name(self) -> &'static str {
        match self {
            Kind::Contour => "contour",
            Kind::Vector => "vector",
            Kind::Thin => "thin",
            Kind::Dashed => "dashed",
            Kind::Centre => "centre",
            Kind::Fill => "fill",
            Kind::Text => "text",
        }
    }

    /// The stroke kind of a pen: by line type, then by width (MAIN 0.7, VECTOR 0.45, THIN 0.25).
    fn of_pen(pen: &Pen) -> Kind {
        match pen.line {
            LineType::Dashed => Kind::Dashed,
            LineType::DashDot => Kind::Centre,
            LineType::Solid if pen.width >= 0.6 => Kind::Contour,
            LineType::Solid if pen.width > 0.3 => Kind::Vector,
            LineType::Solid => Kind::Thin,
        }
    }

    fn of_item(item: &Item) -> Kind {
        match item {
            Item::Path { pen, .. } | Item::Circle { pen, filled: false, .. } => Kind::of_pen(pen),
            Item::Circle { filled: true, .. } | Item::Fill { .. } => Kind::Fill,
            Item::Text(_) => Kind::Text,
        }
    }

    /// The layer's lineweight, 1/100 mm.
    fn lineweight(self) -> i32 {
        match self {
            Kind::Contour => 70,
            Kind::Vector => 50,
            Kind::Thin | Kind::Dashed | Kind::Centre | Kind::Fill | Kind::Text => 25,
        }
    }

    /// The layer's colour (AutoCAD's index): a line kind each, so that R12, which has no
    /// lineweights, can be plotted with a pen per colour (a plot style table mapping
    /// colour 7 to 0.7 mm, 5 to 0.5 mm and the rest to 0.25 mm prints the sheet's widths);
    /// the contour, the fills and the text in 7 (black on paper, white on a dark screen).
    fn colour(self) -> i32 {
        match self {
            Kind::Contour | Kind::Fill | Kind::Text => 7,
            Kind::Vector => 5,
            Kind::Thin => 3,
            Kind::Dashed => 6,
            Kind::Centre => 1,
        }
    }

    fn linetype(self) -> &'static str {
        match self {
            Kind::Dashed => "DASHED",
            Kind::Centre => "CENTER",
            _ => "CONTINUOUS",
        }
    }
}

/// The lineweights AutoCAD offers, 1/100 mm.
const LINEWEIGHTS: [i32; 24] =
    [0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200, 211];

/// The offered lineweight nearest a pen's width (the larger of two as near: 0.45 → 50).
fn lineweight_of(width_mm: f64) -> i32 {
    let w = width_mm * 100.0;
    LINEWEIGHTS
        .into_iter()
        .rev()
        .min_by(|a, b| (f64::from(*a) - w).abs().total_cmp(&(f64::from(*b) - w).abs()))
        .unwrap_or(25)
}

/// A layer name DXF accepts: letters, digits, `-`, `_` and `$`; anything else becomes `_`.
fn layer_name(group: &str, kind: Kind) -> String {
    let id: String =
        group.chars().map(|c| if c.is_ascii_alphanumeric() || "-_$".contains(c) { c } else { '_' }).collect();
    let id = if id.is_empty() { "group".to_string() } else { id };
    format!("{id}-{}", kind.name())
}

/// A number with at most `decimals` digits after the point, at least one, never `-0.0`.
fn num(x: f64, decimals: usize) -> String {
    let mut s = format!("{x:.decimals$}");
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.push('0');
        }
    }
    if s == "-0.0" { "0.0".into() } else { s }
}

/// An angle in degrees in [0, 360).
fn degrees(x: f64) -> f64 {
    let d = x.rem_euclid(360.0);
    // rem_euclid can round up to 360 itself; and a value written as 360 is 0.
    if d >= 360.0 - 0.5e-6 { 0.0 } else { d }
}

/// A text for a DXF TEXT: printable ASCII as it is, everything else (and `\`, and the second
/// `%` of a `%%` control code) as `\U+XXXX`; a character beyond the BMP, which the escape
/// cannot hold, as U+FFFD.
fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut prev = '\0';
    for c in s.chars() {
        let plain = (' '..='~').contains(&c) && c != '\\' && !(c == '%' && prev == '%');
        if plain {
            out.push(c);
        } else {
            let code = if (c as u32) <= 0xFFFF { c as u32 } else { 0xFFFD };
            let _ = write!(out, "\\U+{code:04X}");
        }
        prev = if plain { c } else { '\0' };
    }
    out
}
mod entities;
mod geometry;
mod sections;
#[cfg(test)]
mod tests;

use geometry::{Flip, Shape, Vertex, outline_points, triangles};

/// The file being written, its next free handle and its entity counts.
struct Writer {
    out: String,
    r2000: bool,
    next: u32,
    counts: BTreeMap<&'static str, usize>,
}

impl Writer {
    fn run(scene: &Scene, version: DxfVersion) -> (String, BTreeMap<&'static str, usize>) {
        let mut w = Writer {
            out: String::with_capacity(1 << 20),
            r2000: version == DxfVersion::R2000,
            next: FIRST_FREE,
            counts: BTreeMap::new(),
        };
        let layers = used_layers(scene);
        if w.r2000 {
            w.classes();
        }
        w.tables(&layers);
        w.blocks();
        w.entities(scene);
        if w.r2000 {
            w.objects(scene);
        }
        w.pair(0, "EOF");
        let body = std::mem::take(&mut w.out);
        w.header(scene);
        w.out.push_str(&body);
        (w.out, w.counts)
    }

    fn pair(&mut self, code: i32, value: impl std::fmt::Display) {
        let _ = write!(self.out, "{code:>3}\r\n{value}\r\n");
    }

    fn mm(&mut self, code: i32, x: f64) {
        self.pair(code, num(x, MM));
    }

    fn point(&mut self, code: i32, p: Point) {
        self.mm(code, p.x);
        self.mm(code + 10, p.y);
        self.pair(code + 20, "0.0");
    }

    fn point2(&mut self, code: i32, p: Point) {
        self.mm(code, p.x);
        self.mm(code + 10, p.y);
    }

    fn handle(&mut self) -> u32 {
        let h = self.next;
        self.next += 1;
        h
    }

    /// A handle, R2000's subclass markers and owner are written only where the version has
    /// them: handles in both (R12 with `$HANDLING` 1), the rest in R2000 alone.
    fn hnd(&mut self, code: i32, handle: u32) {
        self.pair(code, format!("{handle:X}"));
    }

    fn owner(&mut self, handle: u32) {
        if self.r2000 {
            self.hnd(330, handle);
        }
    }

    fn sub(&mut self, marker: &str) {
        if self.r2000 {
            self.pair(100, marker);
        }
    }

    fn var(&mut self, name: &str) {
        self.pair(9, name);
    }
}

/// The layers the scene's items use: by group, then by kind, each once.
fn used_layers(scene: &Scene) -> Vec<(String, Kind)> {
    let mut out: Vec<(String, Kind)> = Vec::new();
    for g in &scene.groups {
        for kind in Kind::ALL {
            if g.items.iter().any(|i| Kind::of_item(i) == kind) {
                let name = layer_name(&g.id, kind);
                if !out.iter().any(|(n, _)| *n == name) {
                    out.push((name, kind));
                }
            }
        }
    }
    out
}
