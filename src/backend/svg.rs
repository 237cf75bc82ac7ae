//! A small deterministic SVG writer: fixed decimals, `-0` written as `0`, complete XML
//! escaping, elements in scene order with the groups' stable ids. No timestamps, no
//! randomness. A non-finite number anywhere in the scene is refused, naming its group,
//! rather than written as something else.

use super::{BackendError, shapes};
use crate::drawing::path::{Path, Seg};
use crate::drawing::scene::{Anchor, Group, Ink, Item, LineType, MAIN, Pen, Scene, Text, VECTOR};
use crate::font;
use crate::num::math;
use crate::num::work::{self, Step};
use kurbo::Arc;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::fmt::Write;

/// Digits after the decimal point for paper millimetres (1 µm).
const DECIMALS: usize = 3;

/// Formats a number with at most three decimals (1 µm), no trailing zeros, no `-0`;
/// refuses NaN and infinities.
pub fn num(x: f64) -> Result<String, BackendError> {
    let mut s = String::new();
    push_num(&mut s, x)?;
    Ok(s)
}

/// [`num`] written at the end of `out`.
fn push_num(out: &mut String, x: f64) -> Result<(), BackendError> {
    if !x.is_finite() {
        return Err(BackendError::NonFinite { group: String::new(), value: x, item: "a number".into() });
    }
    if thousandths(out, x) {
        return Ok(());
    }
    let mut s = format!("{x:.DECIMALS$}");
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".into();
    }
    out.push_str(&s);
    Ok(())
}

/// [`num`] without the formatter's exact decimal expansion, written at the end of `out`,
/// where rounding `x` to thousandths in binary is sure to round it as the expansion does:
/// `x` · 1000 is within a part in 2⁵³ of its exact product, so unless that lies within a
/// millionth of a half (then nothing is written: the formatter decides), its nearest whole
/// number is the exact one's.
fn thousandths(out: &mut String, x: f64) -> bool {
    let y = x * 1000.0;
    // Not finite, or past the i64 below: the formatter decides.
    if !y.is_finite() || y.abs() >= 1e12 || ((y - y.trunc()).abs() - 0.5).abs() < 1e-6 {
        return false;
    }
    // Below 2⁵³: exact in an i64.
    let n = y.round() as i64;
    let (whole, mut frac) = (n.unsigned_abs() / 1000, n.unsigned_abs() % 1000);
    if n < 0 {
        out.push('-');
    }
    // Writing to a String cannot fail.
    let _ = write!(out, "{whole}");
    if frac != 0 {
        let mut digits = DECIMALS;
        while frac % 10 == 0 {
            frac /= 10;
            digits -= 1;
        }
        let _ = write!(out, ".{frac:0digits$}");
    }
    true
}

/// Escapes the five XML special characters. Characters XML cannot hold at all (control
/// characters) are refused where the user writes them (`project::text`) and never reach here.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            _ => out.push(c),
        }
    }
    out
}

/// A line's stroke attributes, written at the end of `out`.
fn stroke_attrs(out: &mut String, pen: &Pen, ink: &str) -> Result<(), BackendError> {
    let _ = write!(out, "stroke=\"{ink}\" stroke-width=\"");
    push_num(out, pen.width)?;
    out.push('"');
    if let Some(a) = shapes::dash_array(pen.line) {
        out.push_str(" stroke-dasharray=\"");
        for (k, &x) in a.iter().enumerate() {
            if k > 0 {
                out.push(' ');
            }
            push_num(out, x)?;
        }
        out.push('"');
    }
    Ok(())
}

/// Path data: `M`, `L`, `C` and `A` commands, `Z` when closed, written at the end of `d`.
fn path_d(d: &mut String, p: &Path) -> Result<(), BackendError> {
    // A command's letter, then its numbers apart by spaces.
    let command = |d: &mut String, letter: char, xs: &[f64]| -> Result<(), BackendError> {
        d.push(letter);
        for (k, &x) in xs.iter().enumerate() {
            if k > 0 {
                d.push(' ');
            }
            push_num(d, x)?;
        }
        Ok(())
    };
    command(d, 'M', &[p.start.x, p.start.y])?;
    for s in &p.segs {
        match s {
            Seg::Line(q) => command(d, 'L', &[q.x, q.y])?,
            Seg::Cubic(a, b, c) => command(d, 'C', &[a.x, a.y, b.x, b.y, c.x, c.y])?,
            Seg::Arc(a) => d.push_str(&arc_commands(a)?),
        }
    }
    if p.closed {
        d.push('Z');
    }
    Ok(())
}

/// An arc as `A` commands. An arc whose ends are written as one point (a whole circle) is
/// written as two halves: a renderer draws nothing for an `A` that ends where it starts
/// (SVG 1.1, F.6.2).
fn arc_commands(a: &Arc) -> Result<String, BackendError> {
    let at = |angle: f64| -> Result<(String, String), BackendError> {
        let p = a.center + math::from_angle(angle) * a.radii.x;
        Ok((num(p.x)?, num(p.y)?))
    };
    let closes = a.sweep_angle != 0.0 && at(a.start_angle)? == at(a.start_angle + a.sweep_angle)?;
    if closes {
        let half = a.sweep_angle / 2.0;
        Ok(arc_command(a, a.start_angle, half)? + &arc_command(a, a.start_angle + half, half)?)
    } else {
        arc_command(a, a.start_angle, a.sweep_angle)
    }
}

/// One `A` command along `a`'s circle from `start` through `sweep` (radians).
fn arc_command(a: &Arc, start: f64, sweep: f64) -> Result<String, BackendError> {
    let end = a.center + math::from_angle(start + sweep) * a.radii.x;
    let large = u8::from(sweep.abs() > PI);
    // Paper y points down, so a growing angle is SVG's positive (clockwise) sweep.
    let clockwise = u8::from(sweep > 0.0);
    let r = num(a.radii.x)?;
    Ok(format!("A{r} {r} 0 {large} {clockwise} {} {}", num(end.x)?, num(end.y)?))
}

fn text_element(t: &Text, ink: &str) -> Result<String, BackendError> {
    let anchor = match t.anchor {
        Anchor::Start => "",
        Anchor::Middle => " text-anchor=\"middle\"",
        Anchor::End => " text-anchor=\"end\"",
    };
    let (x, y) = (num(t.at.x)?, num(t.at.y)?);
    let mut transform = String::new();
    if t.rotate != 0.0 || t.sloped || t.stretch != 1.0 {
        transform.push_str(&format!(" transform=\"translate({x} {y})"));
        if t.rotate != 0.0 {
            transform.push_str(&format!(" rotate({})", num(-t.rotate)?));
        }
        if t.stretch != 1.0 {
            transform.push_str(&format!(" scale({} 1)", num(t.stretch)?));
        }
        if t.sloped {
            transform.push_str(" skewX(-15)");
        }
        transform.push('"');
    }
    let (x, y) = if transform.is_empty() { (x, y) } else { ("0".into(), "0".into()) };
    Ok(format!(
        "<text class=\"text\" fill=\"{ink}\" x=\"{x}\" y=\"{y}\" font-size=\"{}\"{anchor}{transform}>{}{}</text>",
        num(font::size_for_cap(t.h))?,
        escape(&t.text),
        subscript_and_tail(t)?
    ))
}

/// The runs after the main text: a subscript as a smaller run lowered by its drop, a tail
/// back on the baseline; the renderer sets each after the last with its own font.
fn subscript_and_tail(t: &Text) -> Result<String, BackendError> {
    let mut out = String::new();
    let mut drop = 0.0;
    for r in t.runs().skip(usize::from(!t.text.is_empty())) {
        let dy = if r.drop == drop { String::new() } else { format!(" dy=\"{}\"", num(r.drop - drop)?) };
        let size = if r.h == t.h { String::new() } else { format!(" font-size=\"{}\"", num(font::size_for_cap(r.h))?) };
        out.push_str(&format!("<tspan{dy}{size}>{}</tspan>", escape(r.text)));
        drop = r.drop;
    }
    Ok(out)
}

/// The item's class: its GOST line type (`contour`, `thin`, `vector`, `dashed`, `centre`),
/// or `fill` and `text` — so a test or a style sheet can pick one kind of line.
pub fn class_of(item: &Item) -> &'static str {
    match item {
        Item::Path { pen, .. } | Item::Circle { pen, filled: false, .. } => line_class(pen),
        Item::Circle { filled: true, .. } | Item::Fill { .. } => "fill",
        Item::Text(_) => "text",
    }
}

fn line_class(pen: &Pen) -> &'static str {
    match pen.line {
        LineType::Dashed => "dashed",
        LineType::DashDot => "centre",
        LineType::Solid if pen.width >= MAIN.width => "contour",
        LineType::Solid if pen.width >= VECTOR.width => "vector",
        LineType::Solid => "thin",
    }
}

/// An item's element, written at the end of `out` (a sheet has thousands: no string of
/// its own for each, nor for its numbers, path data or stroke).
fn item_element(out: &mut String, item: &Item, ink: &str) -> Result<(), BackendError> {
    let class = class_of(item);
    match item {
        Item::Path { path, pen } => {
            let _ = write!(out, "<path class=\"{class}\" d=\"");
            path_d(out, path)?;
            out.push_str("\" ");
            stroke_attrs(out, pen, ink)?;
            out.push_str("/>");
        }
        Item::Circle { c, r, pen, filled } => {
            let _ = write!(out, "<circle class=\"{class}\" cx=\"");
            for (k, x) in [c.x, c.y, *r].into_iter().enumerate() {
                push_num(out, x)?;
                out.push_str(["\" cy=\"", "\" r=\"", "\" "][k]);
            }
            if *filled {
                let _ = write!(out, "fill=\"{ink}\"");
            } else {
                stroke_attrs(out, pen, ink)?;
            }
            out.push_str("/>");
        }
        Item::Fill { path } => {
            let _ = write!(out, "<path class=\"{class}\" d=\"");
            path_d(out, path)?;
            let _ = write!(out, "\" fill=\"{ink}\"/>");
        }
        Item::Text(t) => out.push_str(&text_element(t, ink)?),
    }
    Ok(())
}

/// A group's or a part's SVG id: the sheet's name, a dot, its own id ("sheet1.plan.v.3").
pub fn element_id(scene: &Scene, id: &str) -> String {
    if scene.name.is_empty() { id.to_string() } else { format!("{}.{id}", scene.name) }
}

/// The ink as an SVG colour: `#000`, or `#rrggbb`.
fn colour(ink: Ink) -> String {
    match ink.rgb() {
        [0, 0, 0] => "#000".into(),
        [r, g, b] => format!("#{r:02x}{g:02x}{b:02x}"),
    }
}

/// Group `g` of `scene` as an SVG `<g>` element, its parts' elements nested in it, each
/// element on its own line.
fn group_element(scene: &Scene, g: &Group, ink: &str) -> Result<String, BackendError> {
    let mut s = String::new();
    let line = |s: &mut String, text: String| {
        s.push_str(&text);
        s.push('\n');
    };
    line(&mut s, format!("<g id=\"{}\">", escape(&element_id(scene, &g.id))));
    let mut parts = g.parts.iter().peekable();
    for (i, item) in g.items.iter().enumerate() {
        if let Some(p) = parts.peek().filter(|p| p.items.start == i) {
            line(&mut s, format!("<g id=\"{}\">", escape(&element_id(scene, &p.id))));
        }
        item_element(&mut s, item, ink).map_err(|e| match e {
            BackendError::NonFinite { value, .. } => {
                BackendError::NonFinite { group: g.id.clone(), value, item: format!("{item:?}") }
            }
            other => other,
        })?;
        s.push('\n');
        if parts.peek().is_some_and(|p| p.items.end == i + 1) {
            parts.next();
            line(&mut s, "</g>".into());
        }
    }
    line(&mut s, "</g>".into());
    Ok(s)
}

/// Serialises a scene as an SVG document sized in millimetres.
pub fn write(scene: &Scene) -> Result<String, BackendError> {
    work::count(Step::Svg);
    let mut s = String::with_capacity(1 << 20);
    let ink = colour(scene.ink);
    let (w, h) = (num(scene.width)?, num(scene.height)?);
    let line = |s: &mut String, text: String| {
        s.push_str(&text);
        s.push('\n');
    };
    line(
        &mut s,
        format!("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\">"),
    );
    line(&mut s, format!("<title>{}</title>", escape(&scene.title)));
    if scene.ink == Ink::Black {
        line(&mut s, format!("<rect width=\"{w}\" height=\"{h}\" fill=\"#fff\"/>"));
    }
    // Text set as the layout measured it, in any renderer: no kerning (the PDF and PNG place
    // glyphs by their advances) and every space kept (librsvg and resvg strip a tail run's
    // leading space without `xml:space`: "μP= 7,5 N/mm", "K( μP …").
    line(
        &mut s,
        format!(
            "<g style=\"font-kerning:none\" xml:space=\"preserve\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\" font-family=\"{}\" font-stretch=\"{}\">",
            font::FAMILY,
            font::STRETCH
        ),
    );
    // Each group written on its own (side by side on rayon's pool: a sheet's groups are
    // independent, and writing was a tenth of building sheet 1 after its composition), then
    // joined in scene order; the first group refused is the one reported.
    let groups: Vec<Result<String, BackendError>> =
        scene.groups.par_iter().map(|g| group_element(scene, g, &ink)).collect();
    for g in groups {
        s.push_str(&g?);
    }
    line(&mut s, "</g>\n</svg>".into());
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::scene::{Group, THIN};
    use kurbo::{Point, Rect};

    #[test]
    fn numbers_are_short_fixed_and_never_negative_zero() {
        assert_eq!(num(0.30000000000000004).unwrap(), "0.3");
        assert_eq!(num(-0.0).unwrap(), "0");
        assert_eq!(num(-0.0001).unwrap(), "0");
        assert_eq!(num(12.0).unwrap(), "12");
        assert_eq!(num(8.4666666).unwrap(), "8.467");
        assert_eq!(num(-3.1005).unwrap(), "-3.1"); // binary -3.1005 is just below the tie
        assert!(num(f64::NAN).is_err() && num(f64::INFINITY).is_err());
    }

    /// The shortcut past the formatter writes what the formatter writes: on ties and near
    /// ties of thousandths, whole numbers, tiny and large values of either sign.
    #[test]
    fn numbers_written_without_the_formatter_are_the_formatters() {
        let by_formatter = |x: f64| {
            let s = format!("{x:.DECIMALS$}");
            let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s };
            if s == "-0" { "0".to_string() } else { s }
        };
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut values = vec![0.0, -0.0, 0.0005, -0.0005, 0.0015, 2.5e-4, 1e-9, -1e-9, 999.9995, 1e11, -1e13];
        for k in -20_000..20_000 {
            values.push(f64::from(k) * 0.0005);
            values.push(f64::from(k) * 0.0001 + 1e-12);
        }
        for _ in 0..200_000 {
            let r = next();
            let scale = [1e-3, 1.0, 100.0, 1e4, 1e9][(r % 5) as usize];
            values.push(((r >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * scale);
            values.push(f64::from_bits(next()));
        }
        for x in values.into_iter().filter(|x| x.is_finite()) {
            assert_eq!(num(x).unwrap(), by_formatter(x), "{x:e}");
        }
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\">'"), "a&lt;b &amp; &quot;c&quot;&gt;&apos;");
    }

    fn scene(items: Vec<Item>) -> Scene {
        let mut g = Group::new("g", Rect::new(0.0, 0.0, 10.0, 10.0));
        g.items = items;
        Scene {
            ink: Default::default(),
            name: "s".into(),
            width: 10.0,
            height: 10.0,
            title: "t".into(),
            groups: vec![g],
        }
    }

    #[test]
    fn arcs_and_cubics_are_written_as_svg_commands() {
        let arc = Path::arc(Point::new(5.0, 5.0), 2.0, 0.0, -1.5 * PI);
        let cubic = Path::cubics(&[kurbo::CubicBez::new((0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0))]);
        let svg =
            write(&scene(vec![Item::Path { path: arc, pen: THIN }, Item::Path { path: cubic, pen: THIN }])).unwrap();
        assert!(svg.contains("d=\"M7 5A2 2 0 1 0 5 7\""), "{svg}");
        assert!(svg.contains("d=\"M0 0C1 2 3 2 4 0\""), "{svg}");
    }

    #[test]
    fn a_whole_circle_is_two_half_arcs_since_an_arc_to_its_start_draws_nothing() {
        let circle = Path::arc(Point::new(5.0, 5.0), 2.0, PI / 2.0, 2.0 * PI);
        let svg = write(&scene(vec![Item::Path { path: circle, pen: THIN }])).unwrap();
        assert!(svg.contains("d=\"M5 7A2 2 0 0 1 5 3A2 2 0 0 1 5 7\""), "{svg}");
    }

    #[test]
    fn parts_are_nested_groups_named_after_the_sheet_and_every_element_has_its_class() {
        let line = |w: f64| Item::Path {
            path: Path::polyline(&[Point::ZERO, Point::new(1.0, 1.0)], false),
            pen: Pen { width: w, ..THIN },
        };
        let mut g = Group::new("g", Rect::new(0.0, 0.0, 10.0, 10.0));
        g.items = vec![line(0.7), line(0.25), line(0.45)];
        g.part_from("a", 1);
        g.part_from("b", 0); // overlaps "a": nothing is left of it after "a"
        let svg = write(&Scene { groups: vec![g], ..scene(vec![]) }).unwrap();
        let body: Vec<&str> = svg.lines().skip(4).collect();
        assert_eq!(body[0], "<g id=\"s.g\">");
        assert!(body[1].starts_with("<path class=\"contour\""), "{svg}");
        assert_eq!(body[2], "<g id=\"s.a\">");
        assert!(body[3].starts_with("<path class=\"thin\"") && body[4].starts_with("<path class=\"vector\""));
        assert_eq!(&body[5..7], ["</g>", "</g>"]);
    }

    #[test]
    fn a_non_finite_number_is_refused_with_its_group() {
        let bad = Item::Circle { c: Point::new(f64::NAN, 1.0), r: 1.0, pen: THIN, filled: false };
        match write(&scene(vec![bad])) {
            Err(BackendError::NonFinite { group, .. }) => assert_eq!(group, "g"),
            other => panic!("{other:?}"),
        }
    }
}
