//! An enlarged detail of a crank too small on paper for its position numbers (GOST 2.305's
//! detail, "выносной элемент"): beside the mechanism, at a GOST scale of its own, the crank's
//! circle with the pin at every position and its number, the assigned position's crank thick
//! with its letters and ω₁; in the mechanism the crank ringed by a thin circle and named by
//! the detail's letter. Round a crank a few mm across the numbers, O, A and ω₁ crowd onto the
//! rods' lines; the detail gives them the room a teacher would.

use super::{JOINT_R, MechanismView, SENSE_R, mu_l_text, sense_arrow, split_name};
use crate::drawing::obstacles::{Obstacles, Piece};
use crate::drawing::phrases;
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, MAIN, THIN};
use crate::drawing::symbols::{frame_pivot, turn_arrow_reach};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::lever::linkage::{Mechanism, PointId};
use crate::num::math::Norm;
use crate::sheets::lever::labels::{LeverWords, free_detail_letters};
use kurbo::{Point, Rect, Vec2};

/// A crank whose radius on paper is under this gets a detail, mm: its twelve numbers in
/// 2.5 mm lettering would have under 4.7 mm of its circle each, among the rods' lines.
pub(in crate::sheets::lever) const DETAIL_BELOW_MM: f64 = 9.0;
/// The detail's crank radius at least, mm: twelve numbers in 2.5 mm lettering round it
/// with a space between them.
const DETAIL_R_MM: f64 = 15.0;
/// In a free spot of a crowded region the detail's crank may be this short, mm: its numbers
/// in 2.5 mm lettering have under 5 mm each, but no rod's line among them.
const DETAIL_R_LEAST_MM: f64 = 10.0;
/// Room round the detail's circle for the numbers, the letters and ω₁, mm; in a free spot
/// of a region that has none so large, at least the tight margin (a number in 2.5 mm
/// lettering beside its pin, a letter in 5 mm).
const MARGIN: f64 = 11.0;
const TIGHT_MARGIN: f64 = 8.0;
/// The detail's title above its circle's room, mm, and its baseline from the box's top.
const TITLE_H: f64 = 8.0;
const TITLE_BASELINE: f64 = 6.5;
/// The detail's letter and scale in its title (GOST 2.316: a view's letter larger than the
/// numbers beside it), and the space between them, mm.
const LETTER_H: f64 = 5.0;
const SCALE_H: f64 = 3.5;
const LETTER_GAP: f64 = 2.0;
/// Room kept round the detail's title, mm: about a letter.
const TITLE_CLEAR: f64 = 2.5;
/// Between the mechanism's drawing and the detail, mm.
pub(in crate::sheets::lever) const DETAIL_GAP: f64 = 8.0;
/// The marking circle round the crank in the mechanism, past its circle, mm.
const MARK_PAST: f64 = 1.5;
/// The grid a free spot for the detail is sought on, mm.
const FREE_STEP: f64 = 2.0;

/// Where a detail goes and at what scale, chosen with the mechanism's region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::sheets::lever) struct DetailPlace {
    /// The detail's μ_l, m/mm.
    pub mu: f64,
    /// Its box, width and height, mm.
    pub size: (f64, f64),
    /// On the mechanism's left (where its crank is), else on its right.
    pub left: bool,
    /// Where in the mechanism's region it goes.
    pub at: DetailAt,
}

/// Where a crank's detail goes in the mechanism's region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::sheets::lever) enum DetailAt {
    /// Beside the drawing, on the crank's side, in room the region is widened by.
    Beside,
    /// Under the drawing, below the crank, in room the region is heightened by (a drawing
    /// whose band the detail would fill more than half of: a long rod across it leaves no
    /// free box that tall).
    Below,
    /// In a free spot of the region, if the drawing leaves one.
    Inside,
}

/// The detail the crank of `m` needs at the mechanism's `mu_l`: none when its radius on
/// paper is `DETAIL_BELOW_MM` or more — or, where it is `crowded` (its numbers pushed far
/// off by the rods' lines, the letters and ω₁ round it), `CROWDED_R_BELOW_MM` or more.
pub(in crate::sheets::lever) fn detail_place(
    m: &Mechanism,
    mu_l: f64,
    left: bool,
    words: &LeverWords,
    crowded: bool,
) -> Option<DetailPlace> {
    let crank = m.crank().length;
    let below = if crowded { CROWDED_R_BELOW_MM } else { DETAIL_BELOW_MM };
    if crank.is_nan() || crank <= 0.0 || crank / mu_l >= below {
        return None;
    }
    // The coarsest GOST scale that draws the crank longer than DETAIL_R_MM (and, for a
    // crowded one, enlarges it), a crowded one at most CROWDED_R_MOST_MM long.
    let least = crank / DETAIL_R_MM;
    let mu = scale::length_scale_below(if crowded { least.min(mu_l) } else { least });
    // A detail no larger than the mechanism's drawing would only repeat it.
    let enlarges = mu < mu_l * scale::EXACT;
    (enlarges && (!crowded || crank / mu <= CROWDED_R_MOST_MM)).then(|| at_scale(m, mu, left, words))
}

/// A crowded crank gets a detail where it is drawn shorter than this, mm (a longer one is
/// crowded by more than its size), and the detail draws it at most this long (a larger
/// one takes room the region has not to spare).
const CROWDED_R_BELOW_MM: f64 = 20.0;
const CROWDED_R_MOST_MM: f64 = 40.0;

/// The detail at `mu`: its box holds the crank's circle with the room round it, and its
/// title above.
fn at_scale(m: &Mechanism, mu: f64, left: bool, words: &LeverWords) -> DetailPlace {
    DetailPlace { mu, size: sized(m, mu, words, MARGIN), left, at: DetailAt::Inside }
}

/// The detail's box at `mu` with `margin` round its crank's circle: width and height, mm.
fn sized(m: &Mechanism, mu: f64, words: &LeverWords, margin: f64) -> (f64, f64) {
    let circle = 2.0 * (m.crank().length / mu + margin);
    let (letter, scale) = title(m, mu, words);
    let title_w = letter.width(LETTER_H) + LETTER_GAP + scale.width(SCALE_H);
    (circle.max(title_w + 2.0), circle + TITLE_H)
}

/// The detail's title: its letter, and its scale "(μ_l = 0.002 m/mm)".
fn title(m: &Mechanism, mu: f64, words: &LeverWords) -> (LabelText, LabelText) {
    let scale = mu_l_text(mu, words);
    let scale = LabelText { main: format!("({}", scale.main), tail: format!("{})", scale.tail), ..scale };
    (LabelText::new(letter(m), ""), scale)
}

/// The detail's letter: the last of the detail letters that begins no point's name (the
/// force polygons' insets take them from the first).
fn letter(m: &Mechanism) -> String {
    free_detail_letters(&m.point_names).pop().unwrap_or_else(|| "I".to_string())
}

impl MechanismView<'_> {
    /// The detail in a free box of the drawing's region nearest the crank, at its scale with
    /// its margin, or with the tight margin, or at the next coarser scale that still draws
    /// the crank `DETAIL_R_LEAST_MM` long and larger than the mechanism does.
    pub(super) fn free_spot(&self, g: &Group, d: &DetailPlace) -> Option<(DetailPlace, Rect)> {
        let coarser = scale::length_scale(d.mu * 1.01);
        // Still finer than the mechanism's: a detail at its scale only repeats it (task 1
        // variant 34's crowded crank was "enlarged" at 1:10 beside its 1:10 drawing).
        let enlarges = coarser < self.view.mu * scale::EXACT;
        let smaller = (enlarges && self.m.crank().length / coarser >= DETAIL_R_LEAST_MM)
            .then(|| at_scale(self.m, coarser, d.left, self.words));
        // Where the box with its full margin is not free, the box with the margin the
        // numbers and letters need at least, before a coarser scale.
        let tight = DetailPlace { size: sized(self.m, d.mu, self.words, TIGHT_MARGIN), ..*d };
        let mut drawn = Obstacles::of_items_within(&g.items, g.region);
        // Its title beside a value's statement would read on as part of it ("W = … = 1 Z").
        for band in phrases::statement_bands(g.texts(), SCALE_H) {
            drawn.add(Piece::Band(band), usize::MAX);
        }
        [Some(*d), Some(tight), smaller]
            .into_iter()
            .flatten()
            .find_map(|d| self.free_box(g.region, &drawn, d.size).map(|r| (d, r)))
    }

    /// A box of `(w, h)` in `region` clear of everything `drawn` there (the header and
    /// legend included), nearest the crank, on a grid of FREE_STEP.
    fn free_box(&self, region: Rect, drawn: &Obstacles, (w, h): (f64, f64)) -> Option<Rect> {
        let band = region.inflate(-2.0, -2.0);
        let pivot = self.view.p(self.k.assigned.state.points[self.m.crank().pivot].p);
        let steps = |from: f64, room: f64| {
            let n = (room / FREE_STEP).floor().max(-1.0) as i64;
            (0..=n).map(move |i| from + FREE_STEP * i as f64)
        };
        let mut best: Option<(f64, Rect)> = None;
        for y0 in steps(band.y0, band.height() - h) {
            for x0 in steps(band.x0, band.width() - w) {
                let r = Rect::new(x0, y0, x0 + w, y0 + h);
                let far = (r.center() - pivot).norm();
                if best.is_none_or(|(least, _)| far < least) && drawn.is_clear(r) {
                    best = Some((far, r));
                }
            }
        }
        best.map(|b| b.1)
    }

    /// The crank's detail in `rect` and its mark in the mechanism.
    pub(super) fn crank_detail(&self, g: &mut Group, labels: &mut Labels, d: &DetailPlace, rect: Rect) {
        let crank = self.m.crank();
        let st = &self.k.assigned.state;
        let pivot = st.points[crank.pivot].p;
        // The mark: a thin circle round the crank, named toward the detail.
        let at = self.view.p(pivot);
        let mark_r = self.view.len(crank.length) + MARK_PAST;
        g.circle(at, mark_r, THIN);
        let centre = Point::new(rect.center().x, rect.y0 + TITLE_H + (rect.height() - TITLE_H) / 2.0);
        let toward = centre - at;
        let up = Vec2::new(toward.x.signum(), -1.0).unit();
        let (letter, scale) = title(self.m, d.mu, self.words);
        labels.add(at + up * mark_r, up, letter.clone(), LETTER_H);
        // The title: the letter and the detail's scale, centred over it.
        let letter_w = letter.width(LETTER_H) + LETTER_GAP;
        let start = centre.x - (letter_w + scale.width(SCALE_H)) / 2.0;
        let title_y = rect.y0 + TITLE_BASELINE;
        letter.draw(g, Point::new(start, title_y), LETTER_H, Anchor::Start);
        scale.draw(g, Point::new(start + letter_w, title_y), SCALE_H, Anchor::Start);
        // A label 0.5 mm after the title read as part of it ("(μ_l = 0,0025 m/mm)ε₂").
        let title_box = Rect::new(start, title_y - LETTER_H, start + letter_w + scale.width(SCALE_H), title_y);
        labels.keep_clear(title_box.inflate(TITLE_CLEAR, TITLE_CLEAR));
        // The detail's view: the crank's pivot at its circle's centre.
        let view = View::new(Point::new(centre.x - pivot.x / d.mu, centre.y + pivot.y / d.mu), d.mu);
        let o = view.p(pivot);
        let r = view.len(crank.length);
        g.circle(o, r, THIN);
        let groups = self.coincident_in(&view);
        for group in &groups {
            g.circle(view.p(self.k.positions[group[0]].state.points[crank.pin].p), JOINT_R * 0.7, THIN);
        }
        // The crank as the assigned position draws it: every arm to a joint, each named.
        let arms = self.crank_points();
        for &id in &arms {
            g.line(o, view.p(st.points[id].p), MAIN);
            g.circle(view.p(st.points[id].p), JOINT_R * 1.3, THIN);
        }
        frame_pivot(g, o, JOINT_R * 1.5);
        let a = view.p(st.points[crank.pin].p);
        self.detail_omega(g, labels, o, a);
        let name = |id| {
            let (main, sub) = split_name(self.m.name(id));
            LabelText::new(main, sub)
        };
        labels.add(o, o - a, name(crank.pivot), 5.0);
        for &id in &arms {
            let at = view.p(st.points[id].p);
            labels.add(at, at - o, name(id), 5.0);
        }
        let h = self.numbers_height(r);
        for group in &groups {
            let pin = view.p(self.k.positions[group[0]].state.points[crank.pin].p);
            labels.add_text_apart(pin, pin - o, &self.joined_label(group), h, 2);
        }
    }

    /// The crank's joints besides its pivot (its pin, and a second arm's where it has one).
    pub(super) fn crank_points(&self) -> Vec<PointId> {
        let crank = self.m.crank();
        let link = &self.m.links[crank.link];
        link.points.iter().copied().filter(|&id| id != crank.pivot && !self.m.is_mass_centre(id)).collect()
    }

    /// ω₁'s arc arrow round the detail's pivot `o`, clear of its crank `o`–`a`: halfway out
    /// to the pin (at least the mechanism's radius), so that the pivot's letter has room
    /// inside it.
    fn detail_omega(&self, g: &mut Group, labels: &mut Labels, o: Point, a: Point) {
        let crank = self.m.crank();
        let w = self.k.assigned.state.links[crank.link].omega;
        if w == 0.0 {
            return;
        }
        let r = (0.5 * (a - o).norm()).max(SENSE_R.0);
        let mut drawn = Obstacles::of_items_within(&g.items, turn_arrow_reach(o, r));
        let along = (a - o).arg().to_degrees();
        let name = LabelText::new("ω", self.m.links[crank.link].number.to_string());
        sense_arrow(g, (&mut drawn, labels), (o, r), along, w > 0.0, name);
    }
}
