//! A force polygon's short sides enlarged: where gravity and inertia forces of a few tens of
//! newtons stand between reactions of thousands, their sides at the polygon's μ_P are
//! fractions of a millimetre and their labels knot at one vertex. Each run of consecutive
//! sides shorter than [`SIDE_MIN`] is ringed on the polygon and drawn again beside it at its
//! own round μ_P (a detail view, GOST 2.305's "extension element"), labelled there only —
//! in the room the cell already leaves the polygon (under it beside a tall group drawing,
//! or beside it), else in a cell grown for them where the cells still pack, else each in a
//! cell of its own packed wherever the force cells leave room (the caller decides which
//! polygons may do which, [`Enlarge`]). A run with no room at least [`ENLARGED_MIN`] times
//! larger keeps its labels on the polygon.

use super::ForcesInput;
use super::legend::{decimals_of, force_label, scale_item, value_item};
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, THIN, VECTOR, points_bbox};
use crate::drawing::symbols::vector;
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::lever::kinetostatics::Polygon;
use crate::num::math::Norm;
use crate::num::tol;
use crate::sheets::lever::labels::free_detail_letters;
use kurbo::{Point, Rect, Vec2};

/// A labelled side shorter than this on paper is drawn again enlarged, mm: a side a ruler
/// measures to 2 % and that holds its 3.5 mm label beside it.
pub const SIDE_MIN: f64 = 5.0;
/// The enlarged run's longer side at most, mm.
pub(super) const INSET_BOX: f64 = 40.0;
/// The same where the cells cannot pack a polygon's enlargements at [`INSET_BOX`] at any
/// size tried: a run enlarged in a smaller slot reads better than one left knotted on its
/// polygon (over the catalogue, sheets with short sides labelled on a polygon 27 → 1).
pub(super) const INSET_BOX_CRAMPED: f64 = 25.0;
/// An enlargement less than this many times the polygon's scale is not worth its room.
const ENLARGED_MIN: f64 = 2.0;
/// A slot narrower than this cannot hold an enlargement's title, mm ("K (μP = 12,5 N/mm)"
/// is 37 mm; at 45 a polygon 18 mm wide in a 61 mm room, task 6 variant 7's II(4,5), kept
/// R₀₅ 0.3 mm long on it).
const SLOT_MIN_W: f64 = 40.0;
/// Room round an enlarged run for its labels, and for its title above, mm.
const PAD: f64 = 9.0;
const TITLE: f64 = 6.0;
/// From an enlargement's title's baseline down to its drawing's top, mm.
const TITLE_GAP: f64 = 4.0;
/// An enlargement's title keeps this far inside its slot's sides where it can, mm: two
/// titles side by side 3 mm apart ran together ("L (μP = 6 N/mm)  T (μP = 1,25 N/mm)").
const TITLE_SIDE: f64 = 2.5;
/// The neighbouring long sides' stubs in the enlargement, mm.
const STUB: f64 = 8.0;
/// The ring round a run on the polygon: this much beyond its vertices, mm.
const RING_PAD: f64 = 3.0;

/// One run of short sides: its terms (indices into the polygon's terms, in chain order,
/// wrapping past the last) and its μ_P. Its letter is given when it is drawn, counted
/// across the sheet's polygons (a layout is memoised and drawn once, in cell order).
#[derive(Debug, Clone)]
pub(super) struct Inset {
    pub(super) terms: Vec<usize>,
    pub(super) mu: f64,
    /// The run's vertices' box, N.
    pub(super) world: Rect,
    /// Where it is drawn, relative to the polygon's room's top left, mm.
    pub(super) slot: Rect,
    /// Whether a side is still under [`SIDE_MIN`] at `mu` (it carries its value, and the
    /// drawing keeps [`VALUE_ROOM`] under its title for it).
    pub(super) short: bool,
}

/// Where the polygon and its enlargements go in the polygon's room of a cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Place {
    /// No enlargements: the polygon in the middle of its room.
    None,
    /// The polygon at the top, the enlargements side by side under it.
    Below,
    /// The polygon at the left, the enlargements stacked right of it.
    Beside,
    /// Each enlargement in a cell of its own, packed wherever the force cells leave room
    /// (GOST 2.305 sets an extension element anywhere on the sheet, named by its letter):
    /// where the polygon's cell has no room and cannot grow without overflowing.
    Apart,
}

/// Where a polygon's enlargements may go besides the room its cell leaves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(super) enum Enlarge {
    /// Only in the room the cell leaves.
    InRoom,
    /// In a cell grown for them.
    Grow,
    /// In cells of their own ([`Place::Apart`]).
    Apart,
}

/// Whether term `k`'s side is drawn on the polygon and shorter than [`SIDE_MIN`].
fn short(poly: &Polygon, k: usize, mu_p: f64) -> bool {
    let side = poly.terms[k].force.norm() / mu_p;
    side < SIDE_MIN && poly.terms[k].force.norm() > 0.0
}

/// The runs of short sides of `poly` at `mu_p` (`chain` its vertices from its start), each
/// with its box (N) and its longest side.
pub(super) struct Runs<'a> {
    /// Each run's terms, its vertices' box, its longest and its shortest side, N.
    runs: Vec<(Vec<usize>, Rect, f64, f64)>,
    mu_p: f64,
    /// The enlarged run's longer side at most, mm.
    inset_box: f64,
    /// An enlargement's title's width at its μ_P ([`title_width`]), mm: a cell of its own
    /// holds it [`TITLE_SIDE`] inside each side.
    title_w: &'a dyn Fn(f64) -> f64,
}

impl<'a> Runs<'a> {
    pub(super) fn of(
        poly: &Polygon,
        chain: &[Vec2],
        (mu_p, inset_box): (f64, f64),
        title_w: &'a dyn Fn(f64) -> f64,
    ) -> Runs<'a> {
        let n = poly.terms.len();
        let runs = runs(poly, mu_p)
            .into_iter()
            .map(|terms| {
                let pts: Vec<Point> = run_points(chain, &terms, n).iter().map(|v| v.to_point()).collect();
                let world = points_bbox(&pts);
                let sides = || terms.iter().map(|&k| poly.terms[k].force.norm()).filter(|&f| f > 0.0);
                let (longest, shortest) = (sides().fold(0.0, f64::max), sides().fold(f64::INFINITY, f64::min));
                (terms, world, longest, shortest)
            })
            .collect();
        Runs { runs, mu_p, inset_box, title_w }
    }

    pub(super) fn is_empty(&self) -> bool {
        self.runs.is_empty()
    }

    /// The room `(w, h)` that holds the polygon (`poly` its size with its label room) and
    /// the enlargements placed `place`, from the room `(w, h)` the cell leaves it.
    pub(super) fn grown(&self, place: Place, (w, h): (f64, f64), poly: (f64, f64), titled: bool) -> (f64, f64) {
        let (slot_w, slot_h) = self.slot(titled);
        let n = self.runs.len() as f64;
        match place {
            Place::None | Place::Apart => (w, h),
            Place::Below => (w.max(n * slot_w), h.max(poly.1 + slot_h)),
            Place::Beside => (w.max(poly.0 + slot_w), h.max(n * slot_h)),
        }
    }

    /// An enlargement's slot at its full size, mm: its drawing's box with room for its
    /// labels and title.
    fn slot(&self, titled: bool) -> (f64, f64) {
        // As wide as a title of a four-character μP ("1,25") too, where the titles are
        // kept at 3.5 mm (`titled`).
        let title = if titled { (self.title_w)(1.25) + 2.0 * TITLE_SIDE } else { 0.0 };
        ((self.inset_box + 2.0 * PAD).max(title), self.inset_box + 2.0 * PAD + TITLE)
    }

    /// Each run enlarged in a slot of `room` left by the polygon (`poly` its size) placed
    /// `place`: `None` unless every run gets a slot that enlarges it [`ENLARGED_MIN`] times
    /// and, where `titled`, holds its title in 3.5 mm lettering.
    pub(super) fn placed(&self, place: Place, room: (f64, f64), poly: (f64, f64), titled: bool) -> Option<Vec<Inset>> {
        let count = self.runs.len() as f64;
        let (w, h) = room;
        let slot = |i: usize| {
            let i = i as f64;
            match place {
                Place::Below => Rect::new(w * i / count, poly.1, w * (i + 1.0) / count, h),
                _ => Rect::new(poly.0, h * i / count, w, h * (i + 1.0) / count),
            }
        };
        (place != Place::None && place != Place::Apart).then_some(())?;
        self.in_slots(&slot, titled)
    }

    /// Each run enlarged in a cell of its own ([`Place::Apart`]), its slot from the cell's
    /// top left.
    pub(super) fn apart(&self) -> Option<Vec<Inset>> {
        let (w, h) = self.slot(false);
        // Each cell is made as wide as its title below.
        let full = self.in_slots(&|_| Rect::new(0.0, 0.0, w, h), false)?;
        // Each cell only as large as its drawing at that μ_P: a run of two sides of a few
        // hundred newtons left most of its full slot empty, and the smaller cells pack where
        // the full ones found no room (task 1 variant 1's II(2,3) kept Rᵗ₁₂ and G₂ 1.6 mm long
        // on its polygon).
        Some(
            full.into_iter()
                .map(|inset| Inset { slot: tight_slot(&inset, (self.title_w)(inset.mu)), ..inset })
                .collect(),
        )
    }

    /// Each run enlarged in its slot `slot(i)`: `None` unless every run gets one that
    /// enlarges it [`ENLARGED_MIN`] times and, where `titled`, holds its title.
    fn in_slots(&self, slot: &impl Fn(usize) -> Rect, titled: bool) -> Option<Vec<Inset>> {
        (!self.runs.is_empty()).then_some(())?;
        self.runs
            .iter()
            .enumerate()
            .map(|(i, (terms, world, longest, shortest))| {
                let slot = slot(i);
                let (w, h) = (slot.width() - 2.0 * PAD, slot.height() - 2.0 * PAD - TITLE);
                if slot.width() < SLOT_MIN_W || w <= 0.0 || h <= 0.0 {
                    return None;
                }
                let need = (world.width() / w).max(world.height() / h).max(longest / self.inset_box);
                let mu = scale::plan_round_up(need);
                // A slot that enlarges the run and still leaves every side too short to
                // measure, where a full one would not, moves the knot instead of undoing it
                // (task 8 variant 26's II(2,3): L squeezed under its polygon at 75 N/mm, its
                // longest side 2.7 mm, G₃ named on a 79 mm leader).
                let full = scale::plan_round_up(world.width().max(world.height()).max(*longest) / self.inset_box);
                let measurable = longest / mu >= SIDE_MIN || mu <= full;
                // Its title in 3.5 mm lettering, as every other enlargement's: a narrower
                // slot set it a size smaller beside its neighbour's (the v-compressor's T
                // beside L, a teacher's review).
                let title_fits = !titled || slot.width() >= (self.title_w)(mu) + 2.0 * TITLE_SIDE;
                (mu > 0.0 && mu * ENLARGED_MIN <= self.mu_p && title_fits && measurable).then(|| Inset {
                    terms: terms.clone(),
                    mu,
                    world: *world,
                    slot,
                    short: shortest / mu < SIDE_MIN,
                })
            })
            .collect()
    }
}

/// The slot that holds an enlargement's drawing at its μ_P with room for its labels, its
/// stubs and its title (`title_w` wide, [`TITLE_SIDE`] inside each side, so that two
/// cells side by side keep their titles apart), from its cell's top left.
fn tight_slot(inset: &Inset, title_w: f64) -> Rect {
    let (w, h) = (inset.world.width() / inset.mu, inset.world.height() / inset.mu + value_room(inset));
    Rect::new(0.0, 0.0, (w + 2.0 * PAD).max(SLOT_MIN_W).max(title_w + 2.0 * TITLE_SIDE), h + 2.0 * PAD + TITLE)
}

/// Room between an enlargement's title and its drawing for a short side's value, mm: in a
/// tight cell the value ("Rt03 = 1,050 N") found no room but on a stub under the title
/// (task 15 variant 8).
const VALUE_ROOM: f64 = 4.0;

fn value_room(inset: &Inset) -> f64 {
    if inset.short { VALUE_ROOM } else { 0.0 }
}

/// An enlargement's title at `mu` with its letter `letter`: "K (", then "μP = … N/mm)".
fn title(inp: &ForcesInput, letter: &str, mu: f64) -> (LabelText, LabelText) {
    let mut scale = scale_item(inp, "P", mu, inp.words.common.unit_n_per_mm());
    scale.tail.push(')');
    (LabelText::new(letter, "").with_tail(" ("), scale)
}

/// The width of an enlargement's title at `mu` (3.5 mm lettering), mm, its letter as wide as
/// the widest single capital: its letter is given when it is drawn.
pub(super) fn title_width(inp: &ForcesInput, mu: f64) -> f64 {
    let (name, scale) = title(inp, "W", mu);
    name.width(3.5) + scale.width(3.5)
}

/// The runs of consecutive short sides, each its terms in chain order.
fn runs(poly: &Polygon, mu_p: f64) -> Vec<Vec<usize>> {
    let n = poly.terms.len();
    // Start after a long side, so that a run through the chain's start is one run.
    let Some(long) = (0..n).find(|&k| !short(poly, k, mu_p) && poly.terms[k].force.norm() > 0.0) else {
        return Vec::new();
    };
    let mut runs: Vec<Vec<usize>> = Vec::new();
    let mut current: Vec<usize> = Vec::new();
    for step in 1..=n {
        let k = (long + step) % n;
        let zero = poly.terms[k].force.norm() == 0.0;
        if short(poly, k, mu_p) || (zero && !current.is_empty()) {
            current.push(k);
        } else if !zero {
            runs.extend((!current.is_empty()).then(|| std::mem::take(&mut current)));
        }
    }
    runs.extend((!current.is_empty()).then_some(current));
    // A run of zero forces only draws nothing.
    runs.retain(|r| r.iter().any(|&k| poly.terms[k].force.norm() > 0.0));
    runs
}

/// The vertices of a run: the start of its first side to the end of its last.
fn run_points(chain: &[Vec2], terms: &[usize], n: usize) -> Vec<Vec2> {
    let mut pts = vec![chain[terms[0]]];
    pts.extend(terms.iter().map(|&k| chain[(k + 1) % n.max(1)]));
    pts
}

/// The letters of a sheet's enlargements, in the order its polygons are drawn: the front
/// of the detail letters without those that begin a point's name (or a force's or a
/// moment's symbol) and without the last free one, which the crank's detail takes. Past
/// the list, the first letter numbered on (K2, K3 …): a sheet with that many runs is
/// beyond any the course sets, yet its letters stay distinct.
pub(super) struct Letters {
    free: Vec<String>,
    next: usize,
}

impl Letters {
    pub(super) fn of(inp: &ForcesInput) -> Letters {
        let mut free = free_detail_letters(&inp.m.point_names);
        free.pop();
        Letters { free, next: 0 }
    }

    /// The next `n` letters.
    pub(super) fn take(&mut self, n: usize) -> Vec<String> {
        let first = self.free.first().cloned().unwrap_or_else(|| "K".to_string());
        let beyond = |i: usize| format!("{first}{}", i + 2 - self.free.len());
        let out = (self.next..self.next + n).map(|i| self.free.get(i).cloned().unwrap_or_else(|| beyond(i))).collect();
        self.next += n;
        out
    }
}

/// A polygon's enlargements with the letters the sheet gave them.
#[derive(Clone, Copy)]
pub(super) struct Named<'a> {
    pub(super) insets: &'a [Inset],
    pub(super) letters: &'a [String],
}

/// The side's terms that an inset labels (the polygon leaves them unlabelled).
pub(super) fn labelled_elsewhere(insets: &[Inset], k: usize) -> bool {
    insets.iter().any(|i| i.terms.contains(&k))
}

/// Rings each run on the polygon drawn by `view` and names it with its letter.
pub(super) fn ring(g: &mut Group, labels: &mut Labels, view: &View, chain: &[Vec2], named: Named) {
    let n = chain.len().saturating_sub(1);
    for (inset, letter) in named.insets.iter().zip(named.letters) {
        let pts: Vec<Point> = run_points(chain, &inset.terms, n).iter().map(|&v| view.p(v)).collect();
        let c = pts.iter().fold(Vec2::ZERO, |a, p| a + p.to_vec2()) / pts.len() as f64;
        let r = pts.iter().map(|p| (p.to_vec2() - c).norm()).fold(0.0, f64::max) + RING_PAD;
        let c = c.to_point();
        g.circle(c, r, THIN);
        let top = c + Vec2::new(r * 0.7, -r * 0.7);
        labels.add(top, Vec2::new(1.0, -1.0), LabelText::new(letter, ""), 3.5);
    }
}

/// Draws the enlargements in their slots of the polygon's room `r`, each with its letter
/// and μ_P.
pub(super) fn draw(
    g: &mut Group,
    labels: &mut Labels,
    inp: &ForcesInput,
    poly: &Polygon,
    chain: &[Vec2],
    named: Named,
    r: Rect,
) {
    let n = poly.terms.len();
    for (inset, letter) in named.insets.iter().zip(named.letters) {
        let slot = inset.slot + r.origin().to_vec2();
        // Under its title, not in the middle of a tall slot.
        let drawn_h = inset.world.height() / inset.mu + 2.0 * PAD;
        // Room for a short side's value under the title, where the slot has it to spare.
        let value_room = value_room(inset).min((slot.height() - TITLE - drawn_h).max(0.0));
        let area = Rect::new(
            slot.x0,
            slot.y0 + TITLE + value_room,
            slot.x1,
            slot.y1.min(slot.y0 + TITLE + value_room + drawn_h),
        );
        let view = View::centred(inset.world, area, inset.mu);
        let p = |v: Vec2| view.p(v);
        // The long sides that meet the run, as stubs: where it joins the polygon.
        let (first, last) = (inset.terms[0], inset.terms[inset.terms.len() - 1]);
        let before = poly.terms[(first + n - 1) % n].force;
        let after = poly.terms[(last + 1) % n].force;
        let (start, end) = (p(chain[first]), p(chain[(last + 1) % n]));
        let mut stubs = Vec::new();
        if before.norm() > 0.0 {
            stubs.push((start - view.dir(before).unit() * STUB, start));
        }
        if after.norm() > 0.0 {
            stubs.push((end, end + view.dir(after).unit() * STUB));
        }
        // The title just over the drawing (stubs included) and over its left edge and its
        // labels' room, not at the slot's top left: there "K (μP = …)" stood under the
        // polygon's last labels, nearer the polygon than its own drawing.
        let (title, mu) = title(inp, letter, inset.mu);
        // In GOST 2.304's next smaller size where 3.5 mm lettering is wider than its slot:
        // side by side under a polygon, two titles ran together ("L (μP = 12.5 N/mm)T (…").
        let fits = |h: f64| title.width(h) + mu.width(h) + 2.0 * TITLE_SIDE <= slot.width();
        let h = if fits(3.5) { 3.5 } else { 2.5 };
        let title_w = title.width(h) + mu.width(h);
        let left = area.center().x - inset.world.width() / inset.mu / 2.0 - PAD;
        let top = stubs.iter().flat_map(|&(a, b)| [a.y, b.y]).fold(p(Vec2::new(0.0, inset.world.y1)).y, f64::min);
        let at = Point::new(
            left.min(slot.x1 - TITLE_SIDE - title_w).max(slot.x0 + TITLE_SIDE),
            (top - TITLE_GAP - value_room).max(slot.y0 + 4.0),
        );
        title.draw(g, at, h, Anchor::Start);
        // Set where the title's advance ends: its box's slant would leave a gap after "(".
        mu.draw(g, Point::new(at.x + title.width(h), at.y), h, Anchor::Start);
        // The drawing's labels keep clear of the whole title, the room under its scale's
        // text beside the subscript included.
        for k in 0..=(title_w / 2.0).ceil() as usize {
            labels.keep_out(Point::new(at.x + 2.0 * k as f64, at.y - 1.0), 2.5);
        }
        for (a, b) in stubs {
            g.line(a, b, THIN);
        }
        for &k in &inset.terms {
            let (a, b) = (p(chain[k]), p(chain[(k + 1) % n]));
            if (b - a).norm() < tol::PAPER_INVISIBLE {
                continue;
            }
            vector(g, a, b, VECTOR);
            let t = &poly.terms[k];
            let label = force_label(inp, t.kind, t.on);
            // A side still too short to measure in its enlargement (a force a hundredth of
            // the run's largest: the worked example's Rt12, 0.4 mm in L) carries its value:
            // nothing is left to be read off a side a ruler cannot measure. In 2.5 mm
            // lettering: at 3.5 mm "P_i3 = 52.43 N" found room only over the next
            // enlargement's drawing (the worked example's T beside L).
            let (label, h) = if (b - a).norm() < SIDE_MIN {
                let value = (t.force.norm(), decimals_of(inp, t.kind));
                (value_item(inp, label, value, inp.words.common.unit_n(), false), 2.5)
            } else {
                (label, 3.5)
            };
            labels.add_side((a, b), (b - a).turn_90(), label, h);
        }
    }
}

/// The shortest side the enlargements draw and label, mm.
pub(super) fn shortest_side(poly: &Polygon, insets: &[Inset]) -> Option<f64> {
    insets
        .iter()
        .flat_map(|i| i.terms.iter().map(move |&k| poly.terms[k].force.norm() / i.mu))
        .filter(|&side| side >= tol::PAPER_INVISIBLE)
        .reduce(f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lever::kinetostatics::{Applied, Kind};

    fn polygon(forces: &[(f64, f64)]) -> Polygon {
        let term = |&(x, y): &(f64, f64)| Applied {
            on: 1,
            kind: Kind::Weight,
            at: Vec2::ZERO,
            point: None,
            force: Vec2::new(x, y),
        };
        Polygon { group: None, terms: forces.iter().map(term).collect(), split: 0, inner: None }
    }

    /// At 100 N/mm a side under 500 N is short: the runs are the short sides between long
    /// ones, one run through the chain's start (the last side and the first), a zero force
    /// inside a run kept with it and a run of zero forces alone dropped.
    #[test]
    fn runs_are_the_short_sides_between_long_ones_through_the_chains_start() {
        let p = polygon(&[
            (10.0, 0.0),
            (3000.0, 0.0),
            (0.0, 20.0),
            (0.0, 0.0),
            (0.0, 30.0),
            (0.0, 3000.0),
            (0.0, 0.0),
            (-3000.0, -3050.0),
            (-10.0, 0.0),
        ]);
        assert_eq!(runs(&p, 100.0), vec![vec![2, 3, 4], vec![8, 0]]);
        // At 1 N/mm every side is long: nothing to enlarge.
        assert!(runs(&p, 1.0).is_empty());
    }

    /// Past the free letters an inset is named after the first with a number, "K2", "K3", so
    /// that no two insets of a sheet share a name however many there are.
    #[test]
    fn letters_past_the_free_ones_are_numbered_and_never_repeat() {
        let letters = |free: &[&str]| Letters { free: free.iter().map(|s| s.to_string()).collect(), next: 0 };
        let mut two = letters(&["K", "L"]);
        assert_eq!(two.take(1), ["K"]);
        assert_eq!(two.take(3), ["L", "K2", "K3"]);
        assert_eq!(two.take(1), ["K4"]);
        let mut none = letters(&[]);
        assert_eq!(none.take(2), ["K2", "K3"]);
    }
}
