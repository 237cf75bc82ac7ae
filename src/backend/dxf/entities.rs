//! The ENTITIES section: every item of the scene as lines, arcs, polylines, hatches and texts.

use super::*;
use crate::drawing::path::Path;
use crate::drawing::scene::Text;

impl Writer {
    /// An entity's head: type, handle, owner (the model space), layer, and in R2000 its
    /// lineweight when the pen's differs from its layer's.
    pub(super) fn entity(&mut self, kind: &'static str, layer: &str, lineweight: Option<i32>, marker: &str) {
        *self.counts.entry(kind).or_default() += 1;
        self.vertex_head(kind, layer);
        if let Some(lw) = lineweight.filter(|_| self.r2000) {
            self.pair(370, lw);
        }
        self.sub(marker);
    }

    /// The head of an entity or of a VERTEX and SEQEND (not counted).
    pub(super) fn vertex_head(&mut self, kind: &str, layer: &str) {
        self.pair(0, kind);
        let handle = self.handle();
        self.hnd(5, handle);
        self.owner(h::MODEL_RECORD);
        self.sub("AcDbEntity");
        self.pair(8, layer);
    }

    pub(super) fn entities(&mut self, scene: &Scene) {
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

    pub(super) fn shape(&mut self, shape: &Shape, layer: &str, lw: Option<i32>) {
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
    pub(super) fn hatch(&mut self, v: &[Vertex], layer: &str) {
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
    pub(super) fn solids(&mut self, pts: &[Point], layer: &str) {
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
    pub(super) fn text(&mut self, t: &Text, layer: &str, flip: &Flip) {
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
}
