//! Sheet 3's regions, chosen by content: the diagrams' column as wide as its plan, the
//! tables not kept in that column in a strip left of the title block, and the nomogram and
//! the profile arranged where each comes out largest.

use super::{diagrams, pressure_view};
use crate::drawing::frame;
use crate::drawing::scale;
use crate::drawing::table::{self, Table};
use kurbo::{Rect, Vec2};

/// The sheet inside its frame, with a 4 mm margin.
pub const SHEET: Rect = Rect { x0: 24.0, y0: 9.0, x1: 832.0, y1: 585.0 };
/// How wide the diagrams' column may be, mm: at most `left`, its working angle's axis at
/// most `phi` long.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ColumnWidth {
    pub left: f64,
    pub phi: f64,
}

/// The column's widths tried: the usual one, and a wider one (a longer φ axis) for a sheet
/// whose views leave the middle of the sheet empty beside the usual column. A third, 470 mm
/// (φ ≤ 350), won 13 of the catalogue's 523 sheets by at most 0.041 of empty share and none
/// of the fixtures, for a quarter of the variants built: measured, and left out.
pub const COLUMN_WIDTHS: [ColumnWidth; 2] =
    [ColumnWidth { left: 320.0, phi: 240.0 }, ColumnWidth { left: 400.0, phi: 300.0 }];
/// Between regions, mm.
const GAP: f64 = 6.0;
/// Between tables stacked in a region, mm: 3 mm left a table's grid all but touching the
/// next one's title under it.
pub const TABLE_GAP: f64 = 5.0;
/// Room a view needs besides its drawing: its title and its scale above, its margins.
const VIEW_TOP: f64 = 15.0;
const VIEW_BOTTOM: f64 = 3.0;
const VIEW_SIDES: f64 = 8.0;
/// The nomogram's drawing is at least this long on its longer side when the profile can
/// be drawn smaller to allow it, mm.
const NOMOGRAM_MIN_MM: f64 = 130.0;

/// The regions of the sheet and the views' scales, chosen by content.
#[derive(Debug, Clone, Copy)]
pub struct Regions {
    pub diagrams: Rect,
    pub law_tables: Option<Rect>,
    pub tables: Rect,
    pub nomogram: Rect,
    pub profile: Rect,
    pub nomogram_mu: f64,
    pub profile_mu: f64,
    /// The room the other regions leave for the pressure angle's diagram ([`free_room`]).
    pub pressure: Option<Rect>,
}

/// A view's box in metres: its lower and upper corners.
pub type Extent = (Vec2, Vec2);

/// A view as the regions size it: its box in metres; what it draws at a paper distance from
/// a world point (a dimension set so many mm under the point it measures from); and the
/// width its heading (the title and the scale set at the region's top left) takes on paper,
/// mm. The region is at least as wide as the heading: a small drawing under a long title (a
/// nomogram at a coarse scale, its title in Uzbek) would otherwise leave the title sticking
/// out of its region.
#[derive(Debug, Clone)]
pub struct ViewSize {
    pub extent: Extent,
    /// World points with an offset in paper mm (world axes, y up): each point moved by its
    /// offset at the view's scale must be inside the view's box too.
    pub reach: Vec<(Vec2, Vec2)>,
    pub heading_w: f64,
    /// Scaled at the largest GOST 2.302 scale that fits, else a GOST scale coarser (its
    /// labels' room the wider). Both views are length drawings (r_min is read off the
    /// nomogram in mm), so neither takes the plans' or the diagrams' round series.
    pub fine: bool,
}

impl ViewSize {
    /// The box the view shows at `mu`: its extent grown over what it reaches at that scale.
    pub fn at(&self, mu: f64) -> Extent {
        self.reach.iter().fold(self.extent, |(lo, hi), &(p, off)| {
            let q = p + off * mu;
            (Vec2::new(lo.x.min(q.x), lo.y.min(q.y)), Vec2::new(hi.x.max(q.x), hi.y.max(q.y)))
        })
    }

    /// The least μ at which the box [`ViewSize::at`] is at most `room` mm long on paper along
    /// one axis (`coord` picks it): each pair of the box's corners and reached points apart
    /// by d metres and r mm of offset must keep d/μ + r ≤ room. Infinite when no μ does.
    fn least_mu(&self, room: f64, coord: impl Fn(Vec2) -> f64) -> f64 {
        let (lo, hi) = self.extent;
        let mut pts = vec![(coord(lo), 0.0), (coord(hi), 0.0)];
        pts.extend(self.reach.iter().map(|&(p, off)| (coord(p), coord(off))));
        let mut need: f64 = 0.0;
        for &(pa, ra) in &pts {
            for &(pb, rb) in &pts {
                let (d, left) = (pa - pb, room - (ra - rb));
                if d > 0.0 {
                    need = need.max(if left > 0.0 { d / left } else { f64::INFINITY });
                }
            }
        }
        need
    }
}

/// What the regions are chosen for: the views' boxes, the diagrams' plan and the height of
/// the column's texts, the law's tables and the rest.
pub struct Content<'a> {
    pub nomogram: ViewSize,
    pub profile: ViewSize,
    pub plan: &'a diagrams::Plan,
    pub text_h: f64,
    /// The sizes of the law's tables and of the rest (width, height), mm.
    pub law: &'a [Size],
    pub rest: &'a [Size],
}

/// The room the column and the strip leave.
struct Frame {
    left_w: f64,
    column_used: f64,
    right_x: f64,
}

impl Frame {
    fn of(c: &Content) -> Frame {
        let left_w = c.plan.width + 4.0;
        // 4 mm between the diagrams and the notes, 1 mm under the last note: the height of
        // the column's group as `diagrams_group` draws it.
        Frame { left_w, column_used: c.text_h + c.plan.height + 5.0, right_x: SHEET.x0 + left_w + GAP }
    }

    /// The strip for tables of `sizes` left of the title block, as low as fits.
    fn strip(&self, sizes: &[(f64, f64)]) -> Rect {
        let tb = frame::title_block_rect();
        let h = table::flow_height(sizes, tb.x0 - GAP - self.right_x, TABLE_GAP).unwrap_or(SHEET.height() / 2.0);
        Rect::new(self.right_x, SHEET.y1 - h, tb.x0 - GAP, SHEET.y1)
    }

    /// The room for the views above the strip `tables`.
    fn views_above(&self, tables: Rect) -> Rect {
        Rect::new(self.right_x, SHEET.y0, SHEET.x1, tables.y0.min(frame::title_block_rect().y0) - GAP)
    }
}

impl Regions {
    /// Whether the tables fit the regions left for them: the law's each as wide as the
    /// column at most where they go under it, the rest (or all) flowed into the strip.
    pub fn tables_fit(&self, law: &[Size], rest: &[Size]) -> bool {
        let flows =
            |ts: &[Size], r: Rect| table::flow_height(ts, r.width(), TABLE_GAP).is_some_and(|h| h <= r.height());
        match self.law_tables {
            Some(col) => law.iter().all(|s| s.0 <= col.width()) && flows(rest, self.tables),
            None => flows(&[law, rest].concat(), self.tables),
        }
    }

    /// The room each view's labels may take: its region grown right and then down as far
    /// as the sheet goes without meeting another region or the title block (its title and
    /// drawing stay where the region put them). A label wider than the space its drawing
    /// leaves inside a region cut to the drawing — r_min beside a narrow wedge — would
    /// otherwise be set across the lines. `(nomogram, profile)`.
    pub fn label_rooms(&self) -> (Rect, Rect) {
        let tb = frame::title_block_rect();
        let fixed = [Some(self.diagrams), self.law_tables, Some(self.tables), Some(tb), self.pressure];
        let fixed: Vec<Rect> = fixed.into_iter().flatten().collect();
        let with = |other: Rect| fixed.iter().copied().chain([other]).collect::<Vec<_>>();
        (grown(self.nomogram, &with(self.profile)), grown(self.profile, &with(self.nomogram)))
    }
}

/// `r` grown right, then down, within the sheet, to [`GAP`] short of each of `others`
/// that it would meet.
fn grown(r: Rect, others: &[Rect]) -> Rect {
    let meets_across = |o: &Rect, r: Rect| o.y0 < r.y1 + GAP && o.y1 > r.y0 - GAP;
    let x1 = others.iter().filter(|o| o.x0 >= r.x1 && meets_across(o, r)).fold(SHEET.x1, |x, o| x.min(o.x0 - GAP));
    let r = Rect::new(r.x0, r.y0, x1.max(r.x1), r.y1);
    let meets_along = |o: &Rect| o.x0 < r.x1 + GAP && o.x1 > r.x0 - GAP;
    let y1 = others.iter().filter(|o| o.y0 >= r.y1 && meets_along(o)).fold(SHEET.y1, |y, o| y.min(o.y0 - GAP));
    Rect::new(r.x0, r.y0, r.x1, y1.max(r.y1))
}

/// The height the law's tables take under a column `width` wide, with the gap above them,
/// mm: flowed in columns (side by side where the column is wide enough), else stacked.
pub fn law_height(law: &[Size], width: f64) -> f64 {
    let stacked = law.iter().map(|s| s.1 + TABLE_GAP).sum::<f64>();
    table::flow_height(law, width, TABLE_GAP).map_or(stacked, |h| h.min(stacked)) + GAP
}

/// The height the column's diagrams `width` wide (with the column's margins) may take with
/// the law's tables `law` under them, mm.
pub fn diagrams_above(law: &[Size], width: f64, text_h: f64) -> f64 {
    SHEET.height() - law_height(law, width + 4.0) - text_h - 5.0
}

/// A table's width and height, mm.
pub type Size = (f64, f64);

/// The tables' sizes, measured once for the arrangements tried.
pub fn sizes(ts: &[Table]) -> Vec<Size> {
    ts.iter().map(Table::size).collect()
}

/// The sheet's regions. Three arrangements of the views are tried, and the one with the
/// larger profile wins (then the larger nomogram, then the third):
/// - the nomogram under the notes in the diagrams' column, the profile alone on the right;
/// - both on the right side by side, the profile at the largest GOST scale that leaves the
///   nomogram [`NOMOGRAM_MIN_MM`], the law's tables under the notes when they fit;
/// - both on the right, the nomogram under the profile, the same way.
pub fn regions(c: &Content) -> Regions {
    let f = Frame::of(c);
    let below = nomogram_in_column(c, &f);
    // Both on the right.
    let law_h = law_height(c.law, f.left_w);
    let law_fits = f.column_used + law_h <= SHEET.height() && c.law.iter().all(|s| s.0 <= f.left_w);
    let all = [c.law, c.rest].concat();
    let tables = f.strip(if law_fits { c.rest } else { &all });
    let views = f.views_above(tables);
    let law_tables = law_fits.then(|| Rect::new(SHEET.x0, SHEET.y1 - (law_h - GAP), SHEET.x0 + f.left_w, SHEET.y1));
    let diagrams = Rect::new(SHEET.x0, SHEET.y0, SHEET.x0 + f.left_w, law_tables.map_or(SHEET.y1, |r| r.y0 - GAP));
    let around = |profile_mu, profile, nomogram_mu, nomogram| Regions {
        diagrams,
        law_tables,
        tables,
        nomogram,
        profile,
        nomogram_mu,
        profile_mu,
        pressure: None,
    };
    let beside = side_by_side(c, views).map(|(pm, p, nm, n)| around(pm, p, nm, n));
    let stacked = nomogram_under_profile(c, views).map(|(pm, p, nm, n)| around(pm, p, nm, n));
    // The larger profile wins, then the larger nomogram; on a tie, the views together on the
    // right (under a wide, low profile the sheet's middle is otherwise left empty).
    let better = |a: &Regions, b: &Regions| {
        a.profile_mu < b.profile_mu * 0.999
            || (a.profile_mu <= b.profile_mu * 1.001 && a.nomogram_mu < b.nomogram_mu * 0.999)
    };
    let best = [stacked, below, beside].into_iter().flatten().reduce(|a, b| if better(&b, &a) { b } else { a });
    // Nothing fits at any scale (an extent of no size): the views at 1:1 side by side.
    let best = best.unwrap_or_else(|| {
        let half = views.width() / 2.0;
        let nomogram = Rect::new(views.x0, views.y0, views.x0 + half - GAP, views.y1);
        around(0.001, Rect::new(views.x0 + half, views.y0, views.x1, views.y1), 0.001, nomogram)
    });
    slid_for_pressure(best)
}

/// A view slid across is kept where it leaves the pressure angle's diagram a plot this many
/// times larger than where it was arranged.
const SLIDE_GAIN: f64 = 1.1;

/// The regions with the pressure angle's room ([`free_room`]), the views on the right slid
/// across, each flush with what is beside it on either side, where that leaves the diagram
/// a larger plot: a profile centred over the views' room left a band too narrow for it on
/// each side (a wide rocker's, 60 mm either side at 1:1) where one side could hold it.
fn slid_for_pressure(arranged: Regions) -> Regions {
    let plot = |r: &Regions| free_room(r).and_then(pressure_view::plot_size).map_or(0.0, |(w, h)| w * h);
    let fixed: Vec<Rect> = [Some(arranged.diagrams), arranged.law_tables, Some(arranged.tables)]
        .into_iter()
        .flatten()
        .chain([frame::title_block_rect()])
        .collect();
    let with = |other: Rect| fixed.iter().copied().chain([other]).collect::<Vec<_>>();
    // The nomogram under the diagrams stays in their column.
    let nomogram_slides = arranged.nomogram.x0 >= arranged.diagrams.x1;
    let mut best = (plot(&arranged) * SLIDE_GAIN, arranged);
    for profile in slides(arranged.profile, &with(arranged.nomogram)) {
        let nomograms =
            if nomogram_slides { slides(arranged.nomogram, &with(profile)) } else { vec![arranged.nomogram] };
        for nomogram in nomograms {
            let r = Regions { profile, nomogram, ..arranged };
            let a = plot(&r);
            if a > best.0 {
                best = (a, r);
            }
        }
    }
    let r = best.1;
    Regions { pressure: free_room(&r), ..r }
}

/// `r` where it is and slid across to either end of the room the sheet and `others` leave
/// it, [`GAP`] from each of them beside it.
fn slides(r: Rect, others: &[Rect]) -> Vec<Rect> {
    let beside: Vec<&Rect> = others.iter().filter(|o| o.y0 < r.y1 + GAP - 1e-6 && o.y1 > r.y0 - GAP + 1e-6).collect();
    let lo = beside.iter().filter(|o| o.x1 <= r.x0).fold(SHEET.x0, |x, o| x.max(o.x1 + GAP));
    let hi = beside.iter().filter(|o| o.x0 >= r.x1).fold(SHEET.x1, |x, o| x.min(o.x0 - GAP));
    let at = |x0: f64| r + Vec2::new(x0 - r.x0, 0.0);
    vec![r, at(lo.min(r.x0)), at((hi - r.width()).max(r.x0))]
}

/// The nomogram under the notes in the diagrams' column, the profile alone on the right.
fn nomogram_in_column(c: &Content, f: &Frame) -> Option<Regions> {
    let tables = f.strip(&[c.law, c.rest].concat());
    let views = f.views_above(tables);
    let column = Rect::new(SHEET.x0, SHEET.y0 + f.column_used + GAP, SHEET.x0 + f.left_w, SHEET.y1);
    let n =
        fit_view(&c.nomogram, column).filter(|(mu, _)| longer_side(c.nomogram.at(*mu), *mu) >= NOMOGRAM_MIN_MM * 0.6);
    let p = fit_view(&c.profile, views);
    n.zip(p).map(|((nomogram_mu, nomogram), (profile_mu, profile))| Regions {
        diagrams: Rect::new(SHEET.x0, SHEET.y0, SHEET.x0 + f.left_w, nomogram.y0 - GAP),
        law_tables: None,
        tables,
        nomogram,
        profile: centred_across(profile, views),
        nomogram_mu,
        profile_mu,
        pressure: None,
    })
}

/// Both views on the right side by side, the room left over shared out between and round
/// the two.
fn side_by_side(c: &Content, views: Rect) -> Option<(f64, Rect, f64, Rect)> {
    let found = profile_and_nomogram((&c.profile, &c.nomogram), views, |profile| {
        Rect::new(views.x0, views.y0, views.x1 - profile.width() - GAP, views.y1)
    });
    found.map(|(profile_mu, profile, nomogram_mu, nomogram)| {
        let slack = ((views.width() - profile.width() - nomogram.width() - GAP) / 3.0).max(0.0);
        let nomogram = nomogram + Vec2::new(slack, 0.0);
        let px = (nomogram.x1 + GAP + slack).min(views.x1 - profile.width());
        (profile_mu, profile + Vec2::new(px - profile.x0, 0.0), nomogram_mu, nomogram)
    })
}

/// The nomogram under the profile on the right (a wide, low profile: a rocker's pivots on
/// their arc above the cam).
fn nomogram_under_profile(c: &Content, views: Rect) -> Option<(f64, Rect, f64, Rect)> {
    let found = profile_and_nomogram((&c.profile, &c.nomogram), views, |profile| {
        Rect::new(views.x0, profile.y1 + GAP, views.x1, views.y1)
    });
    found.map(|(pm, p, nm, n)| (pm, centred_across(p, views), nm, centred_across(n, views)))
}

/// The largest room on the sheet that no region of `r` (nor the title block) comes within
/// [`GAP`] of, where the pressure angle's diagram is drawn at least at its least size: the
/// rectangle whose plot ([`pressure_view::plot_size`]) is largest. Its sides are taken from
/// the sheet's and the regions' edges, which is where a largest empty rectangle's lie.
pub fn free_room(r: &Regions) -> Option<Rect> {
    let taken: Vec<Rect> = [Some(r.diagrams), r.law_tables, Some(r.tables), Some(r.nomogram), Some(r.profile)]
        .into_iter()
        .flatten()
        .chain([frame::title_block_rect()])
        .map(|t| t.inflate(GAP, GAP))
        .collect();
    let xs: Vec<f64> = taken.iter().flat_map(|t| [t.x0, t.x1]).chain([SHEET.x0, SHEET.x1]).collect();
    let ys: Vec<f64> = taken.iter().flat_map(|t| [t.y0, t.y1]).chain([SHEET.y0, SHEET.y1]).collect();
    let inside = |v: f64, lo: f64, hi: f64| v >= lo && v <= hi;
    // Each edge once, in the order first met: a repeated room could not beat itself.
    let distinct = |vs: Vec<f64>, lo: f64, hi: f64| {
        let mut out: Vec<f64> = Vec::new();
        for v in vs.into_iter().filter(|&v| inside(v, lo, hi)) {
            if !out.contains(&v) {
                out.push(v);
            }
        }
        out
    };
    let (xs, ys) = (distinct(xs, SHEET.x0, SHEET.x1), distinct(ys, SHEET.y0, SHEET.y1));
    let mut best: Option<(f64, Rect)> = None;
    for &x0 in &xs {
        for &x1 in xs.iter().filter(|&&x| x > x0) {
            // The plot grows with its room's height: no room between these sides beats the
            // best if the sheet's whole height would not.
            let tallest = pressure_view::plot_size(Rect::new(x0, SHEET.y0, x1, SHEET.y1));
            if tallest.is_none_or(|(w, h)| best.is_some_and(|(a, _)| w * h <= a)) {
                continue;
            }
            for &y0 in &ys {
                for &y1 in ys.iter().filter(|&&y| y > y0) {
                    let room = Rect::new(x0, y0, x1, y1);
                    if taken.iter().any(|t| t.intersect(room).area() > 0.0) {
                        continue;
                    }
                    if let Some((w, h)) = pressure_view::plot_size(room)
                        && best.is_none_or(|(a, _)| w * h > a)
                    {
                        best = Some((w * h, room));
                    }
                }
            }
        }
    }
    best.map(|(_, room)| room)
}

/// Where a view draws: its region less its title, scale and margins.
pub fn view_area(r: Rect) -> Rect {
    Rect::new(r.x0 + VIEW_SIDES / 2.0, r.y0 + VIEW_TOP, r.x1 - VIEW_SIDES / 2.0, r.y1 - VIEW_BOTTOM)
}

/// The profile at the top left of `views` at the largest GOST scale that leaves the
/// nomogram [`NOMOGRAM_MIN_MM`] in the room `rest(profile)` (else the largest profile with
/// any nomogram): `(μ_profile, profile, μ_nomogram, nomogram)`.
fn profile_and_nomogram(
    (p_ext, n_ext): (&ViewSize, &ViewSize),
    views: Rect,
    rest: impl Fn(Rect) -> Rect,
) -> Option<(f64, Rect, f64, Rect)> {
    let mut found = None;
    for mu_p in scale::length_scales() {
        let Some((_, profile)) = fit_at(p_ext, views, mu_p) else { continue };
        let Some((mu_n, nomogram)) = fit_view(n_ext, rest(profile)) else { continue };
        let enough = longer_side(n_ext.at(mu_n), mu_n) >= NOMOGRAM_MIN_MM;
        if found.is_none() || enough {
            found = Some((mu_p, profile, mu_n, nomogram));
        }
        if enough {
            break;
        }
    }
    found
}

/// The longer side of a view's drawing at `mu`, mm.
fn longer_side((lo, hi): (Vec2, Vec2), mu: f64) -> f64 {
    ((hi.x - lo.x) / mu).max((hi.y - lo.y) / mu)
}

/// The region a view takes at `mu` at the top left of `room`, if it fits there: its box
/// (metres) at `mu` with the view's margins, and no narrower than its heading.
fn fit_at(view: &ViewSize, room: Rect, mu: f64) -> Option<(f64, Rect)> {
    let (lo, hi) = view.at(mu);
    let w = ((hi.x - lo.x) / mu + VIEW_SIDES).max(view.heading_w);
    let h = (hi.y - lo.y) / mu + VIEW_TOP + VIEW_BOTTOM;
    (w <= room.width() && h <= room.height()).then(|| (mu, Rect::new(room.x0, room.y0, room.x0 + w, room.y0 + h)))
}

/// The largest GOST 2.302 scale at which a view fits `room` (a step coarser where the view
/// is not [`ViewSize::fine`]) and its region there.
fn fit_view(view: &ViewSize, room: Rect) -> Option<(f64, Rect)> {
    let need = view
        .least_mu(room.width() - VIEW_SIDES, |v| v.x)
        .max(view.least_mu(room.height() - VIEW_TOP - VIEW_BOTTOM, |v| v.y));
    if !(need.is_finite() && need > 0.0) {
        return None;
    }
    let mu = scale::length_scale(need);
    let mu = if view.fine { mu } else { scale::length_scale(mu * 1.001) };
    fit_at(view, room, mu)
}

/// `r` moved to the middle of `within` across.
fn centred_across(r: Rect, within: Rect) -> Rect {
    r + Vec2::new(within.x0 + (within.width() - r.width()) / 2.0 - r.x0, 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A view slides to either end of the room beside it: flush, [`GAP`] off, with what is
    /// beside it (not with what is above or below it) or with the sheet's edge.
    #[test]
    fn a_view_slides_flush_with_what_is_beside_it() {
        let view = Rect::new(400.0, 100.0, 600.0, 200.0);
        let column = Rect::new(SHEET.x0, SHEET.y0, 300.0, 300.0);
        let above = Rect::new(300.0, SHEET.y0, SHEET.x1, 100.0 - GAP);
        let [stays, left, right] = slides(view, &[column, above])[..] else { panic!("three places") };
        assert_eq!(stays, view);
        assert_eq!((left.x0, left.width(), left.y0), (300.0 + GAP, 200.0, 100.0));
        assert_eq!((right.x1, right.width()), (SHEET.x1, 200.0));
    }

    /// A view that draws a paper depth under a world point (the offset's dimension under O)
    /// is fitted with that depth inside its region, at a coarser scale where the bare box
    /// would leave it no room; a view under a long title gets a region as wide as the title.
    #[test]
    fn a_views_paper_reach_and_heading_are_inside_the_region_it_is_fitted_to() {
        let bare = ViewSize {
            extent: (Vec2::new(-0.05, -0.02), Vec2::new(0.05, 0.08)),
            reach: Vec::new(),
            heading_w: 0.0,
            fine: true,
        };
        let view = ViewSize { reach: vec![(Vec2::new(0.01, -0.02), Vec2::new(0.0, -30.0))], ..bare.clone() };
        let room = Rect::new(0.0, 0.0, 200.0, 70.0);
        let (mu0, _) = fit_view(&bare, room).unwrap();
        let (mu, r) = fit_view(&view, room).unwrap();
        assert!(mu > mu0, "the reach costs scale: {mu} vs {mu0}");
        let (lo, hi) = view.at(mu);
        assert!(lo.y <= -0.02 - 30.0 * mu + 1e-12, "the box holds the reach: {lo:?}");
        assert!((hi.y - lo.y) / mu + VIEW_TOP + VIEW_BOTTOM <= r.height() + 1e-9 && r.height() <= room.height());
        let titled = ViewSize { heading_w: 150.0, ..bare };
        let (_, r) = fit_view(&titled, room).unwrap();
        assert!(r.width() >= 150.0, "{r:?}");
        assert!(fit_view(&ViewSize { heading_w: 201.0, ..titled }, room).is_none(), "a title wider than the room");
    }
}
