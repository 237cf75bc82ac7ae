//! Label placement that sees everything drawn: a view draws its geometry and fixed texts
//! into a group, asks for its labels ([`Labels::add`]: an anchor, a preferred direction, a
//! symbol with its subscript), and places them all at the end ([`Labels::place`]), when the
//! group holds every line, arrowhead, symbol, hatching and text they must keep clear of.
//!
//! Each label tries candidate boxes around its anchor — 16 directions from the preferred one,
//! at growing distances — scored by distance and turn from the preferred direction, and
//! takes the best one that no stroke crosses, no text overlaps and the bounds contain. Labels
//! are resolved most-constrained first (fewest free candidates against the drawing), and
//! each placed label becomes an obstacle for the rest. A label standing off its anchor
//! gets a short thin leader line. The geometry sits in an R-tree ([`super::obstacles`]).

use super::obstacles::{Obstacles, Piece};
use super::scene::{Anchor, Group, THIN};
use super::text::{LabelText, SLANT, SUB};
use candidate::{Candidate, TOUCH, Verdict, least_bad};
use kurbo::{Point, Rect, Vec2};
use spots::Spots;

mod candidate;
mod spots;

/// Distances tried between an anchor and its label's box, mm.
const DISTANCES: [f64; 19] =
    [0.5, 1.0, 1.7, 2.6, 3.7, 5.0, 6.6, 8.5, 11.0, 14.0, 18.0, 23.0, 30.0, 38.0, 48.0, 60.0, 80.0, 105.0, 135.0];
/// From this distance on, a leader line joins the label to its anchor, mm.
const LEADER_FROM: f64 = 4.0;
/// The leader starts this far from the anchor, clear of the joint or dot drawn there, mm.
const LEADER_GAP: f64 = 0.8;
/// Clearance kept between a label's box and any stroke, mm: at 0.25 a letter touched a thick
/// line's ink ("φ1 = 45,0°" under a load diagram's mark, 148 texts within 0.4 mm of a line
/// on the fixtures' sheets); at 0.5 every catalogue sheet still lays out clean.
const CLEAR: f64 = 0.5;
/// More room kept beside a placed position number for the next label, mm (about a space),
/// and the rank from which labels are position numbers.
const LABEL_GAP: f64 = 0.7;
const NUMBERS_RANK: u8 = 2;
const DIRECTIONS: usize = 24;
/// Baseline to baseline in a stacked label, in lettering heights.
const LINE_PITCH: f64 = 1.4;

/// One label to place.
#[derive(Debug, Clone)]
struct Request {
    anchor: Point,
    pref: Vec2,
    /// Further anchors on the same line with their preferred directions, tried after the
    /// first one's near spots (a profile's name where its first point is crowded).
    others: Vec<(Point, Vec2)>,
    label: LabelText,
    /// Further lines set under the first, centred on it (one label in a stack).
    more: Vec<LabelText>,
    h: f64,
    /// Lower goes first: a class of labels (a mechanism's joint letters) may claim the
    /// best spots before another (its position numbers).
    rank: u8,
    /// A label naming a line (a curve's name): always on a leader that touches the line.
    names_line: bool,
}

impl Request {
    /// A one-line label of rank 0 at one anchor.
    fn new(anchor: Point, pref: Vec2, label: LabelText, h: f64) -> Request {
        Request { anchor, pref, others: Vec::new(), label, more: Vec::new(), h, rank: 0, names_line: false }
    }

    /// The label's box: width, height above the first baseline, depth below it (the further
    /// lines included).
    fn size(&self) -> (f64, f64, f64) {
        let (w, up, down) = label_size(&self.label, self.h);
        self.more.iter().fold((w, up, down), |(w, up, _), line| {
            let (lw, _, ld) = label_size(line, self.h);
            (w.max(lw), up, ld + self.more.len() as f64 * LINE_PITCH * self.h)
        })
    }

    /// A candidate's leader as drawn: a line's name's reaches the line it names.
    fn drawn_leader(&self, c: &Candidate) -> Option<(Point, Point)> {
        c.leader.map(|(a, b)| (if self.names_line { c.anchor } else { a }, b))
    }
}

/// Labels waiting for the geometry of their group to be complete.
#[derive(Debug, Default)]
pub struct Labels {
    requests: Vec<Request>,
    /// Discs no label may enter.
    keep_out: Vec<(Point, f64)>,
}

/// The size of a label's box at lettering height `h` (slant and subscript included): width,
/// height above the baseline, depth below it.
pub fn label_size(label: &LabelText, h: f64) -> (f64, f64, f64) {
    let w = label.width(h) + SLANT * h;
    let below = if label.sub.is_empty() { 0.3 * h } else { 0.3 * h + 0.3 * h * SUB };
    (w, 1.05 * h, below)
}

impl Labels {
    pub fn new() -> Labels {
        Labels::default()
    }

    /// A label beside `anchor`, preferably in direction `pref` (paper coordinates; zero:
    /// up and right).
    pub fn add(&mut self, anchor: Point, pref: Vec2, label: LabelText, h: f64) {
        self.add_ranked(anchor, pref, label, h, 0);
    }

    /// A label placed after every label of a lower rank.
    pub fn add_ranked(&mut self, anchor: Point, pref: Vec2, label: LabelText, h: f64, rank: u8) {
        self.requests.push(Request { rank, ..Request::new(anchor, pref, label, h) });
    }

    /// One label of several plain lines stacked and centred, the first nearest `pref`'s
    /// side (names of one point too many for one line: "p=b=s3=" over "c=s4=s5").
    pub fn add_text_lines(&mut self, anchor: Point, pref: Vec2, lines: &[String], h: f64) {
        self.add_label_lines(anchor, pref, lines.iter().map(|l| LabelText::new(l, "")).collect(), h);
    }

    /// As [`Labels::add_text_lines`], each line a label with its subscript ("a=n" over "BA").
    pub fn add_label_lines(&mut self, anchor: Point, pref: Vec2, mut lines: Vec<LabelText>, h: f64) {
        if lines.is_empty() {
            return;
        }
        let first = lines.remove(0);
        self.requests.push(Request { more: lines, ..Request::new(anchor, pref, first, h) });
    }

    /// A label beside the first of `spots` (a point and its preferred direction), or beside
    /// a further one when the spots near the first are taken: an arrow's name beside its
    /// middle, else nearer its tip or its tail, rather than off on a long leader.
    pub fn add_at_any(&mut self, spots: &[(Point, Vec2)], label: LabelText, h: f64) {
        self.push_at_any(spots, Request::new(Point::ZERO, Vec2::ZERO, label, h));
    }

    /// `req` at the first of `spots`, the rest its further anchors.
    fn push_at_any(&mut self, spots: &[(Point, Vec2)], req: Request) {
        let Some((&(anchor, pref), others)) = spots.split_first() else { return };
        self.requests.push(Request { anchor, pref, others: others.to_vec(), ..req });
    }

    /// A line's name (a profile's, a circle's) with `anchor` on the line: set off on a leader
    /// that reaches the line, so that it cannot be taken for a neighbour's name.
    pub fn add_line_name(&mut self, anchor: Point, pref: Vec2, label: LabelText, h: f64, rank: u8) {
        self.add_line_name_at_any(&[(anchor, pref)], label, h, rank);
    }

    /// A line's name as [`Labels::add_line_name`], with further points of the line (and
    /// their directions) to name it at when the spots near the first are taken.
    pub fn add_line_name_at_any(&mut self, spots: &[(Point, Vec2)], label: LabelText, h: f64, rank: u8) {
        self.push_at_any(spots, Request { rank, names_line: true, ..Request::new(Point::ZERO, Vec2::ZERO, label, h) });
    }

    /// A disc (paper mm) every label keeps out of, though nothing drawn bounds it there.
    pub fn keep_out(&mut self, centre: Point, r: f64) {
        self.keep_out.push((centre, r));
    }

    /// A plain text label.
    pub fn add_text(&mut self, anchor: Point, pref: Vec2, text: &str, h: f64) {
        self.add(anchor, pref, LabelText::new(text, ""), h);
    }

    /// A plain text label of a rank (see [`Labels::add_ranked`]).
    pub fn add_text_ranked(&mut self, anchor: Point, pref: Vec2, text: &str, h: f64, rank: u8) {
        self.add_ranked(anchor, pref, LabelText::new(text, ""), h, rank);
    }

    /// Places every label inside `bounds`, clear of everything `g` holds now, and draws them;
    /// returns whether each found a clean spot (the layout measurement reports those that
    /// did not).
    pub fn place(self, g: &mut Group, bounds: Rect) -> Vec<bool> {
        // Every box tried is inside the bounds and every leader runs from near its anchor
        // to its box: what lies beyond both cannot touch them (a cell's labels need not
        // see the cells drawn before it).
        let reach = self.requests.iter().flat_map(|r| std::iter::once(r.anchor).chain(r.others.iter().map(|o| o.0)));
        let reach = reach.fold(bounds, |b, p| b.union_pt(p)).inflate(REACH, REACH);
        let mut drawn = Obstacles::of_items_within(&g.items, reach);
        for &(c, r) in &self.keep_out {
            drawn.add(Piece::Disc(c, r), usize::MAX);
        }
        // What the drawing alone says of each candidate is asked once (see `Verdict`): the
        // order and every round below ask it again and again, and it does not change as
        // labels are placed.
        let mut spots: Vec<Spots> = self.requests.iter().map(|r| Spots::new(r, bounds)).collect();
        // By rank, then most constrained first: the fewest candidates free against the
        // drawing alone.
        let mut order: Vec<usize> = (0..self.requests.len()).collect();
        // Counting stops at a few: beyond that a label is not constrained.
        let free: Vec<usize> =
            (0..self.requests.len()).map(|i| free_near_first(&mut spots[i], &self.requests[i], &drawn)).collect();
        order.sort_by_key(|&i| (self.requests[i].rank, free[i]));
        // A label left without a clean spot goes first in the next round (labels placed
        // before it took its spots), up to a few rounds; the best round is kept.
        let mut best = self.attempt(&drawn, &mut spots, &order, bounds);
        for _ in 0..REPAIR_ROUNDS {
            let failed: Vec<usize> = order.iter().copied().filter(|&i| !best[i].1).collect();
            if failed.is_empty() {
                break;
            }
            order.retain(|i| !failed.contains(i));
            order.splice(0..0, failed);
            let next = self.attempt(&drawn, &mut spots, &order, bounds);
            if next.iter().filter(|p| !p.1).count() < best.iter().filter(|p| !p.1).count() {
                best = next;
            }
        }
        let mut placed = Vec::with_capacity(best.len());
        for (req, (cand, clear)) in self.requests.iter().zip(best) {
            let (w, up, _) = req.size();
            let base = Point::new(cand.r.x0 + (w - SLANT * req.h) / 2.0, cand.r.y0 + up);
            req.label.draw(g, base, req.h, Anchor::Middle);
            for (k, line) in req.more.iter().enumerate() {
                line.draw(g, base + Vec2::new(0.0, (k + 1) as f64 * LINE_PITCH * req.h), req.h, Anchor::Middle);
            }
            if let Some((a, b)) = req.drawn_leader(&cand) {
                g.writing_line(a, b, THIN);
            }
            placed.push(clear);
        }
        placed
    }

    /// One greedy round in `order`: each label's candidate and whether it is clean. A
    /// candidate is free when it is free against the drawing (its verdict, remembered) and
    /// against the labels this round has placed.
    fn attempt(&self, drawn: &Obstacles, spots: &mut [Spots], order: &[usize], bounds: Rect) -> Vec<(Candidate, bool)> {
        let mut placed = Obstacles::empty_over(drawn.extent().map_or(bounds, |e| e.union(bounds)));
        let none = Candidate { r: Rect::ZERO, anchor: Point::ZERO, leader: None, cost: 0.0 };
        let mut out = vec![(none, false); self.requests.len()];
        for &i in order {
            let s = &mut spots[i];
            let first = |s: &mut Spots, free: &dyn Fn(&Candidate, &mut Verdict) -> bool| {
                (0..).map_while(|k| s.get(k).map(|(c, v)| free(c, v).then(|| c.clone()))).flatten().next()
            };
            // A leader may cross thin lines (out of a fan of links) when no label spot can be
            // reached without: a free box comes first, a clean leader second.
            let best = first(s, &|c, v| v.is_free(c, drawn) && c.is_free(&placed))
                .or_else(|| first(s, &|c, v| v.box_is_free(c, drawn) && c.box_is_free(&placed)));
            let (cand, clear) = match best {
                Some(c) => (c, true),
                None => (least_bad(&s.all(), [drawn, &placed], &self.requests[i], bounds), false),
            };
            // Position numbers (rank 2) are set apart from the next label by more than the
            // clearance: two numbers 0.5 mm apart read as one ("0≡17 16").
            let gap = if self.requests[i].rank >= NUMBERS_RANK { LABEL_GAP } else { 0.0 };
            placed.add(Piece::TextBox(cand.r.inflate(gap, 0.0)), usize::MAX);
            if let Some((a, b)) = self.requests[i].drawn_leader(&cand) {
                placed.add(Piece::Segment(a, b), usize::MAX);
            }
            out[i] = (cand, clear);
        }
        out
    }
}

/// How many of a label's spots around its first anchor are free against the drawing alone
/// (further anchors are a fallback, not a reason to place it later).
fn free_near_first(spots: &mut Spots, req: &Request, drawn: &Obstacles) -> usize {
    (0..)
        .map_while(|k| spots.get(k).map(|(c, v)| c.anchor == req.anchor && v.is_free(c, drawn)))
        .filter(|&free| free)
        .take(CONSTRAINED)
        .count()
}

/// A label with at least this many free spots is not constrained (for the order).
const CONSTRAINED: usize = 8;

/// How far beyond its bounds and anchors a label's box (with its clearance) or leader may
/// reach, mm, with room to spare.
const REACH: f64 = 1.0 + CLEAR + LEADER_GAP;

/// Rounds of moving unplaced labels to the front.
const REPAIR_ROUNDS: usize = 3;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::layout;
    use crate::drawing::scene::{Item, Text};
    use crate::num::math::{self, Norm};

    /// A label asked for inside a ring of discs (rollers round a profile) is placed outside
    /// every disc, though no stroke bounds them.
    /// The layout measure of a 100 × 100 mm scene of the one group `g` finds nothing.
    fn assert_clean(g: Group) {
        let l = layout::measure(&layout::tests::scene(g.items));
        assert!(l.is_clean(), "{l:?}");
    }

    #[test]
    fn labels_keep_out_of_the_discs_they_are_given() {
        let region = Rect::new(0.0, 0.0, 100.0, 100.0);
        let mut g = Group::new("g", region);
        let mut labels = Labels::new();
        let discs: Vec<(Point, f64)> =
            (0..6).map(|k| (Point::new(50.0, 50.0) + math::from_angle(k as f64) * 6.0, 7.0)).collect();
        for &(c, r) in &discs {
            labels.keep_out(c, r);
        }
        labels.add_text(Point::new(50.0, 50.0), Vec2::ZERO, "12", 2.5);
        assert_eq!(labels.place(&mut g, region), vec![true]);
        let text = g.texts().next().unwrap().bbox();
        for (c, r) in discs {
            let nearest = Point::new(c.x.clamp(text.x0, text.x1), c.y.clamp(text.y0, text.y1));
            assert!((nearest - c).norm() >= r, "the label {text:?} enters the disc at {c:?}");
        }
    }

    /// A line's name stands off on a leader that starts on the line itself (not short of
    /// it) and ends on the name's box, the line not counted as crossed.
    #[test]
    fn a_lines_name_has_a_leader_from_the_line() {
        let region = Rect::new(0.0, 0.0, 100.0, 100.0);
        let mut g = Group::new("g", region);
        let on = Point::new(50.0, 50.0);
        g.line(Point::new(10.0, 50.0), Point::new(90.0, 50.0), crate::drawing::scene::MAIN);
        let mut labels = Labels::new();
        labels.add_line_name(on, Vec2::new(0.0, -1.0), LabelText::new("profile", ""), 2.5, 0);
        assert_eq!(labels.place(&mut g, region), vec![true]);
        let text = g.texts().next().unwrap().bbox();
        let leader = g.items.last().and_then(|i| match i {
            Item::Path { path, .. } => Some((path.start, path.end())),
            _ => None,
        });
        let (a, b) = leader.expect("a leader");
        assert!((a - on).norm() < 1e-9, "the leader starts at {a:?}, off the line");
        assert!(text.inflate(0.6, 0.6).contains(b) && text.y1 < on.y, "{b:?} {text:?}");
        assert!((b - a).norm() >= LEADER_FROM - 1e-9);
    }

    /// A label with further spots is set beside a further one, without a leader, when the
    /// first is walled in for a leader's length round (an arrow's name beside its tip rather
    /// than off on a long leader from its middle).
    #[test]
    fn a_label_walled_in_at_its_first_spot_goes_to_a_further_one() {
        let region = Rect::new(0.0, 0.0, 100.0, 100.0);
        let (first, further) = (Point::new(30.0, 50.0), Point::new(70.0, 50.0));
        for with_further in [false, true] {
            let mut g = Group::new("g", region);
            // Circles round the first spot, 2 mm apart out to 12 mm: no box fits near it.
            for k in 1..=6 {
                g.circle(first, 2.0 * k as f64, THIN);
            }
            let mut labels = Labels::new();
            let label = LabelText::new("P", "M4");
            if with_further {
                labels.add_at_any(&[(first, Vec2::new(0.0, -1.0)), (further, Vec2::new(0.0, -1.0))], label, 3.5);
            } else {
                labels.add(first, Vec2::new(0.0, -1.0), label, 3.5);
            }
            assert_eq!(labels.place(&mut g, region), vec![true]);
            let text = g.texts().next().unwrap().bbox();
            let near_further = (text.center() - further).norm() < 8.0;
            assert_eq!(near_further, with_further, "{text:?}");
            let leaders = g.items.iter().filter(|i| matches!(i, Item::Path { .. })).count();
            assert_eq!(leaders, if with_further { 0 } else { 1 }, "a leader only from the walled-in spot");
        }
    }

    /// Position numbers on neighbouring points stand a space apart, not 0.25 mm: "17" and
    /// "16" side by side must not read as "17 16" run together.
    #[test]
    fn position_numbers_keep_a_space_between_them() {
        let region = Rect::new(0.0, 0.0, 100.0, 100.0);
        // The second point at every distance from 1 to 6 mm from the first.
        for k in 0..=50 {
            let mut g = Group::new("g", region);
            // Lines under and over the anchors (and 2 mm strips beyond them) keep both
            // numbers in one row, side by side (a row [`CLEAR`] from each line).
            for y in [41.5, 43.5, 45.5, 51.0, 53.0, 55.0] {
                g.line(Point::new(10.0, y), Point::new(90.0, y), THIN);
            }
            let mut labels = Labels::new();
            let second = 51.0 + 0.1 * k as f64;
            labels.add_text_ranked(Point::new(50.0, 50.0), Vec2::new(0.0, -1.0), "17", 2.5, NUMBERS_RANK);
            labels.add_text_ranked(Point::new(second, 50.0), Vec2::new(0.0, -1.0), "16", 2.5, NUMBERS_RANK);
            assert_eq!(labels.place(&mut g, region), vec![true, true], "at {second}");
            let boxes: Vec<Rect> = g.texts().map(Text::bbox).collect();
            let (a, b) = (boxes[0], boxes[1]);
            assert!(a.y1 <= 50.5 && a.y0 >= 45.5 && b.y1 <= 50.5 && b.y0 >= 45.5, "at {second}: {a:?} {b:?}");
            let apart = (b.x0 - a.x1).max(a.x0 - b.x1);
            assert!(apart >= LABEL_GAP, "at {second}: {apart} mm between {a:?} and {b:?}");
        }
    }

    /// A stacked label is placed by the box of all its lines: between two lines 8 mm apart
    /// where one line of 3.5 mm letters would fit but two do not, it goes elsewhere, and
    /// nothing crosses any of its lines; the lines stand in order, one centre.
    #[test]
    fn a_stacked_label_keeps_every_line_clear() {
        let region = Rect::new(0.0, 0.0, 100.0, 100.0);
        let mut g = Group::new("g", region);
        for y in [46.0, 54.0] {
            g.line(Point::new(0.0, y), Point::new(100.0, y), THIN);
        }
        let mut labels = Labels::new();
        let lines = ["p=b=s3=".to_string(), "c=s4=s5".to_string()];
        labels.add_text_lines(Point::new(50.0, 50.0), Vec2::new(1.0, 0.0), &lines, 3.5);
        labels.place(&mut g, region);
        let texts: Vec<&Text> = g.texts().collect();
        assert_eq!(texts.iter().map(|t| t.text.as_str()).collect::<Vec<_>>(), lines);
        let (a, b) = (texts[0].bbox(), texts[1].bbox());
        assert!(b.y0 >= a.y1 - 1.0 && (a.center().x - b.center().x).abs() < 1e-9, "{a:?} {b:?}");
        assert_clean(g);
    }

    /// A leader stops short of its label's letters: a line touching the letters reads as
    /// part of them ("α = 45°" with a stroke into the 4).
    #[test]
    fn a_leader_stops_short_of_its_label() {
        let region = Rect::new(0.0, 0.0, 100.0, 100.0);
        let mut g = Group::new("g", region);
        let c = Point::new(50.0, 50.0);
        // A disc kept clear round the anchor puts the label beyond the leader's distance.
        let mut labels = Labels::new();
        labels.keep_out(c, 8.0);
        labels.add_text(c, Vec2::new(0.0, 1.0), "45,00°", 3.5);
        assert_eq!(labels.place(&mut g, region), vec![true]);
        let text = g.texts().next().unwrap().bbox();
        let end = g
            .items
            .iter()
            .find_map(|i| match i {
                Item::Path { path, .. } => Some(path.end()),
                _ => None,
            })
            .expect("a leader");
        let gap = (Point::new(end.x.clamp(text.x0, text.x1), end.y.clamp(text.y0, text.y1)) - end).norm();
        assert!(gap >= 0.4, "the leader ends {gap} mm from {text:?}");
    }

    #[test]
    fn labels_keep_off_lines_crossing_at_their_anchor_and_off_each_other() {
        let region = Rect::new(0.0, 0.0, 100.0, 100.0);
        let mut g = Group::new("g", region);
        let c = Point::new(50.0, 50.0);
        // Eight lines radiating from the anchor leave only narrow sectors.
        for k in 0..8 {
            let d = math::from_angle(k as f64 * std::f64::consts::FRAC_PI_4 + 0.2) * 40.0;
            g.line(c, c + d, THIN);
        }
        let mut labels = Labels::new();
        for name in ["A", "B", "C", "S", "D"] {
            labels.add(c, Vec2::new(1.0, -1.0), LabelText::new(name, "2"), 5.0);
        }
        let placed = labels.place(&mut g, region);
        assert!(placed.iter().all(|&clear| clear), "{placed:?}");
        assert_clean(g);
    }
}
