//! A small deterministic SVG writer: fixed decimals, `-0` written as `0`, XML escaping,
//! elements in scene order with the groups' stable ids. No timestamps, no randomness.

use super::BackendError;
use crate::drawing::scene::{Anchor, Item, LineType, Pen, Scene, Text};
use crate::font;
use kurbo::Point;
use std::fmt::Write;

/// Digits after the decimal point for paper millimetres (1 µm).
const DECIMALS: usize = 3;

/// Formats a number with at most `DECIMALS` (3) decimals, no trailing zeros, no `-0`.
pub fn num(x: f64) -> String {
    debug_assert!(x.is_finite(), "non-finite coordinate in the scene");
    let x = if x.is_finite() { x } else { 0.0 };
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
    s
}

pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

fn stroke_attrs(pen: &Pen) -> String {
    let dash = match pen.line {
        LineType::Solid => String::new(),
        LineType::Dashed => " stroke-dasharray=\"4 1.5\"".into(),
        LineType::DashDot => " stroke-dasharray=\"10 1.5 0.5 1.5\"".into(),
    };
    format!("stroke=\"#000\" stroke-width=\"{}\"{dash}", num(pen.width))
}

fn points_d(pts: &[Point], closed: bool) -> String {
    let mut d = String::new();
    for (i, p) in pts.iter().enumerate() {
        let _ = write!(d, "{}{} {}", if i == 0 { "M" } else { "L" }, num(p.x), num(p.y));
    }
    if closed {
        d.push('Z');
    }
    d
}

fn text_element(t: &Text) -> String {
    let anchor = match t.anchor {
        Anchor::Start => "",
        Anchor::Middle => " text-anchor=\"middle\"",
        Anchor::End => " text-anchor=\"end\"",
    };
    let (x, y) = (num(t.at.x), num(t.at.y));
    let mut transform = String::new();
    if t.rotate != 0.0 || t.sloped {
        transform.push_str(&format!(" transform=\"translate({x} {y})"));
        if t.rotate != 0.0 {
            transform.push_str(&format!(" rotate({})", num(-t.rotate)));
        }
        if t.sloped {
            transform.push_str(" skewX(-15)");
        }
        transform.push('"');
    }
    let (x, y) = if transform.is_empty() { (x, y) } else { ("0".into(), "0".into()) };
    format!(
        "<text x=\"{x}\" y=\"{y}\" font-size=\"{}\"{anchor}{transform}>{}</text>",
        num(font::size_for_cap(t.h)),
        escape(&t.text)
    )
}

/// Serialises a scene as an SVG document sized in millimetres.
pub fn write(scene: &Scene) -> Result<String, BackendError> {
    for g in &scene.groups {
        for item in &g.items {
            let bb = item.bbox();
            for value in [bb.x0, bb.y0, bb.x1, bb.y1] {
                if !value.is_finite() {
                    return Err(BackendError::NonFinite { group: g.id.clone(), value, item: format!("{item:?}") });
                }
            }
        }
    }
    let mut s = String::with_capacity(1 << 20);
    let (w, h) = (num(scene.width), num(scene.height));
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\">"
    );
    let _ = writeln!(s, "<title>{}</title>", escape(&scene.title));
    let _ = writeln!(s, "<rect width=\"{w}\" height=\"{h}\" fill=\"#fff\"/>");
    let _ = writeln!(
        s,
        "<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\" font-family=\"{}\" font-stretch=\"{}\">",
        font::FAMILY,
        font::STRETCH
    );
    for g in &scene.groups {
        let _ = writeln!(s, "<g id=\"{}\">", escape(&g.id));
        for item in &g.items {
            write_item(&mut s, item);
        }
        s.push_str("</g>\n");
    }
    s.push_str("</g>\n</svg>\n");
    Ok(s)
}

fn write_item(s: &mut String, item: &Item) {
    let _ = match item {
        Item::Path { pts, closed, pen } => {
            writeln!(s, "<path d=\"{}\" {}/>", points_d(pts, *closed), stroke_attrs(pen))
        }
        Item::Circle { c, r, pen, filled } => {
            let paint = if *filled { "fill=\"#000\"".to_string() } else { stroke_attrs(pen) };
            writeln!(s, "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {paint}/>", num(c.x), num(c.y), num(*r))
        }
        Item::Fill { pts } => writeln!(s, "<path d=\"{}\" fill=\"#000\"/>", points_d(pts, true)),
        Item::Text(t) => writeln!(s, "{}", text_element(t).replacen("<text ", "<text fill=\"#000\" ", 1)),
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_fixed_and_never_negative_zero() {
        assert_eq!(num(0.30000000000000004), "0.3");
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(-0.0001), "0");
        assert_eq!(num(12.0), "12");
        assert_eq!(num(8.4666666), "8.467");
        assert_eq!(num(-3.1005), "-3.1"); // binary -3.1005 is just below the tie
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
    }
}
