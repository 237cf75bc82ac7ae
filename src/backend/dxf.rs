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
//!   (`{group}-contour|vector|thin|dashed|centre|fill|text`, with a lineweight in R2000);
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
use crate::drawing::path::{Path, Seg};
use crate::drawing::scene::{Item, LineType, Pen, Scene, Text};
use crate::num::math;
use kurbo::{Arc, BezPath, PathEl, Point};
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

/// A vertex of a polyline: its point (DXF coordinates) and the bulge of the segment from
/// it to the next (tan of a quarter of the arc's counter-clockwise sweep; 0 straight).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Vertex {
    p: Point,
    bulge: f64,
}

/// A path as the DXF entity it becomes.
#[derive(Debug, Clone, PartialEq)]
enum Shape {
    Line(Point, Point),
    /// Centre, radius, start and end angles (degrees, counter-clockwise from start to end).
    Arc(Point, f64, f64, f64),
    Circle(Point, f64),
    Poly(Vec<Vertex>, bool),
}

/// The writer's geometry: paper mm to DXF coordinates.
struct Flip {
    height: f64,
}

impl Flip {
    fn p(&self, p: Point) -> Point {
        Point::new(p.x, self.height - p.y)
    }

    /// An arc's DXF form: a paper angle θ is −θ in DXF (y flipped), and a paper sweep s
    /// (clockwise on the sheet when positive) runs counter-clockwise from −(θ+s) to −θ.
    fn arc(&self, a: &Arc) -> (Point, f64, f64, f64) {
        let (s0, s1) = (a.start_angle, a.start_angle + a.sweep_angle);
        let (lo, hi) = if s0 <= s1 { (s0, s1) } else { (s1, s0) };
        (self.p(a.center), a.radii.x, degrees(-hi.to_degrees()), degrees(-lo.to_degrees()))
    }

    /// What a path becomes: a LINE, an ARC or CIRCLE, or a polyline.
    fn shape(&self, path: &Path) -> Option<Shape> {
        if path.segs.is_empty() {
            return None;
        }
        if !path.closed && path.segs.len() == 1 {
            match &path.segs[0] {
                Seg::Line(q) => return Some(Shape::Line(self.p(path.start), self.p(*q))),
                Seg::Arc(a) if a.radii.x > 0.0 && a.sweep_angle.abs() >= TAU - 1e-9 => {
                    return Some(Shape::Circle(self.p(a.center), a.radii.x));
                }
                Seg::Arc(a) if a.radii.x > 0.0 && a.sweep_angle != 0.0 => {
                    let (c, r, start, end) = self.arc(a);
                    return Some(Shape::Arc(c, r, start, end));
                }
                _ => {}
            }
        }
        let v = self.vertices(path);
        (v.len() >= 2).then_some(Shape::Poly(v, path.closed))
    }

    /// A path's polyline vertices: lines as they are, arcs as bulges (pieces of at most half
    /// a turn), cubics flattened within [`FLATTEN_MM`]. A closed path's last vertex, back at
    /// its first, is left out (the closing segment takes its place).
    fn vertices(&self, path: &Path) -> Vec<Vertex> {
        let mut v = vec![Vertex { p: self.p(path.start), bulge: 0.0 }];
        let mut cur = path.start;
        let to = |v: &mut Vec<Vertex>, q: Point, bulge: f64| {
            if let Some(last) = v.last_mut() {
                last.bulge = bulge;
            }
            v.push(Vertex { p: self.p(q), bulge: 0.0 });
        };
        for s in &path.segs {
            match s {
                Seg::Line(q) => {
                    to(&mut v, *q, 0.0);
                    cur = *q;
                }
                Seg::Cubic(p1, p2, p3) => {
                    let mut b = BezPath::new();
                    b.move_to(cur);
                    b.curve_to(*p1, *p2, *p3);
                    let mut pts = Vec::new();
                    kurbo::flatten(b, FLATTEN_MM, |el| {
                        if let PathEl::LineTo(q) = el {
                            pts.push(q);
                        }
                    });
                    for q in pts {
                        to(&mut v, q, 0.0);
                    }
                    cur = *p3;
                }
                Seg::Arc(a) => {
                    let r = a.radii.x;
                    let start = a.center + math::from_angle(a.start_angle) * r;
                    if (start - cur).hypot2() > 1e-12 {
                        to(&mut v, start, 0.0);
                    }
                    let n = (a.sweep_angle.abs() / PI).ceil().max(1.0) as usize;
                    let step = a.sweep_angle / n as f64;
                    // A positive paper sweep turns clockwise on the sheet: a negative bulge.
                    let bulge = -math::tan(step / 4.0);
                    for i in 1..=n {
                        let q = a.center + math::from_angle(a.start_angle + step * i as f64) * r;
                        to(&mut v, q, bulge);
                    }
                    cur = a.center + math::from_angle(a.start_angle + a.sweep_angle) * r;
                }
            }
        }
        if path.closed && v.len() > 2 && (v[v.len() - 1].p - v[0].p).hypot2() < 1e-12 {
            v.pop();
        }
        v
    }
}

/// A closed outline flattened to points (DXF coordinates), for the triangles of R12.
fn outline_points(b: &BezPath, flip: &Flip) -> Vec<Point> {
    let mut pts: Vec<Point> = Vec::new();
    kurbo::flatten(b.iter(), FLATTEN_MM, |el| match el {
        PathEl::MoveTo(p) | PathEl::LineTo(p) => {
            let q = flip.p(p);
            if pts.last().is_none_or(|l| (*l - q).hypot2() > 1e-12) {
                pts.push(q);
            }
        }
        _ => {}
    });
    while pts.len() > 1 && (pts[pts.len() - 1] - pts[0]).hypot2() < 1e-12 {
        pts.pop();
    }
    pts
}

/// A simple polygon as triangles by ear clipping (a convex one as a fan from its first
/// corner); an outline of fewer than three points gives none.
fn triangles(pts: &[Point]) -> Vec<[Point; 3]> {
    let area2: f64 = (0..pts.len()).map(|i| pts[i].to_vec2().cross(pts[(i + 1) % pts.len()].to_vec2())).sum();
    let ccw = area2 >= 0.0;
    let mut idx: Vec<usize> = (0..pts.len()).collect();
    let mut out = Vec::new();
    let turn = |a: Point, b: Point, c: Point| {
        let t = (b - a).cross(c - b);
        if ccw { t } else { -t }
    };
    let inside =
        |p: Point, a: Point, b: Point, c: Point| turn(a, b, p) > 0.0 && turn(b, c, p) > 0.0 && turn(c, a, p) > 0.0;
    while idx.len() >= 3 {
        let n = idx.len();
        let ear = (0..n).find(|&i| {
            let (a, b, c) = (pts[idx[(i + n - 1) % n]], pts[idx[i]], pts[idx[(i + 1) % n]]);
            turn(a, b, c) > 0.0 && idx.iter().all(|&j| [a, b, c].contains(&pts[j]) || !inside(pts[j], a, b, c))
        });
        // A degenerate remainder (collinear points): clip the first corner all the same.
        let i = ear.unwrap_or(1 % n);
        let (a, b, c) = (pts[idx[(i + n - 1) % n]], pts[idx[i]], pts[idx[(i + 1) % n]]);
        if turn(a, b, c).abs() > 1e-12 {
            out.push([a, b, c]);
        }
        idx.remove(i);
    }
    out
}

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

    fn header(&mut self, scene: &Scene) {
        let size = Point::new(scene.width, scene.height);
        self.pair(0, "SECTION");
        self.pair(2, "HEADER");
        self.var("$ACADVER");
        self.pair(1, if self.r2000 { "AC1015" } else { "AC1009" });
        if self.r2000 {
            self.var("$ACADMAINTVER");
            self.pair(70, 6);
        }
        self.var("$DWGCODEPAGE");
        self.pair(3, "ANSI_1251");
        self.var("$INSBASE");
        self.point(10, Point::ORIGIN);
        self.var("$EXTMIN");
        self.point(10, Point::ORIGIN);
        self.var("$EXTMAX");
        self.point(10, size);
        self.var("$LIMMIN");
        self.point2(10, Point::ORIGIN);
        self.var("$LIMMAX");
        self.point2(10, size);
        self.var("$LTSCALE");
        self.pair(40, "1.0");
        self.var("$TEXTSTYLE");
        self.pair(7, STYLE);
        self.var("$CLAYER");
        self.pair(8, "0");
        self.var("$CELTYPE");
        self.pair(6, if self.r2000 { "ByLayer" } else { "BYLAYER" });
        self.var("$LUNITS");
        self.pair(70, 2);
        self.var("$LUPREC");
        self.pair(70, 3);
        self.var("$PLINEGEN");
        self.pair(70, 1);
        if self.r2000 {
            self.var("$CELWEIGHT");
            self.pair(370, -1);
            self.var("$LWDISPLAY");
            self.pair(290, 1);
            self.var("$INSUNITS");
            self.pair(70, 4);
            self.var("$MEASUREMENT");
            self.pair(70, 1);
            self.var("$PSLTSCALE");
            self.pair(70, 1);
            self.var("$DIMSTYLE");
            self.pair(2, "Standard");
            self.var("$CMLSTYLE");
            self.pair(2, "Standard");
        } else {
            self.var("$HANDLING");
            self.pair(70, 1);
        }
        let seed = self.next;
        self.var("$HANDSEED");
        self.hnd(5, seed);
        self.pair(0, "ENDSEC");
    }

    fn classes(&mut self) {
        self.pair(0, "SECTION");
        self.pair(2, "CLASSES");
        for (name, cpp) in [
            ("ACDBDICTIONARYWDFLT", "AcDbDictionaryWithDefault"),
            ("ACDBPLACEHOLDER", "AcDbPlaceHolder"),
            ("LAYOUT", "AcDbLayout"),
        ] {
            self.pair(0, "CLASS");
            self.pair(1, name);
            self.pair(2, cpp);
            self.pair(3, "ObjectDBX Classes");
            self.pair(90, 0);
            self.pair(280, 0);
            self.pair(281, 0);
        }
        self.pair(0, "ENDSEC");
    }

    fn table(&mut self, name: &str, handle: u32, count: usize, body: impl FnOnce(&mut Writer)) {
        self.pair(0, "TABLE");
        self.pair(2, name);
        self.hnd(5, handle);
        self.owner(0);
        self.sub("AcDbSymbolTable");
        self.pair(70, count);
        if name == "DIMSTYLE" {
            self.sub("AcDbDimStyleTable");
        }
        body(self);
        self.pair(0, "ENDTAB");
    }

    /// A table record's head: type, handle, owner, markers, name, flags.
    fn record(&mut self, kind: &str, handle: u32, table: u32, marker: &str, name: &str) {
        self.pair(0, kind);
        self.hnd(if kind == "DIMSTYLE" { 105 } else { 5 }, handle);
        self.owner(table);
        self.sub("AcDbSymbolTableRecord");
        self.sub(marker);
        self.pair(2, name);
        self.pair(70, 0);
    }

    fn tables(&mut self, layers: &[(String, Kind)]) {
        let r2000 = self.r2000;
        self.pair(0, "SECTION");
        self.pair(2, "TABLES");
        self.table("VPORT", h::VPORT_TABLE, 1, |w| w.vport());
        let linetypes = if r2000 { 5 } else { 3 };
        self.table("LTYPE", h::LTYPE_TABLE, linetypes, |w| {
            if r2000 {
                w.linetype(h::LTYPE_BYBLOCK, "ByBlock", "", &[]);
                w.linetype(h::LTYPE_BYLAYER, "ByLayer", "", &[]);
            }
            w.linetype(h::LTYPE_CONTINUOUS, "CONTINUOUS", "Solid line", &[]);
            let dashed = shapes::dash_array(LineType::Dashed).unwrap_or(&[]);
            w.linetype(h::LTYPE_DASHED, "DASHED", "GOST 2.303 dashed __ __ __", dashed);
            let centre = shapes::dash_array(LineType::DashDot).unwrap_or(&[]);
            w.linetype(h::LTYPE_CENTER, "CENTER", "GOST 2.303 dash-dot ____ . ____ .", centre);
        });
        self.table("LAYER", h::LAYER_TABLE, layers.len() + 1, |w| {
            w.layer(h::LAYER_0, "0", Kind::Thin);
            for (name, kind) in layers {
                let handle = w.handle();
                w.layer(handle, name, *kind);
            }
        });
        self.table("STYLE", h::STYLE_TABLE, 2, |w| {
            w.style(h::STYLE_STANDARD, "Standard", "txt");
            w.style(h::STYLE_TMM, STYLE, FONT_FILE);
        });
        self.table("VIEW", h::VIEW_TABLE, 0, |_| {});
        self.table("UCS", h::UCS_TABLE, 0, |_| {});
        self.table("APPID", h::APPID_TABLE, 1, |w| {
            w.record("APPID", h::APPID_ACAD, h::APPID_TABLE, "AcDbRegAppTableRecord", "ACAD");
        });
        self.table("DIMSTYLE", h::DIMSTYLE_TABLE, 1, |w| {
            w.record("DIMSTYLE", h::DIMSTYLE_STANDARD, h::DIMSTYLE_TABLE, "AcDbDimStyleTableRecord", "Standard");
            for (code, value) in [(40, "1.0"), (41, "2.5"), (42, "0.625"), (43, "3.75"), (44, "1.25"), (140, "2.5")] {
                w.pair(code, value);
            }
        });
        if r2000 {
            self.table("BLOCK_RECORD", h::BLOCK_RECORD_TABLE, 2, |w| {
                let t = h::BLOCK_RECORD_TABLE;
                w.record("BLOCK_RECORD", h::MODEL_RECORD, t, "AcDbBlockTableRecord", "*Model_Space");
                w.hnd(340, h::MODEL_LAYOUT);
                w.record("BLOCK_RECORD", h::PAPER_RECORD, t, "AcDbBlockTableRecord", "*Paper_Space");
                w.hnd(340, h::PAPER_LAYOUT);
            });
        }
        self.pair(0, "ENDSEC");
    }

    /// The active viewport, its view on the whole sheet.
    fn vport(&mut self) {
        self.record("VPORT", h::VPORT_ACTIVE, h::VPORT_TABLE, "AcDbViewportTableRecord", "*Active");
        self.point2(10, Point::ORIGIN);
        self.point2(11, Point::new(1.0, 1.0));
        self.point2(12, Point::new(420.5, 297.0));
        self.point2(13, Point::ORIGIN);
        self.point2(14, Point::new(10.0, 10.0));
        self.point2(15, Point::new(10.0, 10.0));
        // The view direction: straight down the z axis.
        self.point2(16, Point::ORIGIN);
        self.pair(36, "1.0");
        self.point(17, Point::ORIGIN);
        self.mm(40, 620.0);
        self.mm(41, 1.42);
        self.mm(42, 50.0);
        for code in [43, 44, 50, 51] {
            self.pair(code, "0.0");
        }
        for (code, value) in [(71, 0), (72, 1000), (73, 1), (74, 3), (75, 0), (76, 0), (77, 0), (78, 0)] {
            self.pair(code, value);
        }
    }

    /// A linetype of dashes (positive) and gaps (`pattern` alternates them, mm).
    fn linetype(&mut self, handle: u32, name: &str, description: &str, pattern: &[f64]) {
        self.record("LTYPE", handle, h::LTYPE_TABLE, "AcDbLinetypeTableRecord", name);
        self.pair(3, description);
        self.pair(72, 65);
        self.pair(73, pattern.len());
        self.mm(40, pattern.iter().sum());
        for (i, &x) in pattern.iter().enumerate() {
            self.mm(49, if i % 2 == 0 { x } else { -x });
            if self.r2000 {
                self.pair(74, 0);
            }
        }
    }

    fn layer(&mut self, handle: u32, name: &str, kind: Kind) {
        self.record("LAYER", handle, h::LAYER_TABLE, "AcDbLayerTableRecord", name);
        self.pair(62, 7);
        self.pair(6, kind.linetype());
        if self.r2000 {
            self.pair(370, kind.lineweight());
            self.hnd(390, h::PLOTSTYLE_NORMAL);
        }
    }

    fn style(&mut self, handle: u32, name: &str, font: &str) {
        self.record("STYLE", handle, h::STYLE_TABLE, "AcDbTextStyleTableRecord", name);
        for (code, value) in [(40, "0.0"), (41, "1.0"), (50, "0.0")] {
            self.pair(code, value);
        }
        self.pair(71, 0);
        self.pair(42, "2.5");
        self.pair(3, font);
        self.pair(4, "");
    }

    fn blocks(&mut self) {
        self.pair(0, "SECTION");
        self.pair(2, "BLOCKS");
        let spaces = if self.r2000 {
            [
                ("*Model_Space", h::MODEL_RECORD, h::MODEL_BLOCK, h::MODEL_ENDBLK),
                ("*Paper_Space", h::PAPER_RECORD, h::PAPER_BLOCK, h::PAPER_ENDBLK),
            ]
        } else {
            [("$MODEL_SPACE", 0, h::MODEL_BLOCK, h::MODEL_ENDBLK), ("$PAPER_SPACE", 0, h::PAPER_BLOCK, h::PAPER_ENDBLK)]
        };
        for (name, record, begin, end) in spaces {
            self.pair(0, "BLOCK");
            self.hnd(5, begin);
            self.owner(record);
            self.sub("AcDbEntity");
            self.pair(8, "0");
            self.sub("AcDbBlockBegin");
            self.pair(2, name);
            self.pair(70, 0);
            self.point(10, Point::ORIGIN);
            self.pair(3, name);
            self.pair(1, "");
            self.pair(0, "ENDBLK");
            self.hnd(5, end);
            self.owner(record);
            self.sub("AcDbEntity");
            self.pair(8, "0");
            self.sub("AcDbBlockEnd");
        }
        self.pair(0, "ENDSEC");
    }

    /// An entity's head: type, handle, owner (the model space), layer, and in R2000 its
    /// lineweight when the pen's differs from its layer's.
    fn entity(&mut self, kind: &'static str, layer: &str, lineweight: Option<i32>, marker: &str) {
        *self.counts.entry(kind).or_default() += 1;
        self.vertex_head(kind, layer);
        if let Some(lw) = lineweight.filter(|_| self.r2000) {
            self.pair(370, lw);
        }
        self.sub(marker);
    }

    /// The head of an entity or of a VERTEX and SEQEND (not counted).
    fn vertex_head(&mut self, kind: &str, layer: &str) {
        self.pair(0, kind);
        let handle = self.handle();
        self.hnd(5, handle);
        self.owner(h::MODEL_RECORD);
        self.sub("AcDbEntity");
        self.pair(8, layer);
    }

    fn entities(&mut self, scene: &Scene) {
        let flip = Flip { height: scene.height };
        self.pair(0, "SECTION");
        self.pair(2, "ENTITIES");
        for g in &scene.groups {
            for item in &g.items {
                let kind = Kind::of_item(item);
                let layer = layer_name(&g.id, kind);
                match item {
                    Item::Path { path, pen } => {
                        let lw = Some(lineweight_of(pen.width)).filter(|&lw| lw != kind.lineweight());
                        if let Some(shape) = flip.shape(path) {
                            self.shape(&shape, &layer, lw);
                        }
                    }
                    Item::Circle { c, r, pen, filled: false } => {
                        let lw = Some(lineweight_of(pen.width)).filter(|&lw| lw != kind.lineweight());
                        self.shape(&Shape::Circle(flip.p(*c), *r), &layer, lw);
                    }
                    Item::Circle { c, r, filled: true, .. } => {
                        if self.r2000 {
                            let (c, r) = (flip.p(*c), *r);
                            let v =
                                [Point::new(c.x + r, c.y), Point::new(c.x - r, c.y)].map(|p| Vertex { p, bulge: 1.0 });
                            self.hatch(&v, &layer);
                        } else {
                            self.solids(&outline_points(&shapes::circle(*c, *r), &flip), &layer);
                        }
                    }
                    Item::Fill { path } => {
                        if self.r2000 {
                            let closed = Path { closed: true, ..path.clone() };
                            let v = flip.vertices(&closed);
                            if v.len() >= 3 || v.iter().any(|v| v.bulge != 0.0) {
                                self.hatch(&v, &layer);
                            }
                        } else {
                            let mut b = shapes::bez_path(path);
                            b.close_path();
                            self.solids(&outline_points(&b, &flip), &layer);
                        }
                    }
                    Item::Text(t) => self.text(t, &layer, &flip),
                }
            }
        }
        self.pair(0, "ENDSEC");
    }

    fn shape(&mut self, shape: &Shape, layer: &str, lw: Option<i32>) {
        match shape {
            Shape::Line(a, b) => {
                self.entity("LINE", layer, lw, "AcDbLine");
                self.point(10, *a);
                self.point(11, *b);
            }
            Shape::Circle(c, r) => {
                self.entity("CIRCLE", layer, lw, "AcDbCircle");
                self.point(10, *c);
                self.mm(40, *r);
            }
            Shape::Arc(c, r, start, end) => {
                self.entity("ARC", layer, lw, "AcDbCircle");
                self.point(10, *c);
                self.mm(40, *r);
                self.sub("AcDbArc");
                self.pair(50, num(*start, DEG));
                self.pair(51, num(*end, DEG));
            }
            Shape::Poly(v, closed) => {
                // 128: the linetype's pattern runs on over the vertices (a flattened curve).
                let flags = 128 + u8::from(*closed);
                if self.r2000 {
                    self.entity("LWPOLYLINE", layer, lw, "AcDbPolyline");
                    self.pair(90, v.len());
                    self.pair(70, flags);
                    for x in v {
                        self.point2(10, x.p);
                        if x.bulge != 0.0 {
                            self.pair(42, num(x.bulge, BULGE));
                        }
                    }
                } else {
                    self.entity("POLYLINE", layer, lw, "AcDb2dPolyline");
                    self.pair(66, 1);
                    self.point(10, Point::ORIGIN);
                    self.pair(70, flags);
                    for x in v {
                        self.vertex_head("VERTEX", layer);
                        self.point(10, x.p);
                        if x.bulge != 0.0 {
                            self.pair(42, num(x.bulge, BULGE));
                        }
                        self.pair(70, 0);
                    }
                    self.vertex_head("SEQEND", layer);
                }
            }
        }
    }

    /// A solid fill of a closed outline (R2000).
    fn hatch(&mut self, v: &[Vertex], layer: &str) {
        self.entity("HATCH", layer, None, "AcDbHatch");
        self.point(10, Point::ORIGIN);
        // The extrusion: the drawing's plane.
        self.pair(210, "0.0");
        self.pair(220, "0.0");
        self.pair(230, "1.0");
        self.pair(2, "SOLID");
        self.pair(70, 1);
        self.pair(71, 0);
        self.pair(91, 1);
        // An external polyline boundary.
        self.pair(92, 3);
        let bulges = v.iter().any(|x| x.bulge != 0.0);
        self.pair(72, u8::from(bulges));
        self.pair(73, 1);
        self.pair(93, v.len());
        for x in v {
            self.point2(10, x.p);
            if bulges {
                self.pair(42, num(x.bulge, BULGE));
            }
        }
        self.pair(97, 0);
        self.pair(75, 0);
        self.pair(76, 1);
        self.pair(98, 0);
    }

    /// A solid fill as SOLID triangles (R12).
    fn solids(&mut self, pts: &[Point], layer: &str) {
        for [a, b, c] in triangles(pts) {
            self.entity("SOLID", layer, None, "AcDbTrace");
            self.point(10, a);
            self.point(11, b);
            self.point(12, c);
            self.point(13, c);
        }
    }

    /// Each run of a text with letters as a TEXT at the start of its baseline, where
    /// [`text::set`] puts it (its leading spaces left out, their advance kept).
    fn text(&mut self, t: &Text, layer: &str, flip: &Flip) {
        let set = text::set(t);
        for (run, placed) in t.runs().zip(&set.runs) {
            let letters = placed.text.trim_start();
            if letters.trim_end().is_empty() {
                continue;
            }
            let skipped = placed.text.len() - letters.len();
            let dx = placed.glyphs.iter().find(|g| g.chars.start == skipped).map_or(0.0, |g| g.x);
            let at = flip.p(set.transform * Point::new(placed.origin.x + dx, placed.origin.y));
            self.entity("TEXT", layer, None, "AcDbText");
            self.point(10, at);
            self.mm(40, run.h);
            self.pair(1, escape(letters.trim_end()));
            if t.rotate != 0.0 {
                self.pair(50, num(degrees(t.rotate), DEG));
            }
            if t.stretch != 1.0 {
                self.pair(41, num(t.stretch, DEG));
            }
            if t.sloped {
                self.pair(51, num(OBLIQUE_DEG, DEG));
            }
            self.pair(7, STYLE);
            self.sub("AcDbText");
        }
    }

    fn dictionary(&mut self, kind: &str, handle: u32, owner: u32, entries: &[(&str, u32)]) {
        self.pair(0, kind);
        self.hnd(5, handle);
        self.hnd(330, owner);
        self.pair(100, "AcDbDictionary");
        self.pair(281, 1);
        for &(name, entry) in entries {
            self.pair(3, name);
            self.hnd(350, entry);
        }
    }

    fn objects(&mut self, scene: &Scene) {
        self.pair(0, "SECTION");
        self.pair(2, "OBJECTS");
        self.dictionary(
            "DICTIONARY",
            h::ROOT_DICT,
            0,
            &[
                ("ACAD_GROUP", h::GROUP_DICT),
                ("ACAD_LAYOUT", h::LAYOUT_DICT),
                ("ACAD_MLINESTYLE", h::MLINESTYLE_DICT),
                ("ACAD_PLOTSTYLENAME", h::PLOTSTYLE_DICT),
            ],
        );
        self.dictionary("DICTIONARY", h::GROUP_DICT, h::ROOT_DICT, &[]);
        self.dictionary(
            "DICTIONARY",
            h::LAYOUT_DICT,
            h::ROOT_DICT,
            &[("Model", h::MODEL_LAYOUT), ("Layout1", h::PAPER_LAYOUT)],
        );
        self.dictionary("DICTIONARY", h::MLINESTYLE_DICT, h::ROOT_DICT, &[("Standard", h::MLINESTYLE_STANDARD)]);
        self.dictionary("ACDBDICTIONARYWDFLT", h::PLOTSTYLE_DICT, h::ROOT_DICT, &[("Normal", h::PLOTSTYLE_NORMAL)]);
        self.pair(100, "AcDbDictionaryWithDefault");
        self.hnd(340, h::PLOTSTYLE_NORMAL);
        self.pair(0, "ACDBPLACEHOLDER");
        self.hnd(5, h::PLOTSTYLE_NORMAL);
        self.hnd(330, h::PLOTSTYLE_DICT);
        let size = Point::new(scene.width, scene.height);
        self.layout(h::MODEL_LAYOUT, "Model", 0, h::MODEL_RECORD, size);
        self.layout(h::PAPER_LAYOUT, "Layout1", 1, h::PAPER_RECORD, size);
        self.pair(0, "MLINESTYLE");
        self.hnd(5, h::MLINESTYLE_STANDARD);
        self.hnd(330, h::MLINESTYLE_DICT);
        self.pair(100, "AcDbMlineStyle");
        self.pair(2, "Standard");
        self.pair(70, 0);
        self.pair(3, "");
        self.pair(62, 256);
        self.pair(51, "90.0");
        self.pair(52, "90.0");
        self.pair(71, 2);
        for offset in ["0.5", "-0.5"] {
            self.pair(49, offset);
            self.pair(62, 256);
            self.pair(6, "BYLAYER");
        }
        self.pair(0, "ENDSEC");
    }

    /// A layout on an A1 sheet in millimetres.
    fn layout(&mut self, handle: u32, name: &str, order: i32, record: u32, size: Point) {
        self.pair(0, "LAYOUT");
        self.hnd(5, handle);
        self.hnd(330, h::LAYOUT_DICT);
        self.pair(100, "AcDbPlotSettings");
        self.pair(1, "");
        self.pair(4, "ISO_A1_(841.00_x_594.00_MM)");
        self.pair(6, "");
        for code in [40, 41, 42, 43] {
            self.pair(code, "0.0");
        }
        self.mm(44, size.x);
        self.mm(45, size.y);
        for code in [46, 47, 48, 49, 140, 141] {
            self.pair(code, "0.0");
        }
        self.pair(142, "1.0");
        self.pair(143, "1.0");
        // 70: plot flags (1024 for the model: "model type"); 72: paper units mm; 74: plot
        // type 5 (layout); 75: standard scale 16 (1:1).
        self.pair(70, if order == 0 { 1024 } else { 0 });
        self.pair(72, 1);
        self.pair(73, 0);
        self.pair(74, 5);
        self.pair(7, "");
        self.pair(75, 16);
        self.pair(76, 0);
        self.pair(77, 2);
        self.pair(78, 300);
        self.pair(147, "1.0");
        self.pair(148, "0.0");
        self.pair(149, "0.0");
        self.pair(100, "AcDbLayout");
        self.pair(1, name);
        self.pair(70, 1);
        self.pair(71, order);
        self.point2(10, Point::ORIGIN);
        self.point2(11, size);
        self.point(12, Point::ORIGIN);
        self.point(14, Point::ORIGIN);
        self.point(15, size);
        self.pair(146, "0.0");
        self.point(13, Point::ORIGIN);
        self.point(16, Point::new(1.0, 0.0));
        self.point(17, Point::new(0.0, 1.0));
        self.pair(76, 1);
        self.hnd(330, record);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::scene::{Anchor, DASHED, Group, MAIN, THIN};
    use kurbo::Rect;

    fn scene(items: Vec<Item>) -> Scene {
        let mut g = Group::new("velocity plans", Rect::new(0.0, 0.0, 100.0, 100.0));
        g.items = items;
        Scene {
            ink: Default::default(),
            name: "s".into(),
            width: 100.0,
            height: 80.0,
            title: "t".into(),
            groups: vec![g],
        }
    }

    fn dxf(s: &Scene, v: DxfVersion) -> String {
        String::from_utf8(write(s, v).unwrap()).unwrap()
    }

    /// The values of every `code` pair after the first `0 / kind`.
    fn values<'a>(dxf: &'a str, kind: &str, code: &str) -> Vec<&'a str> {
        let lines: Vec<&str> = dxf.split("\r\n").collect();
        let start = (0..lines.len() - 1).step_by(2).find(|&i| lines[i].trim() == "0" && lines[i + 1] == kind).unwrap();
        let mut out = Vec::new();
        let mut i = start + 2;
        while i + 1 < lines.len() && lines[i].trim() != "0" {
            if lines[i].trim() == code {
                out.push(lines[i + 1]);
            }
            i += 2;
        }
        out
    }

    #[test]
    fn y_is_flipped_up_from_the_sheets_height() {
        let s = scene(vec![Item::Path {
            path: Path::polyline(&[Point::new(1.0, 2.0), Point::new(3.0, 70.0)], false),
            pen: MAIN,
        }]);
        let d = dxf(&s, DxfVersion::R2000);
        assert_eq!(values(&d, "LINE", "10"), ["1.0"]);
        assert_eq!(values(&d, "LINE", "20"), ["78.0"]);
        assert_eq!(values(&d, "LINE", "21"), ["10.0"]);
        assert_eq!(values(&d, "LINE", "8"), ["velocity_plans-contour"]);
    }

    #[test]
    fn an_arc_clockwise_on_paper_runs_clockwise_in_dxf() {
        // From the sheet's right (angle 0) a quarter turn clockwise on paper: down the sheet.
        let s = scene(vec![Item::Path { path: Path::arc(Point::new(50.0, 40.0), 10.0, 0.0, PI / 2.0), pen: THIN }]);
        let d = dxf(&s, DxfVersion::R2000);
        // In DXF (y up) that arc lies below the centre: counter-clockwise from 270° to 360°.
        assert_eq!(values(&d, "ARC", "50"), ["270.0"]);
        assert_eq!(values(&d, "ARC", "51"), ["0.0"]);
        assert_eq!(values(&d, "ARC", "20"), ["40.0"]);
        // Anticlockwise on paper, from the left a quarter up the sheet: 90°..180° in DXF.
        let s = scene(vec![Item::Path { path: Path::arc(Point::new(50.0, 40.0), 10.0, PI, PI / 2.0), pen: THIN }]);
        let d = dxf(&s, DxfVersion::R2000);
        assert_eq!((values(&d, "ARC", "50"), values(&d, "ARC", "51")), (vec!["90.0"], vec!["180.0"]));
        // In a polyline: the bulge of a clockwise (on paper, and so in DXF) arc is negative.
        let mut p = Path::arc(Point::new(50.0, 40.0), 10.0, 0.0, PI / 2.0);
        p.segs.push(Seg::Line(Point::new(0.0, 0.0)));
        let d = dxf(&scene(vec![Item::Path { path: p, pen: THIN }]), DxfVersion::R2000);
        assert_eq!(values(&d, "LWPOLYLINE", "42"), [num(-math::tan(PI / 8.0), BULGE)]);
        assert_eq!(values(&d, "LWPOLYLINE", "20"), ["40.0", "30.0", "80.0"]);
    }

    #[test]
    fn non_ascii_letters_are_escaped() {
        assert_eq!(escape("Механизм"), "\\U+041C\\U+0435\\U+0445\\U+0430\\U+043D\\U+0438\\U+0437\\U+043C");
        assert_eq!(escape("oʻ μ ω ≈ 5°"), "o\\U+02BB \\U+03BC \\U+03C9 \\U+2248 5\\U+00B0");
        assert_eq!(escape("a\\b 3 %%"), "a\\U+005Cb 3 %\\U+0025");
        let s = scene(vec![Item::Text(Text::new(Point::new(10.0, 10.0), "ТММ КП", 5.0, Anchor::Start))]);
        let d = dxf(&s, DxfVersion::R12);
        assert_eq!(values(&d, "TEXT", "1"), ["\\U+0422\\U+041C\\U+041C \\U+041A\\U+041F"]);
        assert!(d.is_ascii());
    }

    #[test]
    fn runs_are_texts_where_the_setter_puts_them() {
        let mut t = Text::new(Point::new(50.0, 40.0), "v", 5.0, Anchor::Middle).with_sub("BA", " = 1");
        t.rotate = 90.0;
        let s = scene(vec![Item::Text(t.clone())]);
        let d = dxf(&s, DxfVersion::R2000);
        let lines: Vec<&str> = d.split("\r\n").collect();
        let texts: Vec<usize> = (0..lines.len() - 1).step_by(2).filter(|&i| lines[i + 1] == "TEXT").collect();
        assert_eq!(texts.len(), 3);
        assert_eq!(entity_counts(&s, DxfVersion::R2000)["TEXT"], 3);
        let set = text::set(&t);
        // The first run starts where the setter's frame puts its origin; turned 90°
        // anticlockwise its baseline runs up the sheet, so in DXF its x stays, y grows.
        let p = set.transform * set.runs[0].origin;
        assert_eq!(values(&d, "TEXT", "10"), [num(p.x, MM)]);
        assert_eq!(values(&d, "TEXT", "20"), [num(80.0 - p.y, MM)]);
        assert_eq!(values(&d, "TEXT", "50"), ["90.0"]);
        assert_eq!(values(&d, "TEXT", "51"), ["15.0"]);
        assert!(p.y > 40.0, "the middle anchor puts the start below the anchor: {p:?}");
    }

    #[test]
    fn two_writes_are_equal_and_counts_match() {
        let mut items = vec![
            Item::Path {
                path: Path::polyline(&[Point::new(0.0, 0.0), Point::new(5.0, 5.0), Point::new(9.0, 1.0)], true),
                pen: DASHED,
            },
            Item::Circle { c: Point::new(20.0, 20.0), r: 3.0, pen: MAIN, filled: false },
            Item::Circle { c: Point::new(30.0, 20.0), r: 0.6, pen: THIN, filled: true },
            Item::Fill {
                path: Path::polyline(&[Point::new(0.0, 0.0), Point::new(2.0, 0.0), Point::new(1.0, 3.0)], true),
            },
        ];
        items.push(Item::Path {
            path: Path::cubics(&[kurbo::CubicBez::new((0.0, 0.0), (10.0, 20.0), (30.0, 20.0), (40.0, 0.0))]),
            pen: THIN,
        });
        let s = scene(items);
        for v in [DxfVersion::R2000, DxfVersion::R12] {
            assert_eq!(write(&s, v).unwrap(), write(&s, v).unwrap());
        }
        let c = entity_counts(&s, DxfVersion::R2000);
        assert_eq!(c.get("LWPOLYLINE"), Some(&2));
        assert_eq!(c.get("HATCH"), Some(&2));
        assert_eq!(c.get("CIRCLE"), Some(&1));
        let c = entity_counts(&s, DxfVersion::R12);
        assert_eq!(c.get("POLYLINE"), Some(&2));
        assert!(c["SOLID"] > 2, "{c:?}");
        let d = dxf(&s, DxfVersion::R2000);
        assert!(d.contains("\r\nDASHED\r\n") && d.contains("\r\nvelocity_plans-dashed\r\n"));
    }

    #[test]
    fn a_non_finite_number_is_refused() {
        let bad = Item::Circle { c: Point::new(f64::NAN, 1.0), r: 1.0, pen: THIN, filled: false };
        assert!(matches!(write(&scene(vec![bad]), DxfVersion::R2000), Err(BackendError::NonFinite { .. })));
    }

    #[test]
    fn numbers_are_fixed_and_never_negative_zero() {
        assert_eq!(num(-0.0001, MM), "0.0");
        assert_eq!(num(12.0, MM), "12.0");
        assert_eq!(num(8.4666666, MM), "8.467");
        assert_eq!(degrees(-90.0), 270.0);
        assert_eq!(degrees(360.0), 0.0);
        assert_eq!(lineweight_of(0.45), 50);
        assert_eq!(lineweight_of(1.2), 120);
        assert_eq!(lineweight_of(0.25), 25);
    }

    #[test]
    fn ear_clipping_covers_a_concave_outline() {
        let l = [(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (1.0, 1.0), (1.0, 4.0), (0.0, 4.0)].map(|(x, y)| Point::new(x, y));
        let t = triangles(&l);
        assert_eq!(t.len(), 4);
        let area: f64 = t.iter().map(|[a, b, c]| ((*b - *a).cross(*c - *a)).abs() / 2.0).sum();
        assert!((area - 7.0).abs() < 1e-12, "{area}");
    }
}
