//! The planetary stage's region in the top of the sheet's right half: the front view, the
//! kinematic scheme and beside it the picture of linear velocities, and under the three the
//! plan of angular velocities in a strip as wide as the half (or, where the tables below
//! leave no room for one, under the picture of linear velocities); the views as large as
//! the tables still fit below, the strip as tall as they leave.

use super::labels::GearWords;
use super::stage_velocities::{self, CARRIER_TARGETS_MM, Reading, Slopes};
use super::{PLANETARY_PART, planetary_view, tables};
use crate::drawing::fmt;
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, Item, Text};
use crate::drawing::table::CELL_TEXT;
use crate::drawing::text::wrap;
use crate::project::gears::PlanetaryProject;
use kurbo::{Point, Rect};

/// The planetary stage as drawn: the views' group, their μ_l, the bottom of their region and
/// the ratio read off the plan of angular velocities.
pub(super) struct PlanetaryDrawn {
    pub group: Group,
    pub mu: f64,
    pub bottom: f64,
    pub reading: Reading,
}

/// The shares of the right half's width the front view may take, largest first: the views
/// take the largest that leaves the tables room below them.
const VIEW_SHARES: [f64; 3] = [0.54, 0.5, 0.45];

/// Where the plan of angular velocities goes: a strip under the views tall enough for 0–H
/// of `target` mm (as the width allows), or under the picture of linear velocities beside
/// the scheme's lower half, in the views' own height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum PlanRoom {
    Strip { target: f64 },
    Column,
}

/// The least 0–H a strip is drawn for where none of [`CARRIER_TARGETS_MM`] leaves the tables
/// room, mm.
const LEAST_TARGET_MM: f64 = 10.0;

/// The stage's region and its parts for one choice.
struct Frame {
    mu: f64,
    region: Rect,
    /// The front view, the kinematic scheme, the velocity pictures beside it (down to the
    /// views' foot) and the plan's strip under all three (empty where the plan is beside).
    front: Rect,
    side: Rect,
    pictures: Rect,
    strip: Rect,
    /// The length 0–H the plan draws in the strip, mm.
    strip_carrier: f64,
}

/// The planetary views' μ_l and their region in the top of `right` when the front view may
/// take `share` of its width and the plan goes in `plan`.
fn frame(pl: &PlanetaryProject, right: Rect, share: f64, plan: PlanRoom) -> Frame {
    let s = &pl.stage;
    let mu = planetary_view::scale_for(s, pl.module, (right.width() * share - 10.0).min(260.0));
    let across = 2.0 * planetary_view::extent(s, pl.module) / mu;
    let views = Rect::new(right.x0, right.y0, right.x1, right.y0 + 14.0 + across + 16.0 + 6.0);
    let (top, bottom) = (views.y0 + 14.0, views.y1 - 6.0);
    let front = Rect::new(views.x0, top, views.x0 + across + 14.0, bottom);
    let scheme_w = ((views.x1 - front.x1) * 0.48).min(110.0);
    let side = Rect::new(front.x1, top, front.x1 + scheme_w, bottom);
    let pictures = Rect::new(side.x1 + 4.0, top - 8.0, views.x1, views.y1 - 1.0);
    let (strip_h, strip_carrier) = match plan {
        PlanRoom::Strip { target } => {
            let v_a = stage_velocities::v_a_length(pictures.width());
            let slopes = Slopes::new(planetary_view::heights(s, pl.module, mu), v_a);
            let h = stage_velocities::strip_height(slopes, views.width(), target);
            (h, stage_velocities::carrier_mm(slopes, Rect::new(views.x0, 0.0, views.x1, h)))
        }
        PlanRoom::Column => (0.0, 0.0),
    };
    let region = Rect { y1: views.y1 + strip_h, ..views };
    Frame { mu, region, front, side, pictures, strip: Rect { y0: views.y1, ..region }, strip_carrier }
}

/// The planetary views' share of `right` and the plan's rooms worth drawing, best first: the
/// views as large as the tables (`table_sizes`, in 5 and 3.5 mm lettering) still fit below
/// them in 3.5 mm; the plan of angular velocities in a strip under them for 0–H of
/// [`CARRIER_TARGETS_MM`], the tables first keeping the lettering and arrangement they have
/// without it (only moved down), then their lettering, then in 3.5 mm for 5 mm; else for
/// [`LEAST_TARGET_MM`] so; else beside the scheme. Only the first tier that has any: the
/// caller picks among them (the one that leaves room for the rack generation pictures).
pub(super) fn choices(
    pl: &PlanetaryProject,
    right: Rect,
    table_sizes: &[Vec<(f64, f64)>; 2],
    words: &GearWords,
) -> Choices {
    let below = |share: f64, plan: PlanRoom| {
        Rect::new(right.x0, frame(pl, right, share, plan).region.y1 + 4.0, right.x1, right.y1)
    };
    let share = VIEW_SHARES
        .into_iter()
        .find(|&s| tables::fit(&table_sizes[1], below(s, PlanRoom::Column)))
        .unwrap_or(VIEW_SHARES[VIEW_SHARES.len() - 1]);
    let kept = tables::arrangement(table_sizes, below(share, PlanRoom::Column));
    // What a strip costs the tables: nothing; their arrangement (rows for columns) in the
    // same lettering; 3.5 mm lettering for 5 mm. None: 2.5 mm.
    let cost = |target: f64| {
        let a = tables::arrangement(table_sizes, below(share, PlanRoom::Strip { target }));
        match a {
            _ if a == kept => Some(0),
            _ if a.lettering() == kept.lettering() => Some(1),
            _ => None,
        }
    };
    // Only a strip that draws 0–H longer than the plan beside the scheme does (a small
    // ratio's there may be longer than any target).
    let beside = draw(pl, right, share, PlanRoom::Column, words).reading.carrier_mm;
    let longer = |target: f64| frame(pl, right, share, PlanRoom::Strip { target }).strip_carrier > beside + 0.5;
    let tiers: [&[f64]; 2] = [&CARRIER_TARGETS_MM, &[LEAST_TARGET_MM]];
    let plans = tiers
        .into_iter()
        .map(|targets| {
            let costs: Vec<(f64, u8)> =
                targets.iter().filter(|&&t| longer(t)).filter_map(|&t| cost(t).map(|c| (t, c))).collect();
            (0..=1)
                .flat_map(|c| costs.iter().filter(move |tc| tc.1 == c).map(|tc| PlanRoom::Strip { target: tc.0 }))
                .collect::<Vec<_>>()
        })
        .find(|plans| !plans.is_empty())
        .unwrap_or_else(|| vec![PlanRoom::Column]);
    Choices { share, plans }
}

/// The planetary views' share of the right half and the plan's rooms to choose from, best
/// first ([`choices`]).
pub(super) struct Choices {
    pub share: f64,
    pub plans: Vec<PlanRoom>,
}

/// The planetary views in the top of `right` at `share`, the plan in `plan`.
pub(super) fn draw(
    pl: &PlanetaryProject,
    right: Rect,
    share: f64,
    plan: PlanRoom,
    words: &GearWords,
) -> PlanetaryDrawn {
    group(pl, frame(pl, right, share, plan), plan, words)
}

/// The planetary views in `f`: the front view, the kinematic scheme and beside it the
/// pictures of linear and angular velocities, with the ratio read from them.
fn group(pl: &PlanetaryProject, f: Frame, plan: PlanRoom, words: &GearWords) -> PlanetaryDrawn {
    let (l, lang) = (words.sheet, words.lang);
    let (s, region, mu) = (&pl.stage, f.region, f.mu);
    let mut g = Group::new("planetary", region);
    let [u, required] =
        <[String; 2]>::try_from(fmt::values_alike(&[s.ratio, s.ratio_required], lang)).expect("two values written");
    let title = l.planetary_title(&u, &required, &s.planets.to_string());
    // In the mesh's title's lettering: the two are the sheet's sections (in 3.5 mm it read
    // as a caption under the mesh's, a teacher's review).
    g.text(Text::new(Point::new(region.x0 + 2.0, region.y0 + 6.0), title, 5.0, Anchor::Start));
    let scheme = match s.scheme {
        crate::gears::planetary::Scheme::SunPlanetRing => l.scheme_sun_planet_ring(),
        crate::gears::planetary::Scheme::DoublePlanet => l.scheme_double_planet(),
    };
    let sc = l.scale(&fmt::localise(&scale::ratio(mu), lang));
    g.text(Text::new(Point::new(region.x0 + 2.0, region.y0 + 11.0), format!("{scheme}; {sc}"), 2.5, Anchor::Start));
    let mut labels = Labels::new();
    let start = g.mark();
    let points = planetary_view::draw(&mut g, f.front, f.side, s, pl.module, mu, &mut labels);
    // Each view's caption just under it, not at the foot of the views' row: there, over
    // a plan of angular velocities in the strip below, «Кинематическая схема» read as the
    // plan's title (a teacher's review of the Russian sheets).
    for (view, caption) in [(f.front, l.front_view()), (f.side, l.side_view())] {
        let y = (drawn_bottom(&g.items[start..], view) + CAPTION_UNDER).min(f.strip.y0 - 1.5);
        g.text(Text::new(Point::new(view.center().x, y), caption, 2.5, Anchor::Middle));
    }
    let strip = (plan != PlanRoom::Column).then_some(f.strip);
    let reading = velocity_pictures(&mut g, (f.pictures, strip), &points, s.ratio, words, &mut labels);
    labels.place(&mut g, region);
    g.part_from(PLANETARY_PART, start);
    PlanetaryDrawn { group: g, mu, bottom: region.y1, reading }
}

/// A view's caption's baseline under the view's lowest line, mm: a name placed under the
/// view keeps to the room between them.
const CAPTION_UNDER: f64 = 7.0;

/// The lowest point of `items` drawn in `view`'s columns (their boxes' middles within
/// them), else the view's top.
fn drawn_bottom(items: &[Item], view: Rect) -> f64 {
    items
        .iter()
        .map(Item::bbox)
        .filter(|b| (view.x0..=view.x1).contains(&b.center().x))
        .map(|b| b.y1)
        .fold(view.y0, f64::max)
}

/// The pictures of linear and angular velocities: the linear in `area` beside the scheme,
/// above its axis; the angular in `strip`, or where there is none under the linear; their
/// captions and the ratio read from them against the analytic `ratio` at the foot of `area`.
fn velocity_pictures(
    g: &mut Group,
    (area, strip): (Rect, Option<Rect>),
    points: &planetary_view::SchemePoints,
    ratio: f64,
    words: &GearWords,
    labels: &mut Labels,
) -> Reading {
    let (l, lang) = (words.sheet, words.lang);
    let axis = points.axis.y;
    // The caption of the linear velocities above C; the plan's caption and reading at the foot.
    let caption_at = Point::new(area.x0 + 10.0, points.c.y - 3.0);
    g.text(Text::new(caption_at, l.linear_velocities(), 2.5, Anchor::Start));
    let read = |mm: f64| fmt::localise(&format!("{:.1}", Reading::read(mm)), lang);
    let note = |u: f64| {
        let difference = fmt::localise(&format!("{:.2}", (u - ratio) / ratio * 100.0), lang);
        wrap(&l.graphic_ratio_note(&fmt::value(ratio, lang), &difference), CELL_TEXT, area.width() - 2.0)
    };
    // The texts keep room for the plan's caption, the reading and the note (whose length the
    // reading hardly changes: a difference of −99,99 % is the longest): over the strip, at
    // the foot just above the plan; else the plan beside the scheme, under the picture of
    // linear velocities with the texts under it, or, where that draws 0–H longer, under the
    // carrier (right of the ring, from the foot of the carrier's arm down to the scheme's
    // caption) with the texts just over it.
    let line = CELL_TEXT * crate::drawing::text::LINE_PITCH;
    let block = (2 + note(-99.99 * ratio).len()) as f64 * line;
    let foot = area.y1 - block - 2.0;
    let upper = Rect::new(area.x0, area.y0, area.x1, axis);
    let beside = Rect::new(area.x0, axis + 3.0, area.x1, foot);
    let h_b = axis - points.b.y;
    let under = Rect::new(points.c.x + 4.0, (axis + h_b + 4.0).max(axis + block + 6.0), area.x1, area.y1 - 5.0);
    let heights = [axis - points.a.y, h_b, axis - points.c.y];
    let slopes = Slopes::new(heights, stage_velocities::v_a_length(upper.width()));
    let carrier_under = |room: Rect| stage_velocities::carrier_mm(slopes, room);
    let under_wins = strip.is_none() && under.height() > 20.0 && carrier_under(under) > carrier_under(beside);
    let room = strip.unwrap_or(if under_wins { under } else { beside });
    let (reading, plan_bottom) = stage_velocities::draw(g, upper, room, points, labels);
    let (u_line, notes) = match reading.ratio {
        Some(u) => (l.graphic_ratio(&read(reading.sun_mm), &read(reading.carrier_mm), &fmt::value(u, lang)), note(u)),
        None => (l.graphic_ratio_unreadable().to_string(), Vec::new()),
    };
    let at = |y: f64| Point::new(area.x0 + 1.0, y);
    let mut y = match (strip, under_wins) {
        (Some(_), _) => foot,
        // Just over the plan: at the axis, 55 mm over a tall stage's plan, the caption read
        // as the picture of linear velocities' (the worked example in Russian).
        (None, true) => (under.y0 - block - 3.0).max(axis + 3.0),
        (None, false) => plan_bottom.min(foot),
    } + line;
    g.text(Text::new(at(y), l.angular_velocities(), CELL_TEXT, Anchor::Start));
    y += line;
    g.text(Text::new(at(y), "u", CELL_TEXT, Anchor::Start).with_sub("1H", u_line));
    for text in notes {
        y += line;
        g.text(Text::new(at(y), text, CELL_TEXT, Anchor::Start));
    }
    reading
}
