//! The sheet measures its own layout: texts crossed by a drawn line, texts overlapping
//! each other, items leaving their region or the page. A teacher sends a sheet back for any of them, so
//! `results.json` reports the counts and the tests hold them at zero.

use super::frame::{self, DESIGNATION_BOX, FRAME, TITLE_BLOCK};
use super::obstacles::{Obstacles, segments};
use super::phrases;
use super::scene::{Item, Scene};
use crate::num::math::{Norm, rect_inside as inside};
use kurbo::{Point, Rect};
use overlaps::overlapping_runs;

mod overlaps;

/// A text's box is shrunk by this much before testing: a line touching the letters' box
/// passes beside the letters (glyphs do not fill their box), one entering it does not.
pub const TOUCH: f64 = 0.1;
/// A border stroke centred on a region's edge counts as inside (half the main line).
const EDGE: f64 = 0.36;
/// The side of the cells the sheet's segments are indexed in, mm: the whole sheet's lines
/// are indexed for a few hundred texts' questions, so indexing costs more than asking
/// (on the worked example's sheet 1, 6–20 mm cells 2 % faster than the labels' 3 mm).
const STROKE_CELL: f64 = 10.0;
/// How many problems are described in words.
const DESCRIBED: usize = 20;

/// The counts of layout defects on one sheet.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize)]
pub struct Layout {
    /// Texts whose letters a drawn line (stroke, arrowhead, symbol, hatching) crosses.
    pub texts_crossed: usize,
    /// Pairs of texts whose letters overlap.
    pub text_overlaps: usize,
    /// Pairs of texts on one line, one stating a value, so close that they read as one
    /// phrase ([`phrases::run_together`]).
    pub texts_run_together: usize,
    /// Items not inside their group's region, or not on the page (a region may itself have
    /// grown off the page with what it holds); an item leaving both counts once.
    pub outside_region: usize,
    /// The shortest side of the smallest velocity or acceleration plan, mm (a sheet without
    /// plans has none).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smallest_plan_mm: Option<f64>,
    /// The share of the drawing field's 20 mm cells that hold no ink (no line, no letter),
    /// from 0 to 1: how much of the sheet is left empty (the frame and the title block do not
    /// count).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub empty_share: Option<f64>,
    /// The longest leader joining a label to its point, mm, to 0.1 mm (a sheet without
    /// leaders has none): a label far off on a long leader is read, but a teacher marks it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub longest_leader_mm: Option<f64>,
    /// The first problems in words, for the user and the tests.
    pub problems: Vec<String>,
}

/// The counts of [`Layout`] that are faults, as `results.json` names them: a clean sheet has
/// none of any.
pub const FAULTS: [&str; 4] = ["texts_crossed", "text_overlaps", "outside_region", "texts_run_together"];

impl Layout {
    pub fn is_clean(&self) -> bool {
        self.faults() == [0; 4]
    }

    /// The counts named by [`FAULTS`], in its order.
    pub fn faults(&self) -> [usize; 4] {
        [self.texts_crossed, self.text_overlaps, self.outside_region, self.texts_run_together]
    }

    fn note(&mut self, what: String) {
        if self.problems.len() < DESCRIBED {
            self.problems.push(what);
        }
    }
}

/// Every item's [`segments`] (a text's none), group by group: flattened once for both
/// [`measure`] and [`empty_share`].
type Flattened = Vec<Vec<Vec<(Point, Point)>>>;

fn flattened(scene: &Scene) -> Flattened {
    scene.groups.iter().map(|g| g.items.iter().map(segments).collect()).collect()
}

/// [`measure`] and [`empty_share`] of `scene` together, its lines flattened once.
pub fn measure_with_share(scene: &Scene, field: Rect, excluded: Rect, skip: &[&str]) -> (Layout, f64) {
    let flat = flattened(scene);
    (measure_flat(scene, &flat), empty_share_flat(scene, &flat, field, excluded, skip))
}

/// Measures the layout of `scene`.
pub fn measure(scene: &Scene) -> Layout {
    measure_flat(scene, &flattened(scene))
}

/// The texts of `scene` whose letters' boxes, grown by `clearance` (mm; negative shrinks
/// them), a drawn line meets: each as its group's and its item's index.
fn texts_meeting_lines(scene: &Scene, strokes: &Obstacles, clearance: f64) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for (gi, g) in scene.groups.iter().enumerate() {
        for (ii, item) in g.items.iter().enumerate() {
            let Item::Text(t) = item else { continue };
            let met = t.core_boxes().any(|b| {
                let r = b.inflate(clearance, clearance);
                strokes.segment_meets(r)
            });
            if met {
                out.push((gi, ii));
            }
        }
    }
    out
}

/// The texts of `scene` that a drawn line passes within `clearance` of (mm, from the
/// letters' boxes), each as its group's and its item's index: letters that touch a line
/// read as crowded even where none crosses them (the tests hold placed labels 0.4 mm clear).
pub fn texts_near_lines(scene: &Scene, clearance: f64) -> Vec<(usize, usize)> {
    texts_meeting_lines(scene, &strokes(scene, &flattened(scene)), clearance)
}

/// The drawn lines of `scene` (not its texts), indexed.
fn strokes(scene: &Scene, flat: &Flattened) -> Obstacles {
    let drawn = scene.groups.iter().zip(flat).flat_map(|(g, segs)| g.items.iter().zip(segs));
    Obstacles::of_flattened(drawn.filter(|(i, _)| !is_text(i)).map(|(i, s)| (i, &s[..])), STROKE_CELL)
}

fn measure_flat(scene: &Scene, flat: &Flattened) -> Layout {
    let mut out = Layout::default();
    let strokes = strokes(scene, flat);
    for (gi, ii) in texts_meeting_lines(scene, &strokes, -TOUCH) {
        let g = &scene.groups[gi];
        let Item::Text(t) = &g.items[ii] else { continue };
        out.texts_crossed += 1;
        out.note(format!("drawing '{}': a line crosses “{}” at ({:.1}, {:.1}) mm", g.id, t.plain(), t.at.x, t.at.y));
    }
    let texts: Vec<(&str, &super::scene::Text)> =
        scene.groups.iter().flat_map(|g| g.texts().map(move |t| (g.id.as_str(), t))).collect();
    // Every run's box, tagged with its text: a text's own runs touch, never count.
    let runs: Vec<(Rect, usize)> =
        texts.iter().enumerate().flat_map(|(k, (_, t))| t.core_boxes().map(move |b| (b, k))).collect();
    let mut seen = std::collections::BTreeSet::new();
    for (i, j) in overlapping_runs(&runs) {
        let ((_, k), (_, other)) = (runs[i], runs[j]);
        let ((group, t), (og, o)) = (texts[k], texts[other]);
        if seen.insert((k, other)) {
            out.text_overlaps += 1;
            out.note(format!(
                "drawing '{group}': “{}” overlaps “{}” ('{og}') at ({:.1}, {:.1}) mm",
                t.plain(),
                o.plain(),
                t.at.x,
                t.at.y
            ));
        }
    }
    let page = Rect::new(0.0, 0.0, scene.width, scene.height);
    // The title block and box 26 are no drawing's room, whatever its region says.
    let blocks: Vec<Rect> = scene
        .groups
        .iter()
        .filter(|g| g.id == TITLE_BLOCK || g.id == DESIGNATION_BOX)
        .map(|g| g.region.inflate(-EDGE, -EDGE))
        .collect();
    // A sheet's drawings stay inside its frame (a diagrams' column whose region ran 5 mm past
    // it, its items inside that region, was counted clean).
    let inner = scene.groups.iter().any(|g| g.id == FRAME).then(frame::inner);
    for g in &scene.groups {
        let region = g.region.inflate(EDGE, EDGE);
        let own = [TITLE_BLOCK, DESIGNATION_BOX, FRAME].contains(&g.id.as_str());
        let inner = inner.filter(|_| !own);
        for item in &g.items {
            let bb = item.bbox();
            for tb in blocks.iter().filter(|tb| !own && tb.intersect(bb).area() > 0.0) {
                if !Obstacles::of_items([item]).is_clear(*tb) {
                    out.outside_region += 1;
                    out.note(format!("drawing '{}': {} enters the title block {}", g.id, extent(bb), extent(*tb)));
                }
            }
            if !inside(page.inflate(EDGE, EDGE), bb) {
                out.outside_region += 1;
                out.note(format!(
                    "drawing '{}': {} leaves the page by {:.1} mm",
                    g.id,
                    extent(bb),
                    overshoot(page, bb)
                ));
            } else if let Some(f) = inner.filter(|f| !inside(f.inflate(EDGE, EDGE), bb)) {
                out.outside_region += 1;
                out.note(format!("drawing '{}': {} leaves the frame by {:.1} mm", g.id, extent(bb), overshoot(f, bb)));
            } else if !inside(region, bb) {
                out.outside_region += 1;
                out.note(format!(
                    "drawing '{}': {} leaves its region {} by {:.1} mm",
                    g.id,
                    extent(bb),
                    extent(g.region),
                    overshoot(g.region, bb)
                ));
            }
        }
    }
    for r in phrases::run_together(scene, &strokes) {
        out.texts_run_together += 1;
        out.note(format!(
            "drawing '{}': “{}” and “{}” read as one phrase, {:.1} mm apart at ({:.1}, {:.1}) mm",
            r.group, r.first, r.second, r.gap, r.at.x, r.at.y
        ));
    }
    out.longest_leader_mm = longest_leader(scene).map(|mm| (mm * 10.0).round() / 10.0);
    out
}

/// The longest of the scene's leaders, end to end, mm.
fn longest_leader(scene: &Scene) -> Option<f64> {
    let leaders = scene.groups.iter().flat_map(|g| g.leaders.iter().map(|&k| &g.items[k]));
    leaders
        .filter_map(|item| match item {
            Item::Path { path, .. } => Some((path.end() - path.start).norm()),
            _ => None,
        })
        .reduce(f64::max)
}

/// The side of the cells [`empty_share`] counts, mm.
pub const CELL: f64 = 20.0;

/// The share of `field`'s whole `CELL` × `CELL` cells (those not meeting `excluded`, the
/// title block) that no item of `scene` touches; the groups named in `skip` (the frame
/// itself) are not ink. Lines are walked in steps under a cell, texts by their letters' boxes.
pub fn empty_share(scene: &Scene, field: Rect, excluded: Rect, skip: &[&str]) -> f64 {
    empty_share_flat(scene, &flattened(scene), field, excluded, skip)
}

fn empty_share_flat(scene: &Scene, flat: &Flattened, field: Rect, excluded: Rect, skip: &[&str]) -> f64 {
    let (nx, ny) = ((field.width() / CELL).floor() as usize, (field.height() / CELL).floor() as usize);
    // A point's cell, column and row (off the field: out of range).
    let cell_at = |x: f64, y: f64| (((x - field.x0) / CELL).floor() as i64, ((y - field.y0) / CELL).floor() as i64);
    let mut inked = vec![false; nx * ny];
    for (g, segs) in scene.groups.iter().zip(flat).filter(|(g, _)| !skip.contains(&g.id.as_str())) {
        for (item, segs) in g.items.iter().zip(segs) {
            match item {
                Item::Text(t) => {
                    // Every cell a letters' box meets, from its corners' cells.
                    for b in t.core_boxes() {
                        let (lo, hi) = (cell_at(b.x0, b.y0), cell_at(b.x1, b.y1));
                        for j in lo.1.max(0)..=hi.1.min(ny as i64 - 1) {
                            for i in lo.0.max(0)..=hi.0.min(nx as i64 - 1) {
                                inked[j as usize * nx + i as usize] = true;
                            }
                        }
                    }
                }
                _ => {
                    for &(a, b) in segs {
                        let steps = ((b - a).norm() / (CELL / 4.0)).ceil().max(1.0) as usize;
                        for k in 0..=steps {
                            let p = a.lerp(b, k as f64 / steps as f64);
                            let (i, j) = cell_at(p.x, p.y);
                            if (0..nx as i64).contains(&i) && (0..ny as i64).contains(&j) {
                                inked[j as usize * nx + i as usize] = true;
                            }
                        }
                    }
                }
            }
        }
    }
    let counted: Vec<bool> = (0..nx * ny)
        .filter(|&k| {
            let (x0, y0) = (field.x0 + (k % nx) as f64 * CELL, field.y0 + (k / nx) as f64 * CELL);
            Rect::new(x0, y0, x0 + CELL, y0 + CELL).intersect(excluded).area() <= 0.0
        })
        .map(|k| inked[k])
        .collect();
    let empty = counted.iter().filter(|&&ink| !ink).count();
    if counted.is_empty() { 0.0 } else { empty as f64 / counted.len() as f64 }
}

fn is_text(i: &Item) -> bool {
    matches!(i, Item::Text(_))
}

/// A box as a reader finds it on the sheet: its corners in paper millimetres.
fn extent(r: Rect) -> String {
    format!("({:.1}, {:.1})–({:.1}, {:.1}) mm", r.x0, r.y0, r.x1, r.y1)
}

/// How far `inner` reaches past `outer` on its worst side, mm.
fn overshoot(outer: Rect, inner: Rect) -> f64 {
    [outer.x0 - inner.x0, inner.x1 - outer.x1, outer.y0 - inner.y0, inner.y1 - outer.y1].into_iter().fold(0.0, f64::max)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::drawing::scene::{Anchor, Group, THIN, Text};
    use kurbo::Point;

    /// A 100 × 100 mm scene of one group "g" (as large) holding `items`.
    pub(crate) fn scene(items: Vec<Item>) -> Scene {
        let mut g = Group::new("g", Rect::new(0.0, 0.0, 100.0, 100.0));
        g.items = items;
        Scene {
            ink: Default::default(),
            name: "s".into(),
            width: 100.0,
            height: 100.0,
            title: String::new(),
            groups: vec![g],
        }
    }

    /// A 100 × 60 mm field is 5 × 3 cells; a line along the top row inks its five, a text
    /// in the middle of the bottom row one more; the frame group is not ink, and a cell
    /// under the excluded box is not counted.
    #[test]
    fn empty_share_counts_the_cells_without_ink() {
        let line = Item::Path {
            path: crate::drawing::path::Path::polyline(&[Point::new(2.0, 10.0), Point::new(98.0, 10.0)], false),
            pen: THIN,
        };
        let text = Item::Text(Text::new(Point::new(45.0, 50.0), "x", 2.5, Anchor::Start));
        let mut frame = Group::new("frame", Rect::new(0.0, 0.0, 100.0, 60.0));
        frame.items.push(Item::Path {
            path: crate::drawing::path::Path::polyline(&[Point::new(0.0, 0.0), Point::new(100.0, 60.0)], false),
            pen: THIN,
        });
        let mut s = scene(vec![line, text]);
        s.groups.push(frame);
        let field = Rect::new(0.0, 0.0, 100.0, 60.0);
        let share = empty_share(&s, field, Rect::ZERO, &["frame"]);
        assert!((share - 9.0 / 15.0).abs() < 1e-12, "{share}");
        let corner = Rect::new(80.0, 40.0, 100.0, 60.0);
        assert!((empty_share(&s, field, corner, &["frame"]) - 8.0 / 14.0).abs() < 1e-12);
    }

    #[test]
    fn a_line_through_a_label_an_overlap_and_an_escape_are_each_counted() {
        let line = |a: (f64, f64), b: (f64, f64)| Item::Path {
            path: crate::drawing::path::Path::polyline(&[a.into(), b.into()], false),
            pen: THIN,
        };
        let text = |x: f64, y: f64, s: &str| Item::Text(Text::new(Point::new(x, y), s, 5.0, Anchor::Start));
        let clean = scene(vec![line((0.0, 30.0), (90.0, 30.0)), text(10.0, 20.0, "A"), text(40.0, 20.0, "B")]);
        assert!(measure(&clean).is_clean(), "{:?}", measure(&clean));
        let crossed = scene(vec![line((0.0, 18.0), (90.0, 18.0)), text(10.0, 20.0, "A")]);
        assert_eq!(measure(&crossed).texts_crossed, 1);
        let touching = scene(vec![line((0.0, 20.0), (90.0, 20.0)), text(10.0, 20.0, "A")]);
        assert_eq!(measure(&touching).texts_crossed, 0, "a line along the baseline only touches");
        let overlap = scene(vec![text(10.0, 20.0, "AAA"), text(12.0, 21.0, "BBB")]);
        assert_eq!(measure(&overlap).text_overlaps, 1);
        let out = scene(vec![line((0.0, 18.0), (190.0, 18.0))]);
        assert_eq!(measure(&out).outside_region, 1);
        // Each problem names the drawing and says where in paper mm, in a reader's words.
        for m in [measure(&crossed), measure(&overlap), measure(&out)] {
            let p = &m.problems[0];
            assert!(p.starts_with("drawing 'g': ") && p.contains(" mm") && !p.contains('{'), "{p}");
        }
        assert!(measure(&out).problems[0].contains("by 90.1 mm"), "{:?}", measure(&out).problems);
    }

    /// A region grown off the page with what it holds (notes set under the page's edge)
    /// keeps its items inside it: they are counted for leaving the page, once each.
    #[test]
    fn an_item_off_the_page_is_counted_even_inside_its_region() {
        let mut s = scene(vec![Item::Text(Text::new(Point::new(10.0, 20.0), "on the page", 2.5, Anchor::Start))]);
        assert!(measure(&s).is_clean());
        s.groups[0].region = Rect::new(0.0, 0.0, 100.0, 200.0);
        s.groups[0].items.push(Item::Text(Text::new(Point::new(10.0, 150.0), "below", 2.5, Anchor::Start)));
        s.groups[0].items.push(Item::Text(Text::new(Point::new(10.0, 101.0), "across the edge", 2.5, Anchor::Start)));
        let m = measure(&s);
        assert_eq!(m.outside_region, 2, "{m:?}");
        assert!(m.problems.iter().all(|p| p.contains("leaves the page")), "{m:?}");
        s.groups[0].region = Rect::new(0.0, 0.0, 50.0, 200.0);
        s.groups[0].items.push(Item::Text(Text::new(Point::new(60.0, 60.0), "beside", 2.5, Anchor::Start)));
        assert_eq!(measure(&s).outside_region, 3, "leaving the page and the region counts once");
    }

    /// A sheet's drawing stays inside its frame even where its region reaches past it (sheet
    /// 3's diagrams' column ran 5 mm past the frame's foot, its notes inside their region):
    /// an item past the frame's inside is counted once a scene has a frame.
    #[test]
    fn an_item_past_the_frame_is_counted_even_inside_its_region() {
        let inner = frame::inner();
        let below = |y: f64| Item::Text(Text::new(Point::new(100.0, y), "note", 2.5, Anchor::Start));
        let mut s = scene(vec![below(inner.y1 - 5.0), below(inner.y1 + 4.0)]);
        (s.width, s.height) = (841.0, 594.0);
        s.groups[0].region = Rect::new(inner.x0, inner.y0, 400.0, 594.0);
        assert!(measure(&s).is_clean(), "no frame drawn: the page bounds it");
        s.groups.push(Group::new(FRAME, Rect::new(0.0, 0.0, 841.0, 594.0)));
        let m = measure(&s);
        assert_eq!(m.outside_region, 1, "{m:?}");
        assert!(m.problems[0].contains("leaves the frame"), "{m:?}");
    }

    /// The title block is no drawing's room even where a drawing's region covers it (a mesh
    /// region as wide as the tables leave ran over it, its circles' arcs through the block's
    /// lines): an arc entering it is counted, one passing round its corner is not.
    #[test]
    fn a_drawing_entering_the_title_block_is_counted_even_inside_its_region() {
        let arc = |r: f64| Item::Path { path: crate::drawing::path::Path::arc(Point::ZERO, r, 0.0, 1.5), pen: THIN };
        let mut s = scene(vec![arc(105.0)]);
        (s.width, s.height, s.groups[0].region) = (200.0, 200.0, Rect::new(0.0, 0.0, 200.0, 200.0));
        s.groups.push(Group::new(TITLE_BLOCK, Rect::new(70.0, 70.0, 100.0, 100.0)));
        let m = measure(&s);
        assert_eq!(m.outside_region, 1, "{m:?}");
        assert!(m.problems[0].contains("enters the title block"), "{m:?}");
        // Radius 105 passes through (74.2, 74.2); radius 95 stays short of the block's corner
        // (99.0 from the centre), though its box overlaps the block's.
        s.groups[0].items = vec![arc(95.0)];
        assert!(measure(&s).is_clean(), "{:?}", measure(&s));
    }

    /// A thick line's ink reaches into a text whose box its centre line only passes beside:
    /// the letters sitting 0.05 mm under a 0.7 mm line's centre are crossed, under a thin
    /// line's they are not.
    #[test]
    fn a_thick_lines_ink_crossing_a_text_is_counted() {
        let text = Item::Text(Text::new(Point::new(10.0, 25.15), "A", 5.0, Anchor::Start));
        let top = match &text {
            Item::Text(t) => t.core_box().y0,
            _ => unreachable!(),
        };
        let y = top - 0.05;
        for (pen, crossed) in [(THIN, 0), (crate::drawing::scene::MAIN, 1)] {
            let line = Item::Path {
                path: crate::drawing::path::Path::polyline(&[(0.0, y).into(), (90.0, y).into()], false),
                pen,
            };
            assert_eq!(measure(&scene(vec![line, text.clone()])).texts_crossed, crossed, "{pen:?}");
        }
    }

    /// A leader ran through the space of an enlargement's title "μP = 75 N/mm)" between the
    /// subscript and "=" (task 8 variant 26 in English), and neither the placer nor this
    /// measure saw it: a run's box now starts where the run before it ends. A line through
    /// that space crosses the text; one just past its end does not.
    #[test]
    fn a_line_through_the_space_between_a_subscript_and_its_tail_crosses_the_text() {
        let mut g = Group::new("g", Rect::new(0.0, 0.0, 100.0, 100.0));
        crate::drawing::text::LabelText::new("μ", "P").with_tail(" = 75 N/mm)").draw(
            &mut g,
            Point::new(51.734, 78.792),
            3.5,
            Anchor::Start,
        );
        let Item::Text(t) = &g.items[0] else { panic!("{:?}", g.items) };
        let (sub_end, tail) = (t.core_boxes().nth(1).unwrap().x1, t.core_box().x1);
        let vertical = |x: f64| Item::Path {
            path: crate::drawing::path::Path::polyline(&[(x, 82.7).into(), (x, 4.0).into()], false),
            pen: THIN,
        };
        for (x, crossed) in [(sub_end + 0.6, 1), (tail + 0.5, 0)] {
            let items = vec![g.items[0].clone(), vertical(x)];
            assert_eq!(measure(&scene(items)).texts_crossed, crossed, "a line at x = {x}");
        }
    }
}
