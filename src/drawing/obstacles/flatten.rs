//! An item's drawn pieces for the index: its lines flattened into segments, a text's
//! letters' boxes, and the box every piece of an item lies in.

use super::memo;
use super::{FLATTEN, Piece};
use crate::drawing::path::{Path, Seg};
use crate::drawing::scene::Item;
use crate::num::math::Norm;
use kurbo::{Point, Rect, Shape};

/// The segments an item draws (none for a text).
pub fn segments(item: &Item) -> Vec<(Point, Point)> {
    let mut out = Vec::new();
    segments_into(item, &mut out);
    out
}

/// [`segments`] appended to `out`: an index made of many items flattens each into one
/// buffer rather than a list of its own.
fn segments_into(item: &Item, out: &mut Vec<(Point, Point)>) {
    match item {
        Item::Path { path, .. } if lines_only(path) => polyline(path, path.closed, out),
        Item::Fill { path } if lines_only(path) => polyline(path, true, out),
        Item::Path { path, .. } => flatten(path.to_bez().iter(), out),
        Item::Fill { path } => {
            let mut p = path.clone();
            p.closed = true;
            flatten(p.to_bez().iter(), out);
        }
        // Flattened once a build ([`memo`]); its elements as its path would hold them,
        // without making the path.
        Item::Circle { c, r, .. } => memo::circle(*c, *r, out, |out| {
            flatten(kurbo::Circle::new(*c, *r).path_elements(FLATTEN / 10.0), out);
        }),
        Item::Text(_) => {}
    }
}

/// The segments of a path's elements flattened within [`FLATTEN`], appended to `out`.
fn flatten(els: impl IntoIterator<Item = kurbo::PathEl>, out: &mut Vec<(Point, Point)>) {
    let (mut start, mut last) = (Point::ZERO, Point::ZERO);
    kurbo::flatten(els, FLATTEN, |el| match el {
        kurbo::PathEl::MoveTo(p) => (start, last) = (p, p),
        kurbo::PathEl::LineTo(p) => {
            out.push((last, p));
            last = p;
        }
        kurbo::PathEl::ClosePath => {
            if last != start {
                out.push((last, start));
            }
            last = start;
        }
        _ => {}
    });
}

fn lines_only(path: &Path) -> bool {
    path.segs.iter().all(|s| matches!(s, Seg::Line(_)))
}

/// The segments of a path of straight lines, closed or not: what flattening it gives (its
/// lines as they are, and the closing line where the path does not end at its start),
/// without building and walking a curve path for it (most of a sheet's paths are lines).
fn polyline(path: &Path, closed: bool, out: &mut Vec<(Point, Point)>) {
    out.reserve(path.segs.len() + usize::from(closed));
    let mut last = path.start;
    for s in &path.segs {
        if let Seg::Line(p) = *s {
            out.push((last, p));
            last = p;
        }
    }
    if closed && last != path.start {
        out.push((last, path.start));
    }
}

/// Half a thin line's width, mm: its ink is within the labels' clearance of its centre line.
const THIN_HALF: f64 = 0.125;

/// An item's pieces, tagged `k`, appended to `out`: a text's letters' boxes; a line's
/// segments, and a thick line's edges too (its ink reaches past its centre line further
/// than a label's clearance). `segs` is a buffer for the line's segments.
pub(super) fn pieces_of(item: &Item, k: usize, out: &mut Vec<(Piece, usize)>, segs: &mut Vec<(Point, Point)>) {
    match item {
        Item::Text(t) => out.extend(t.core_boxes().map(|b| (Piece::TextBox(b), k))),
        _ => {
            segs.clear();
            segments_into(item, segs);
            stroke_pieces(item, segs, k, out);
        }
    }
}

/// A drawn item's pieces from its [`segments`] `segs`, as [`pieces_of`].
pub(super) fn stroke_pieces(item: &Item, segs: &[(Point, Point)], k: usize, out: &mut Vec<(Piece, usize)>) {
    let edge = pen_width(item).map_or(0.0, |w| w / 2.0 - THIN_HALF);
    if edge > 0.0 {
        for &(a, b) in segs.iter().filter(|(a, b)| (*b - *a).norm() > 0.0) {
            let n = (b - a).unit().turn_90() * edge;
            out.push((Piece::Segment(a + n, b + n), k));
            out.push((Piece::Segment(a - n, b - n), k));
        }
    }
    out.extend(segs.iter().map(|&(a, b)| (Piece::Segment(a, b), k)));
}

/// A box every piece of a drawn item lies in, found without flattening it (its points and
/// control points, an arc's whole circle, half its pen beyond, and a margin for the
/// flattening's tolerance); none for a text (its letters' boxes are its pieces).
pub(super) fn reach(item: &Item) -> Option<Rect> {
    let path_box = |path: &Path| {
        path.segs.iter().fold(Rect::from_points(path.start, path.start), |r, seg| match seg {
            Seg::Line(p) => r.union_pt(*p),
            Seg::Cubic(p1, p2, p3) => r.union_pt(*p1).union_pt(*p2).union_pt(*p3),
            Seg::Arc(a) => {
                let rad = a.radii.x.max(a.radii.y);
                r.union(Rect::from_center_size(a.center, (2.0 * rad, 2.0 * rad)))
            }
        })
    };
    let (r, pen) = match item {
        Item::Path { path, pen } => (path_box(path), pen.width),
        Item::Fill { path } => (path_box(path), 0.0),
        Item::Circle { c, r, pen, .. } => (Rect::from_center_size(*c, (2.0 * r, 2.0 * r)), pen.width),
        Item::Text(_) => return None,
    };
    let out = pen / 2.0 + REACH_SLACK;
    Some(r.inflate(out, out))
}

/// Far beyond a curve's flattening tolerance, mm.
const REACH_SLACK: f64 = 0.1;

/// Whether the closed boxes `a` and `b` share a point.
pub(super) fn meets(a: Rect, b: Rect) -> bool {
    a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1
}

/// The width of an item's stroke, if it has one.
fn pen_width(item: &Item) -> Option<f64> {
    match item {
        Item::Path { pen, .. } | Item::Circle { pen, filled: false, .. } => Some(pen.width),
        _ => None,
    }
}
