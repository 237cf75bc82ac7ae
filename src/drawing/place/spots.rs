//! The candidate spots of a label around its anchors, cheapest first: [`DISTANCES`] out in
//! [`DIRECTIONS`] turns from the preferred direction, a further anchor's dearer by a few
//! distance steps, each with its leader when it stands off.

use super::{Candidate, DIRECTIONS, DISTANCES, LEADER_FROM, Request, Verdict};
use crate::num::math::{self, Norm};
use crate::num::tol;
use kurbo::{Point, Rect, Vec2};

/// A label's candidates, cheapest first, each with its verdict against the drawing: made
/// as they are asked for (most labels take one of their first few spots of the 456). Each
/// anchor's spots come in [`SPOTS_CHEAPEST_FIRST`]'s order, its cost raised by the same
/// amount for all of them, so merging the anchors' streams (a tie to the earlier anchor)
/// gives the order a stable sort of all their spots would, without making them all.
pub(super) struct Spots<'a> {
    req: &'a Request,
    bounds: Rect,
    made: Vec<(Candidate, Verdict)>,
    /// One per anchor, the label's own first.
    streams: Vec<Stream>,
    /// A line's name with several further points: the same spots with each further point
    /// costing only [`FURTHER_ANCHOR`] (see [`Spots::along`]).
    along: Option<Box<Spots<'a>>>,
}

/// The spots around one anchor not yet taken: the next of [`SPOTS_CHEAPEST_FIRST`] to try
/// and the cheapest made but not taken (none: all taken).
struct Stream {
    around: Around,
    at: usize,
    head: Option<Candidate>,
    /// The same spot with its other leader, next after the head (see [`Around::spot`]).
    further: Option<Candidate>,
}

impl Stream {
    fn new(req: &Request, bounds: Rect, around: Around) -> Stream {
        let mut s = Stream { around, at: 0, head: None, further: None };
        s.advance(req, bounds);
        s
    }

    /// Makes the next spot inside `bounds` the head.
    fn advance(&mut self, req: &Request, bounds: Rect) {
        if let Some(c) = self.further.take() {
            self.head = Some(c);
            return;
        }
        self.head = loop {
            let Some(&(di, dir)) = SPOTS_CHEAPEST_FIRST.get(self.at) else { break None };
            self.at += 1;
            if let Some((c, further)) = self.around.spot(req, bounds, di, dir) {
                self.further = further;
                break Some(c);
            }
        };
    }
}

impl<'a> Spots<'a> {
    pub(super) fn new(req: &'a Request, bounds: Rect) -> Spots<'a> {
        // A further anchor's spots cost as much as the first's a few distances out, the
        // next's a few more.
        let mut spots = Spots::costing(req, bounds, &req.others[..], |n| n as f64 * FURTHER_ANCHOR);
        let all: Vec<(Point, Vec2)> = req.others.iter().chain(&req.along).copied().collect();
        if req.names_line && all.len() > 1 {
            let along = Spots::costing(req, bounds, &all, |n| n.min(1) as f64 * FURTHER_ANCHOR);
            spots.along = Some(Box::new(along));
        }
        spots
    }

    /// For a line's name with several further points, its spots round every point of the
    /// line, those further ones ([`Request::along`] too) each as dear as the second: a
    /// point far down the list names the line as well as the next. Looked at where the
    /// points first in the list leave the name on a long leader
    /// ([`super::Labels::place_measured`]).
    pub(super) fn along(&mut self) -> Option<&mut Spots<'a>> {
        self.along.as_deref_mut()
    }

    /// The spots round the label's anchor and `others`, the `n`th anchor's raised by
    /// `extra(n)`.
    fn costing(req: &'a Request, bounds: Rect, others: &[(Point, Vec2)], extra: impl Fn(usize) -> f64) -> Spots<'a> {
        let anchors = std::iter::once((req.anchor, req.pref)).chain(others.iter().copied());
        let streams = anchors
            .enumerate()
            .map(|(n, (anchor, pref))| Stream::new(req, bounds, Around::new(req, anchor, pref, extra(n))))
            .collect();
        // Room for every spot of one anchor at once: a constrained label is asked for all of
        // them, and growing the list from 64 as they came copied it three times (2 % of
        // building sheet 1).
        let made = Vec::with_capacity(SPOTS_CHEAPEST_FIRST.len());
        Spots { req, bounds, made, streams, along: None }
    }

    /// Candidate `k` and its verdict, made if need be; none past the last.
    pub(super) fn get(&mut self, k: usize) -> Option<(&Candidate, &mut Verdict)> {
        // One anchor (most labels): its stream's order, no merging to do.
        if let [stream] = &mut self.streams[..] {
            while self.made.len() <= k {
                let c = stream.head.take()?;
                stream.advance(self.req, self.bounds);
                push(&mut self.made, c);
            }
        }
        while self.made.len() <= k {
            let cheapest = self
                .streams
                .iter()
                .enumerate()
                .filter_map(|(i, s)| s.head.as_ref().map(|c| (i, c.cost)))
                .min_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)))?
                .0;
            let stream = &mut self.streams[cheapest];
            let c = stream.head.take()?;
            stream.advance(self.req, self.bounds);
            push(&mut self.made, c);
        }
        self.made.get_mut(k).map(|(c, v)| (&*c, v))
    }

    /// Candidate `k` and its verdict, as [`Spots::get`], while its box is one of the first
    /// `boxes`.
    pub(super) fn near(&mut self, k: usize, boxes: usize) -> Option<(&Candidate, &mut Verdict)> {
        self.get(k).filter(|(c, _)| c.nth < boxes)
    }

    /// Every candidate.
    pub(super) fn all(&mut self) -> Vec<Candidate> {
        while self.get(self.made.len()).is_some() {}
        self.made.iter().map(|(c, _)| c.clone()).collect()
    }
}

/// Makes `c` the next candidate of `made`, numbering its box.
fn push(made: &mut Vec<(Candidate, Verdict)>, mut c: Candidate) {
    c.nth = made.last().map_or(0, |(p, _)| p.nth + usize::from(!c.again));
    made.push((c, Verdict::default()));
}

/// Every (distance, direction) index pair, cheapest first and, among equals, in the order
/// of distances then directions: the order a stable sort of one anchor's spots gives,
/// found once rather than for every label.
static SPOTS_CHEAPEST_FIRST: std::sync::LazyLock<Vec<(usize, usize)>> = std::sync::LazyLock::new(|| {
    let mut all: Vec<(usize, usize)> =
        (0..DISTANCES.len()).flat_map(|di| (0..DIRECTIONS).map(move |k| (di, k))).collect();
    all.sort_by(|&(da, ka), &(db, kb)| spot_cost(0.0, da, ka).total_cmp(&spot_cost(0.0, db, kb)));
    all
});

/// The sine and cosine of each direction's turn.
static TURNS: std::sync::LazyLock<[(f64, f64); DIRECTIONS]> =
    std::sync::LazyLock::new(|| std::array::from_fn(|k| math::sin_cos(turn_deg(k).to_radians())));

/// What naming a line at its next anchor costs, against its first (in distance steps).
const FURTHER_ANCHOR: f64 = 4.0;

/// The turn of direction `k` from the preferred one, degrees: 0, +1, −1, +2, −2, … steps,
/// alternate sides of the preferred direction.
fn turn_deg(k: usize) -> f64 {
    let step = k.div_ceil(2) as f64 * if k % 2 == 1 { 1.0 } else { -1.0 };
    step * 360.0 / DIRECTIONS as f64
}

/// A spot's cost: its distance step and its turn, raised by `extra`.
fn spot_cost(extra: f64, di: usize, k: usize) -> f64 {
    extra + di as f64 * 1.0 + turn_deg(k).abs() / 45.0 * 0.8
}

/// The spots around one anchor of a label.
struct Around {
    anchor: Point,
    /// The preferred direction, a unit vector.
    base: Vec2,
    /// The label's box: width and height.
    w: f64,
    ht: f64,
    /// Added to each spot's cost.
    extra: f64,
}

impl Around {
    fn new(req: &Request, anchor: Point, pref: Vec2, extra: f64) -> Around {
        let (w, up, down) = req.size();
        let base = if pref.norm() > tol::PAPER { pref.unit() } else { Vec2::new(1.0, -1.0).unit() };
        Around { anchor, base, w, ht: up + down, extra }
    }

    /// The candidate box at distance `DISTANCES[di]` in direction `k`, if it is inside
    /// `bounds` (and far enough for a line's name), and the same box with another leader: a
    /// short leader that would run level into the box's side goes
    /// to the side's corner farther from the anchor's height, then to the other
    /// ([`LEVEL_SHORT`]). A third try with the level leader itself, as a last resort, left
    /// more leaders across vectors over the catalogue's sheets 1, not fewer (973 against
    /// 968), and 215 dashes.
    fn spot(&self, req: &Request, bounds: Rect, di: usize, k: usize) -> Option<(Candidate, Option<Candidate>)> {
        let dist = DISTANCES[di];
        if req.names_line && dist < LEADER_FROM {
            return None;
        }
        let (w, ht) = (self.w, self.ht);
        let (sin, cos) = TURNS[k];
        // As math::rotate(base, turn), its sine and cosine found once.
        let d = Vec2::new(cos * self.base.x - sin * self.base.y, sin * self.base.x + cos * self.base.y);
        // The box's nearest point stands `dist` from the anchor along `d` (a superellipse
        // around the anchor: boxes beside, above and diagonal all keep the gap).
        let centre = self.anchor + Vec2::new(d.x * (w / 2.0 + dist), d.y * (ht / 2.0 + dist));
        let r = Rect::new(centre.x - w / 2.0, centre.y - ht / 2.0, centre.x + w / 2.0, centre.y + ht / 2.0);
        if !math::rect_inside(bounds, r) {
            return None;
        }
        let gap = req.leader_gap();
        let ends = (dist >= LEADER_FROM).then(|| leader_ends(self.anchor, r, gap));
        let leader = ends.as_ref().map(|e| e.0);
        // A direction's spots share a slot of hints (a direction past the slots would have
        // none: the answers are the same).
        const _: () = assert!(DIRECTIONS <= crate::drawing::obstacles::SLOTS && DIRECTIONS <= 256);
        let dir = k as u8;
        let cost = spot_cost(self.extra, di, k);
        let c = Candidate {
            r,
            anchor: self.anchor,
            leader,
            cost,
            breaks: false,
            dir,
            states_value: req.states_value,
            apart_from_taller: req.apart_from_taller,
            h: req.h,
            again: false,
            nth: 0,
        };
        let further = ends.and_then(|e| e.1).map(|l| Candidate { leader: Some(l), again: true, ..c.clone() });
        Some((c, further))
    }
}

/// A label's leader from `gap` off the anchor to [`LEADER_SHORT`] short of the nearest point
/// of the label's box `r` (a leader ending on the box's edge touches the letters' tops),
/// and no other; or where that one is short and runs level into the box's side (the anchor
/// at the height of the box), leaders to the side's two corners instead, the one farther
/// from the anchor's height first.
pub(super) fn leader_ends(anchor: Point, r: Rect, gap: f64) -> ((Point, Point), Option<(Point, Point)>) {
    let end = Point::new(anchor.x.clamp(r.x0, r.x1), anchor.y.clamp(r.y0, r.y1));
    let level = anchor.y > r.y0 && anchor.y < r.y1;
    if !level || (end - anchor).norm() >= LEVEL_SHORT + gap + LEADER_SHORT {
        return (leader_to(anchor, end, gap), None);
    }
    let (far, near) = if anchor.y - r.y0 > r.y1 - anchor.y { (r.y0, r.y1) } else { (r.y1, r.y0) };
    // It stops short of the corner along both sides (a slanted leader stopped short along
    // itself alone ends closer than that to the letters' side).
    let corner = |y: f64| {
        let c = Point::new(end.x, y);
        let out = Vec2::new((c.x - r.center().x).signum(), (c.y - r.center().y).signum()) * LEADER_SHORT;
        let d = c + out - anchor;
        (anchor + d.unit() * gap.min(d.norm() / 2.0), c + out)
    };
    (corner(far), Some(corner(near)))
}

/// A leader from `gap` off `anchor` to [`LEADER_SHORT`] short of `end`.
fn leader_to(anchor: Point, end: Point, gap: f64) -> (Point, Point) {
    let d = end - anchor;
    let start = anchor + d.unit() * gap.min(d.norm() / 2.0);
    (start, end - d.unit() * LEADER_SHORT.min(d.norm() / 4.0))
}

/// A leader shorter than this as drawn, mm, running level into its label's side reads as a
/// dash or a minus in the text («—s₂», «r_b1 −», a teacher's marks): it meets a corner,
/// slanted.
const LEVEL_SHORT: f64 = 8.0;

/// How far a leader stops short of its label's box, mm.
const LEADER_SHORT: f64 = 0.5;
