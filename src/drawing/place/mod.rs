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
//! gets a short thin leader line. A side's name ([`Labels::add_side`]) prefers a spot that
//! is nearer its own side than any other named one: beside a vertex, the nearest free spot
//! may be beside the neighbouring side, and read as its name. The geometry sits in an R-tree ([`super::obstacles`]).

use super::obstacles::{Obstacles, Piece};
use super::phrases;
use super::scene::{Anchor, Group, THIN};
use super::text::{LabelText, SLANT, SUB};
use crate::num::math::Norm;
use breakable::{LONG_LEADER, on_breakable};
use candidate::{Candidate, Verdict, least_bad};
use crossings::Detour;
use kurbo::{Point, Rect, Vec2};
use layers::{Layers, is_bold};
use lined::unlined;
pub use request::Placed;
use request::Request;
use seen::{first_preferred, seen_spot};
use spots::Spots;

mod breakable;
mod candidate;
mod crossings;
mod layers;
mod lined;
mod make_room;
mod request;
mod seen;
mod sides;
mod spots;
mod untangle;

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
/// A line interrupted for a label stops this far from its box, mm: at [`CLEAR`] the break
/// read, printed, as the line run through the letters (a teacher read a cam profile's
/// «φ_в = 90°» as cut by the follower's axes).
const BREAK_CLEAR: f64 = 1.2;
/// More room kept beside a placed position number for the next label, mm (about a space:
/// two numbers 0.5 mm apart read as one, "0≡17 16"), and the rank from which labels are
/// position numbers.
const LABEL_GAP: f64 = 0.7;
pub const NUMBERS_RANK: u8 = 2;
const DIRECTIONS: usize = 24;
/// Baseline to baseline in a stacked label, in lettering heights.
const LINE_PITCH: f64 = 1.4;

/// Labels waiting for the geometry of their group to be complete.
#[derive(Debug, Default)]
pub struct Labels {
    requests: Vec<Request>,
    /// Discs and boxes no label may enter.
    keep_out: Vec<Piece>,
    /// Room below the bounds (down to this y) for the labels anchored within the given
    /// distance of their bottom (see [`Labels::reach_below`]).
    below: Option<(f64, f64)>,
    /// Lines a leader crosses only where no spot near enough avoids them, as another
    /// label's leader ([`Labels::keep_leaders_off`]).
    walls: Vec<(Point, Point)>,
}

/// The size of a label's box at lettering height `h` (slant and subscript included): width,
/// height above the baseline, depth below it.
pub fn label_size(label: &LabelText, h: f64) -> (f64, f64, f64) {
    let w = label.width(h) + SLANT * h;
    let below = if !label.has_sub() { 0.3 * h } else { 0.3 * h + 0.3 * h * SUB };
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

    /// A label naming the segment a–b (a force polygon's side), beside its middle,
    /// preferably in direction `pref`: nearer to a–b than to any other segment named so in
    /// this batch by 0.5 mm, where a free spot allows (a name on a leader is read along it).
    pub fn add_side(&mut self, (a, b): (Point, Point), pref: Vec2, label: LabelText, h: f64) {
        self.requests.push(Request { side: Some((a, b)), ..Request::new(a.midpoint(b), pref, label, h) });
    }

    /// A label placed after every label of a lower rank.
    pub fn add_ranked(&mut self, anchor: Point, pref: Vec2, label: LabelText, h: f64, rank: u8) {
        self.requests.push(Request { rank, ..Request::new(anchor, pref, label, h) });
    }

    /// One label of several plain lines stacked and centred, the first nearest `pref`'s
    /// side (names of one point too many for one line: "p=b=s3=" over "c=s4=s5").
    pub fn add_text_lines(&mut self, anchor: Point, pref: Vec2, lines: &[String], h: f64) {
        self.add_text_lines_ranked(anchor, pref, lines, h, 0);
    }

    /// As [`Labels::add_text_lines`], placed after every label of a lower rank.
    pub fn add_text_lines_ranked(&mut self, anchor: Point, pref: Vec2, lines: &[String], h: f64, rank: u8) {
        let n = self.requests.len();
        self.add_label_lines(anchor, pref, lines.iter().map(|l| LabelText::new(l, "")).collect(), h);
        if let Some(r) = self.requests.get_mut(n) {
            r.rank = rank;
        }
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

    /// As [`Labels::add_at_any`], placed after every label of a lower rank.
    pub fn add_ranked_at_any(&mut self, spots: &[(Point, Vec2)], label: LabelText, h: f64, rank: u8) {
        self.push_at_any(spots, Request { rank, ..Request::new(Point::ZERO, Vec2::ZERO, label, h) });
    }

    /// As [`Labels::add_at_any`], a label naming the segment a–b (a force's arrow): like a
    /// side's name ([`Labels::add_side`]) it prefers spots nearer its own segment than any
    /// other named one (two arrows from one point, G₂ and P_и2, each read the other's name).
    pub fn add_side_at_any(&mut self, spots: &[(Point, Vec2)], (a, b): (Point, Point), label: LabelText, h: f64) {
        self.push_at_any(spots, Request { side: Some((a, b)), ..Request::new(Point::ZERO, Vec2::ZERO, label, h) });
    }

    /// `req` at the first of `spots`, the rest its further anchors.
    fn push_at_any(&mut self, spots: &[(Point, Vec2)], req: Request) {
        let Some((&(anchor, pref), others)) = spots.split_first() else { return };
        self.requests.push(Request { anchor, pref, others: others.to_vec(), ..req });
    }

    /// As [`Labels::add_ranked_at_any`], a label whose spots lie on a drawn line (an
    /// angle's value on its arc): a leader, where it needs one, starts on the line.
    pub fn add_on_line_at_any(&mut self, spots: &[(Point, Vec2)], label: LabelText, h: f64, rank: u8) {
        self.push_at_any(spots, Request { rank, on_line: true, ..Request::new(Point::ZERO, Vec2::ZERO, label, h) });
    }

    /// A line's name (a profile's, a circle's) with `anchor` on the line: set off on a leader
    /// that reaches the line, so that it cannot be taken for a neighbour's name.
    pub fn add_line_name(&mut self, anchor: Point, pref: Vec2, label: LabelText, h: f64, rank: u8) {
        self.add_line_name_at_any(&[(anchor, pref)], &[], label, h, rank);
    }

    /// A line's name as [`Labels::add_line_name`], with further points of the line (and
    /// their directions) to name it at when the spots near the first are taken, and more,
    /// `along`, where those leave it on a long leader.
    pub fn add_line_name_at_any(
        &mut self,
        spots: &[(Point, Vec2)],
        along: &[(Point, Vec2)],
        label: LabelText,
        h: f64,
        rank: u8,
    ) {
        let req = Request::new(Point::ZERO, Vec2::ZERO, label, h);
        self.push_at_any(spots, Request { rank, names_line: true, along: along.to_vec(), ..req });
    }

    /// A disc (paper mm) every label keeps out of, though nothing drawn bounds it there.
    pub fn keep_out(&mut self, centre: Point, r: f64) {
        self.keep_out.push(Piece::Disc(centre, r));
    }

    /// A box (paper mm) every label and leader keeps out of: room round a title.
    pub fn keep_clear(&mut self, r: Rect) {
        self.keep_out.push(Piece::TextBox(r));
    }

    /// A line (paper mm) that leaders keep off as they keep off each other's: a dimension
    /// line, which a number's leader across reads as its value.
    pub fn keep_leaders_off(&mut self, (a, b): (Point, Point)) {
        self.walls.push((a, b));
    }

    /// Lets a label anchored within `near` mm of the bounds' bottom reach further down, to
    /// `y1` (a plan's cell into the gap over the next row: the letters at a plan's foot,
    /// where a label further up would hang on a long leader across the plan).
    pub fn reach_below(&mut self, y1: f64, near: f64) {
        self.below = Some((y1, near));
    }

    /// A plain text label.
    pub fn add_text(&mut self, anchor: Point, pref: Vec2, text: &str, h: f64) {
        self.add(anchor, pref, LabelText::new(text, ""), h);
    }

    /// A plain text label of a rank (see [`Labels::add_ranked`]).
    /// As [`Labels::add_text_ranked`], the text kept two of its heights off taller texts on
    /// its line: a slider's number a word's space before a point's letter reads as one
    /// designation with it («0 D»: the guide's D₀).
    pub fn add_text_apart(&mut self, anchor: Point, pref: Vec2, text: &str, h: f64, rank: u8) {
        let req = Request::new(anchor, pref, LabelText::new(text, ""), h);
        self.requests.push(Request { rank, apart_from_taller: true, ..req });
    }

    /// How many labels were added (the next one's index in what placing returns).
    pub fn count(&self) -> usize {
        self.requests.len()
    }

    pub fn add_text_ranked(&mut self, anchor: Point, pref: Vec2, text: &str, h: f64, rank: u8) {
        self.add_ranked(anchor, pref, LabelText::new(text, ""), h, rank);
    }

    /// Places every label inside `bounds`, clear of everything `g` holds now, and draws them;
    /// returns whether each found a clean spot (the layout measurement reports those that
    /// did not).
    pub fn place(self, g: &mut Group, bounds: Rect) -> Vec<bool> {
        self.place_measured(g, bounds).into_iter().map(|p| p.clean).collect()
    }

    /// As [`Labels::place`], with how far off each label stands.
    pub fn place_measured(self, g: &mut Group, bounds: Rect) -> Vec<Placed> {
        // Every box tried is inside the bounds and every leader runs from near its anchor
        // to its box: what lies beyond both cannot touch them (a cell's labels need not
        // see the cells drawn before it).
        let own: Vec<Rect> = self.requests.iter().map(|r| self.bounds_of(r, bounds)).collect();
        let outer = own.iter().fold(bounds, |b, o| b.union(*o));
        let reach = self
            .requests
            .iter()
            .flat_map(|r| std::iter::once(r.anchor).chain(r.others.iter().chain(&r.along).map(|o| o.0)));
        let reach = reach.fold(outer, |b, p| b.union_pt(p)).inflate(REACH, REACH);
        let mut drawn = Obstacles::of_items_within(&g.items, reach);
        // The drawing without its breakable lines, where it has any: the same pieces but
        // theirs, taken from `drawn` rather than flattened again.
        let mut hard = (!g.breakable.is_empty()).then(|| drawn.without(|k| g.breakable.binary_search(&k).is_ok()));
        // A value's statement already written keeps a label off its line beside it.
        let bands = statements(g, reach);
        for &piece in self.keep_out.iter().chain(&bands) {
            drawn.add(piece, usize::MAX);
            if let Some(h) = hard.as_mut() {
                h.add(piece, usize::MAX);
            }
        }
        let bold: Vec<bool> = g.items.iter().map(is_bold).collect();
        let layers = Layers { drawn: &drawn, hard: hard.as_ref(), bold: &bold, items: &g.items };
        // What the drawing alone says of each candidate is asked once (see `Verdict`): the
        // order and every round below ask it again and again, and it does not change as
        // labels are placed.
        let mut spots: Vec<Spots> = self.requests.iter().zip(&own).map(|(r, &b)| Spots::new(r, b)).collect();
        // By rank, then most constrained first: the fewest candidates free against the
        // drawing alone.
        let mut order: Vec<usize> = (0..self.requests.len()).collect();
        // Counting stops at a few: beyond that a label is not constrained.
        let free: Vec<usize> =
            (0..self.requests.len()).map(|i| free_near_first(&mut spots[i], &self.requests[i], layers.drawn)).collect();
        order.sort_by_key(|&i| (self.requests[i].rank, free[i]));
        // Leaders seen preferred; where that leaves a label without a clean spot, the
        // rounds again taking each label's first free spot, and the one with fewer left
        // kept: a leader lost in a line is better than a label on a line (a stress cam's
        // r_min, moved to a seen leader, left e = … no spot but across its leader).
        let failures = |placed: &[(Candidate, bool)]| placed.iter().filter(|p| !p.1).count();
        let mut best = self.rounds(layers, &mut spots, order.clone(), outer, true);
        if failures(&best) > 0 {
            let plain = self.rounds(layers, &mut spots, order.clone(), outer, false);
            if failures(&plain) < failures(&best) {
                best = plain;
            }
        }
        // Labels standing on breakable lines take room that others may have needed (a tiny
        // cam's position numbers beside their points left its r_min no clean spot): where
        // that leaves a label without one, the placement without breaking is kept if it
        // leaves fewer.
        if failures(&best) > 0 && layers.hard.is_some() {
            let whole = self.rounds(Layers { hard: None, ..layers }, &mut spots, order, outer, true);
            if failures(&whole) < failures(&best) {
                best = whole;
            }
        }
        self.repair(layers, &mut spots, &mut best, &own);
        let mut placed = Vec::with_capacity(best.len());
        let mut gaps = Vec::new();
        for (req, (cand, clear)) in self.requests.iter().zip(best) {
            let (w, up, _) = req.size();
            let base = Point::new(cand.r.x0 + (w - SLANT * req.h) / 2.0, cand.r.y0 + up);
            req.label.draw(g, base, req.h, Anchor::Middle);
            for (k, line) in req.more.iter().enumerate() {
                line.draw(g, base + Vec2::new(0.0, (k + 1) as f64 * LINE_PITCH * req.h), req.h, Anchor::Middle);
            }
            let leader = req.drawn_leader(&cand);
            if let Some((a, b)) = leader {
                g.leader_line(a, b, THIN);
            }
            if cand.breaks {
                gaps.push(cand.r.inflate(BREAK_CLEAR, BREAK_CLEAR));
            }
            placed.push(Placed { clean: clear, leader: leader.map_or(0.0, |(a, b)| (b - a).norm()), rank: req.rank });
        }
        g.interrupt_breakable(&gaps);
        placed
    }

    /// The bounds of label `r`'s spots: `bounds`, reaching below them where
    /// [`Labels::reach_below`] lets it.
    fn bounds_of(&self, r: &Request, bounds: Rect) -> Rect {
        match self.below {
            Some((y1, near)) if r.anchor.y >= bounds.y1 - near && y1 > bounds.y1 => Rect { y1, ..bounds },
            _ => bounds,
        }
    }

    /// Greedy rounds from `order`: a label left without a clean spot goes first in the next
    /// round (labels placed before it took its spots), up to a few rounds; the best round is
    /// kept.
    fn rounds(
        &self,
        layers: Layers,
        spots: &mut [Spots],
        mut order: Vec<usize>,
        bounds: Rect,
        prefer_seen: bool,
    ) -> Vec<(Candidate, bool)> {
        let mut best = self.attempt(layers, spots, &order, bounds, prefer_seen);
        for _ in 0..REPAIR_ROUNDS {
            let failed: Vec<usize> = order.iter().copied().filter(|&i| !best[i].1).collect();
            if failed.is_empty() {
                break;
            }
            order.retain(|i| !failed.contains(i));
            order.splice(0..0, failed);
            let next = self.attempt(layers, spots, &order, bounds, prefer_seen);
            if next.iter().filter(|p| !p.1).count() < best.iter().filter(|p| !p.1).count() {
                best = next;
            }
        }
        best
    }

    /// One greedy round in `order`: each label's candidate and whether it is clean. A
    /// candidate is free when it is free against the drawing (its verdict, remembered) and
    /// against the labels this round has placed.
    /// With `prefer_seen`, a spot whose leader is seen goes before one lost in a line
    /// ([`seen_spot`]).
    fn attempt(
        &self,
        layers: Layers,
        spots: &mut [Spots],
        order: &[usize],
        bounds: Rect,
        prefer_seen: bool,
    ) -> Vec<(Candidate, bool)> {
        let drawn = layers.drawn;
        let mut placed = Obstacles::empty_over(drawn.extent().map_or(bounds, |e| e.union(bounds)));
        let mut out = vec![(Candidate::default(), false); self.requests.len()];
        for &i in order {
            let s = &mut spots[i];
            let first = |s: &mut Spots, free: &dyn Fn(&Candidate, &mut Verdict) -> bool| {
                (0..).map_while(|k| s.get(k).map(|(c, v)| free(c, v).then(|| c.clone()))).flatten().next()
            };
            // A leader may cross thin lines (out of a fan of links) when no label spot can be
            // reached without: a free box comes first, a clean leader second. A side's name
            // takes a spot that reads as another side's only when none that does not is
            // free a few steps further.
            let free = |c: &Candidate, v: &mut Verdict| v.is_free(c, drawn) && c.is_free(&placed);
            let box_free = |c: &Candidate, v: &mut Verdict| v.box_is_free(c, drawn) && c.box_is_free(&placed);
            let choose = |s: &mut Spots| {
                let best = self
                    .unambiguous_spot(i, s, &free)
                    .or_else(|| prefer_seen.then(|| seen_spot(s, &free, drawn)).flatten())
                    .or_else(|| prefer_seen.then(|| seen_spot(s, &box_free, drawn)).flatten())
                    .or_else(|| first(s, &free))
                    .or_else(|| first(s, &box_free));
                // Across lines, but not across another label's leader where a spot little
                // further allows: two leaders crossing read as each other's («3 ≡ 9» over
                // «4 ≡ 8»'s on a slider).
                let crosses = |c: &Candidate| crossings::crosses_walls(&self.walls, c);
                let off = Detour { crosses_wall: &crosses, steps: crossings::PER_CROSSING, near: crossings::NEAR };
                let best = best.map(|c| crossings::off_leaders(s, &box_free, (drawn, &placed), off, c));
                // Then not across a vector or a link either, where a spot near enough allows.
                let across = |c: &Candidate| crosses(c) || layers.crosses_bold(c);
                let (steps, near) = crossings::OFF_BOLD;
                let off = Detour { crosses_wall: &across, steps, near };
                let best = best.map(|c| crossings::off_leaders(s, &box_free, (drawn, &placed), off, c));
                // On a long leader: a nearer spot across a line or two, if it weighs less.
                match best {
                    Some(c) if c.leader_at_least(crossings::LONG) => {
                        let reads = |c: &Candidate, v: &mut Verdict| box_free(c, v) && self.reads_as_own(i, c);
                        let bold = |c: &Candidate| layers.crosses_bold(c);
                        crossings::nearer_across(s, &reads, (drawn, &placed), &bold, c.cost).or(Some(c))
                    }
                    best => best,
                }
            };
            // Just over or under a level line, the label reads as over- or underlined: a
            // spot clear of it instead, on a leader little longer, where one is free.
            let best = choose(s).map(|c| {
                let fits =
                    |c: &Candidate, v: &mut Verdict| free(c, v) && self.reads_as_own(i, c) && v.leader_seen(c, drawn);
                unlined(s, c, &fits, drawn)
            });
            // Far off on a long leader, or nowhere: beside its point on thin lines broken
            // for it, where the drawing has such lines.
            let far = best.as_ref().is_none_or(|c| c.leader_at_least(LONG_LEADER));
            let mut best = match layers.hard {
                Some(hard) if far => on_breakable(s, &self.requests[i], (drawn, hard), &placed).or(best),
                _ => best,
            };
            // A line's name still far off its first points: at any point of its line, where
            // that hangs it on a shorter leader.
            let long = best.as_ref().filter(|c| c.leader_at_least(LONG_LEADER)).map(Candidate::leader_length);
            if let (Some(long), Some(along)) = (long, s.along()) {
                best = choose(along).filter(|o| o.leader_length() < long).or(best);
            }
            let (cand, clear) = match best {
                Some(c) => (c, true),
                None => (least_bad(&s.all(), [drawn, &placed], &self.requests[i], bounds), false),
            };
            for piece in self.pieces(i, &cand) {
                placed.add(piece, usize::MAX);
            }
            out[i] = (cand, clear);
        }
        out
    }
}

/// The level statements of `g` within `reach`, which a label keeps off its line beside
/// ([`Candidate::box_is_free`]).
fn statements(g: &Group, reach: Rect) -> Vec<Piece> {
    phrases::level_statements(g.texts())
        .map(|t| (t.core_box(), t.h))
        .filter(|(b, _)| b.intersect(reach).area() > 0.0)
        .map(|(b, h)| Piece::Statement(b, h))
        .collect()
}

/// How many of a label's cheapest spots are looked at for one beside its point.
pub(super) const NEAR_SPOTS: usize = 6 * DIRECTIONS;

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
mod tests;
