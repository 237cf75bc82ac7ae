//! Symbols with subscripts (v_BA, ω₂, aⁿ_BA) as one scene text each, so that every backend
//! sets the subscript after its symbol with its own font; wrapping and fitting text to cells.

use super::scene::{Anchor, Group, Text};
use crate::font;
use kurbo::{Point, Rect};

/// Labels of points that are one point to the reader merged: each label that is `same` as an
/// earlier kept one is appended to it after `joiner` ("0≡17", "10 ≡ 11") and gets none of its
/// own (`None` at its index).
pub fn merged_labels(
    labels: impl IntoIterator<Item = String>,
    same: impl Fn(usize, usize) -> bool,
    joiner: &str,
) -> Vec<Option<String>> {
    let mut out: Vec<Option<String>> = Vec::new();
    for (k, label) in labels.into_iter().enumerate() {
        match (0..k).find(|&j| out[j].is_some() && same(j, k)) {
            Some(j) => {
                if let Some(first) = out[j].as_mut() {
                    first.push_str(joiner);
                    first.push_str(&label);
                }
                out.push(None);
            }
            None => out.push(Some(label)),
        }
    }
    out
}

/// A symbol and an optional subscript, e.g. ("v", "BA").
#[derive(Debug, Clone, PartialEq)]
pub struct LabelText {
    pub main: String,
    pub sub: String,
    /// Text after the subscript, at the symbol's size (" = 0,005 m/mm").
    pub tail: String,
    /// Further subscripts with the text after each ([`Text::then`]).
    pub then: Vec<(String, String)>,
}

impl LabelText {
    pub fn new(main: impl Into<String>, sub: impl Into<String>) -> LabelText {
        LabelText { main: main.into(), sub: sub.into(), tail: String::new(), then: Vec::new() }
    }

    pub fn with_tail(mut self, tail: impl Into<String>) -> LabelText {
        self.tail = tail.into();
        self
    }

    /// The same label with further subscripts and their tails ([`Text::then`]).
    pub fn with_then(mut self, then: Vec<(String, String)>) -> LabelText {
        self.then = then;
        self
    }

    /// Whether any run is a subscript (it hangs below the baseline).
    pub fn has_sub(&self) -> bool {
        !self.sub.is_empty() || self.then.iter().any(|(s, _)| !s.is_empty())
    }

    /// The label's characters in order, subscripts unmarked ("d=s4=s5").
    pub fn chars_in_order(&self) -> String {
        let mut out = format!("{}{}{}", self.main, self.sub, self.tail);
        for (s, t) in &self.then {
            out.push_str(s);
            out.push_str(t);
        }
        out
    }

    /// Width of the symbol, subscript and tail at lettering height `h`, mm.
    pub fn width(&self, h: f64) -> f64 {
        self.text(Point::ZERO, h, Anchor::Start).advance()
    }

    /// The label as one scene text with its baseline at `at`, anchored by `anchor`.
    pub fn text(&self, at: Point, h: f64, anchor: Anchor) -> Text {
        Text::new(at, self.main.clone(), h, anchor)
            .with_sub(self.sub.clone(), self.tail.clone())
            .with_then(self.then.clone())
    }

    /// Draws the label with its baseline at `at.y`, anchored horizontally by `anchor`;
    /// returns the bounding box of what it drew.
    pub fn draw(&self, g: &mut Group, at: Point, h: f64, anchor: Anchor) -> Rect {
        let t = self.text(at, h, anchor);
        let bb = t.bbox();
        g.text(t);
        bb
    }
}

pub use super::scene::SUB;

/// Line pitch of wrapped text, in lettering heights.
pub const LINE_PITCH: f64 = 1.6;

/// Breaks `text` into lines no wider than `width` mm at lettering height `h`: at white space,
/// and inside a word that is wider than a line by itself. Linear in the text's length (each
/// character is measured once).
pub fn wrap(text: &str, h: f64, width: f64) -> Vec<String> {
    let m = font::metrics();
    let size = font::size_for_cap(h);
    let room = width - SLANT * h;
    let space = m.width(" ", size);
    let mut lines = Vec::new();
    let (mut cur, mut cur_w) = (String::new(), 0.0);
    let mut queue: std::collections::VecDeque<String> = units(text).into();
    while let Some(word) = queue.pop_front() {
        let word = word.as_str();
        let word_w = m.width(word, size);
        // Words kept together that no line holds ("7 mm uzunlikda": a number with its unit,
        // the unit, two letters, with the next word) give up their last word first, rather
        // than be broken between letters.
        if let Some((head, last)) = word.rsplit_once(' ').filter(|_| word_w > room) {
            queue.push_front(last.to_string());
            queue.push_front(head.to_string());
            continue;
        }
        if !cur.is_empty() && cur_w + space + word_w <= room {
            cur.push(' ');
            cur.push_str(word);
            cur_w += space + word_w;
            continue;
        }
        if !cur.is_empty() {
            lines.push(std::mem::take(&mut cur));
        }
        if word_w <= room {
            (cur, cur_w) = (word.to_string(), word_w);
            continue;
        }
        // A word wider than a line: broken after its hyphens ("Кривошипно-" over
        // "ползунный"), and a piece still wider between characters.
        cur_w = 0.0;
        for piece in pieces(word) {
            let piece_w = m.width(piece, size);
            if !cur.is_empty() && cur_w + piece_w > room {
                lines.push(std::mem::take(&mut cur));
                cur_w = 0.0;
            }
            if piece_w <= room {
                cur.push_str(piece);
                cur_w += piece_w;
                continue;
            }
            for c in piece.chars() {
                let cw = m.width(c.encode_utf8(&mut [0; 4]), size);
                if !cur.is_empty() && cur_w + cw > room {
                    lines.push(std::mem::take(&mut cur));
                    cur_w = 0.0;
                }
                cur.push(c);
                cur_w += cw;
            }
        }
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    keep_last_word_company(&mut lines, |l| m.width(l, size) <= room);
    lines
}

/// A word's pieces a line may end after: up to and including each hyphen.
fn pieces(word: &str) -> std::str::SplitInclusive<'_, char> {
    word.split_inclusive('-')
}

/// A caption's head, its number through the title's first word ("Таблица 5 – Уравновешивающая",
/// GOST 2.105 puts them on one line), when `text` begins as a caption does.
pub fn caption_head(text: &str) -> Option<String> {
    units(text).into_iter().next().filter(|unit| unit.contains(" – "))
}

/// The words of `text` as wrapping sees them: a one- or two-letter word (a preposition or
/// conjunction: "в", "и", "da") goes to the next line with the word after it, as Russian
/// typesetting asks ("длины в" over "мм" reads as if the unit were lost), and so does a
/// number: "7" at a line's end over "mm" parts a length from its unit. A unit in brackets
/// goes with the word before it.
fn units(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut glue = false;
    for word in text.split_whitespace() {
        // A unit in brackets stays with the word before it: "(Н)" alone on a title's last
        // line reads as a stray mark.
        let unit = word.starts_with('(') && word.ends_with(')') && word.chars().count() <= 8;
        // A dash does not begin a line (Russian and Uzbek typography): it stays with the
        // word before it.
        let dash = matches!(word, "—" | "–");
        match out.last_mut() {
            Some(last) if glue || unit || dash => {
                last.push(' ');
                last.push_str(word);
            }
            _ => out.push(word.to_string()),
        }
        let short_word = word.chars().count() <= 2 && word.chars().all(char::is_alphabetic);
        // A number ends in a digit: "5." ends a clause.
        let number = word.ends_with(|c: char| c.is_ascii_digit())
            && word.chars().all(|c| c.is_ascii_digit() || matches!(c, ',' | '.' | '−' | '-' | '+'));
        // A caption's dash ("Таблица 9 – Результаты", GOST 2.105) holds the title's first
        // word too: its number alone over the title reads as a stray line.
        let caption = dash && out.len() <= 2;
        glue = short_word || number || caption;
    }
    // And its word before the number: "Таблица" alone over "5 – Уравновешивающая".
    if out.len() >= 2 && out[1].contains(" – ") && out[1].starts_with(|c: char| c.is_ascii_digit()) {
        let head = out.remove(0);
        out[0] = format!("{head} {}", out[0]);
    }
    out
}

/// A paragraph's last line of one word (a widow: "значения" alone under a full line) takes
/// the word before it along, when that fits and leaves the line above two words or more.
/// Words are [`units`]: a preposition moves with its word.
fn keep_last_word_company(lines: &mut [String], fits: impl Fn(&str) -> bool) {
    let [.., above, last] = lines else { return };
    let words = units(above);
    let ([kept @ .., moved], 1) = (words.as_slice(), units(last).len()) else { return };
    if kept.len() < 2 {
        return;
    }
    let joined = format!("{moved} {last}");
    if fits(&joined) {
        *above = kept.join(" ");
        *last = joined;
    }
}

/// The slant of GOST type B lettering adds this much width per unit of height (tan 15°).
pub const SLANT: f64 = 0.27;

/// GOST 2.304 lettering heights, mm, largest first.
pub const SIZES: [f64; 6] = [14.0, 10.0, 7.0, 5.0, 3.5, 2.5];

/// A user's text that does not fit where the sheet prints it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "{field}: \"{excerpt}\" ({chars} characters) does not fit the {place} ({w:.0} × {h:.0} mm) even condensed or wrapped in the smallest lettering; shorten it"
)]
pub struct TooLong {
    pub field: String,
    pub excerpt: String,
    pub chars: usize,
    pub place: String,
    pub w: f64,
    pub h: f64,
}

impl TooLong {
    pub fn new(field: &str, text: &str, place: &str, (w, h): (f64, f64)) -> TooLong {
        let chars = text.chars().count();
        let mut excerpt: String = text.chars().take(40).collect();
        if chars > 40 {
            excerpt.push('…');
        }
        TooLong { field: field.into(), excerpt, chars, place: place.into(), w, h }
    }
}

/// Text set to fit a cell: its lines and their lettering height.
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    pub lines: Vec<String>,
    pub h: f64,
    /// Width factor of the letters (1, or down to [`NARROWEST`] for a long name).
    pub stretch: f64,
}

impl Fitted {
    /// Height of the block from the first line's capitals to the last line's descenders.
    pub fn height(&self) -> f64 {
        block_height(self.lines.len(), self.h)
    }
}

/// Height of `n` lines at lettering height `h` (capitals to descenders).
pub fn block_height(n: usize, h: f64) -> f64 {
    if n == 0 { 0.0 } else { (n - 1) as f64 * LINE_PITCH * h + 1.3 * h }
}

/// `text` in a `w` × `ht` mm cell (the room for the letters themselves): on one line at the
/// largest GOST height from `h_max` down to 2.5 mm that fits, else wrapped (at spaces and
/// hyphens) at the largest such height whose lines fit, else on one line condensed (at 2.5
/// mm, then 1.8 mm, to [`NARROWEST`]), else wrapped with a word broken between letters;
/// `None` when none of these fits.
pub fn fit(text: &str, w: f64, ht: f64, h_max: f64) -> Option<Fitted> {
    let sizes = || SIZES.into_iter().filter(move |&h| h <= h_max);
    let m = font::metrics();
    // A text far too long for the cell is refused without measuring it at every size.
    let least = m.width(text, font::size_for_cap(2.5));
    let lines_at_least = (ht / (LINE_PITCH * 2.5)).floor().max(1.0);
    // (Condensed at 1.8 mm a line holds 2.5/1.8/NARROWEST ≈ 2 times its 2.5 mm width.)
    let widest = 2.5 / CONDENSED_SMALLEST / NARROWEST;
    if least > lines_at_least * w * widest.max(1.5) {
        return None;
    }
    for h in sizes() {
        if block_height(1, h) <= ht && m.width(text, font::size_for_cap(h)) + SLANT * h <= w {
            return Some(Fitted { lines: vec![text.to_string()], h, stretch: 1.0 });
        }
    }
    // Wrapped at white space and hyphens at the largest height that needs no word broken
    // between letters ("ползу" over "нный" reads as two words).
    let whole_words = |h: f64| {
        let room = w - SLANT * h;
        text.split_whitespace().flat_map(pieces).all(|p| m.width(p, font::size_for_cap(h)) <= room)
    };
    let wrapped = sizes()
        .filter(|&h| whole_words(h))
        .map(|h| Fitted { lines: wrap(text, h, w), h, stretch: 1.0 })
        .find(|f| f.height() <= ht);
    if wrapped.is_some() {
        return wrapped;
    }
    // Condensed on one line, at 2.5 mm and then at GOST 2.304's 1.8 mm, when wrapping does not
    // fit (a 5 mm cell): a surname with its initials keeps its line in a 23 mm cell.
    for h in [2.5, CONDENSED_SMALLEST].into_iter().filter(|&h| h <= h_max) {
        let natural = m.width(text, font::size_for_cap(h));
        let room = w - SLANT * h;
        if block_height(1, h) <= ht && natural > 0.0 && room / natural >= NARROWEST {
            // Down to the hundredth, so the condensed line is never wider than its room.
            let stretch = ((room / natural) * 100.0).floor() / 100.0;
            return Some(Fitted { lines: vec![text.to_string()], h, stretch });
        }
    }
    sizes().map(|h| Fitted { lines: wrap(text, h, w), h, stretch: 1.0 }).find(|f| f.height() <= ht)
}

/// The narrowest a fitted text's letters are set: GOST 2.304's narrow type A against the
/// type B the sheets use, about 0.7 of the width.
pub const NARROWEST: f64 = 0.7;
/// GOST 2.304's smallest lettering, used only condensed for a name that fits no other way.
const CONDENSED_SMALLEST: f64 = 1.8;

/// Draws wrapped lines starting with the first baseline at `at`, line pitch 1.6·h;
/// returns the y of the next free line.
pub fn paragraph(g: &mut Group, at: Point, lines: &[String], h: f64, anchor: Anchor) -> f64 {
    paragraph_stretched(g, at, lines, (h, 1.0), anchor)
}

/// [`paragraph`] with the letters' width factor: (lettering height, stretch).
pub fn paragraph_stretched(
    g: &mut Group,
    at: Point,
    lines: &[String],
    (h, stretch): (f64, f64),
    anchor: Anchor,
) -> f64 {
    let mut y = at.y;
    for line in lines {
        g.text(Text::new(Point::new(at.x, y), line.clone(), h, anchor).with_stretch(stretch));
        y += LINE_PITCH * h;
    }
    y
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A last line of one word takes the word before it along; the words keep their order
    /// and every line its width.
    /// A hyphenated word wider than its line breaks after the hyphen, and `fit` takes a smaller
    /// height rather than break a word between letters (the title block's "Кривошипно-ползу" /
    /// "нный механизм").
    #[test]
    fn long_words_break_after_their_hyphens_not_between_letters() {
        let word = "Кривошипно-ползунный";
        let w = font::metrics().width(word, font::size_for_cap(3.5)) * 0.8;
        assert_eq!(wrap(word, 3.5, w), ["Кривошипно-", "ползунный"]);
        let text = "Кривошипно-ползунный механизм";
        let f = fit(text, w, 12.0, 3.5).expect("fits");
        let whole = ["Кривошипно-ползунный", "Кривошипно-", "ползунный", "механизм"];
        assert!(f.lines.iter().flat_map(|l| l.split_whitespace()).all(|t| whole.contains(&t)), "{:?}", f.lines);
        assert_eq!(f.lines.concat().replace(' ', ""), text.replace(' ', ""));
    }

    #[test]
    fn a_short_word_goes_to_the_next_line_with_its_word() {
        let text = "Параметры внешнего зацепления (длины в мм, продолжение)";
        for width in [30.0, 40.0, 50.0, 60.0, 80.0] {
            let lines = wrap(text, 2.5, width);
            assert!(lines.iter().all(|l| !l.ends_with(" в")), "{lines:?} at {width} mm");
            assert_eq!(lines.join(" "), text);
        }
    }

    /// A number stays with its unit ("7" at a line's end over "mm" parts a length from its
    /// unit), but a numbered caption's "5." may end a line.
    #[test]
    fn a_number_goes_to_the_next_line_with_its_unit() {
        let text = "* kuch strelkalari masshtabida 7 mm dan qisqa: strelka 7 mm uzunlikda chizilgan";
        for width in (30..=120).step_by(5) {
            let lines = wrap(text, 3.5, width as f64);
            assert!(lines.iter().all(|l| !l.ends_with(" 7") && !l.starts_with("mm")), "{lines:?} at {width} mm");
            assert_eq!(lines.join(" "), text);
        }
        assert_eq!(units("Таблица 5. Уравновешивающая сила")[1], "5.");
        assert_eq!(units("Таблица 5 – Уравновешивающая сила"), ["Таблица 5 – Уравновешивающая", "сила"]);
        assert_eq!(units("y = 0,06 m, 12 N·m"), ["y =", "0,06 m,", "12 N·m"]);
    }

    /// Table 5's signed title broke before its dash: "— harakatlantiruvchi)" began a line.
    #[test]
    fn a_dash_never_begins_a_line() {
        let text = "5-jadval – Muvozanatlovchi kuch («+» — harakatlantiruvchi)";
        for width in (50..=120).step_by(2) {
            let lines = wrap(text, 3.5, width as f64);
            assert!(lines.iter().all(|l| !l.starts_with('—')), "{lines:?} at {width} mm");
            assert_eq!(lines.join(" "), text);
        }
    }

    /// A caption's number, dash and first word make one line (GOST 2.105): never "5-jadval –"
    /// alone over its title.
    #[test]
    fn a_captions_number_stays_with_its_title() {
        let cases = [
            ("5-jadval – Muvozanatlovchi kuch", "5-jadval – Muvozanatlovchi"),
            ("Таблица 13 – Результаты", "Таблица 13 – Результаты"),
            ("Table 2 – Accelerations (m/s²) and angular ones", "Table 2 – Accelerations (m/s²)"),
        ];
        let head_w = |s: &str| font::metrics().width(s, font::size_for_cap(3.5)) + SLANT * 3.5;
        for (text, head) in cases {
            assert_eq!(caption_head(text).as_deref(), Some(head));
            // A table widens its title to the head's width (Table::title_lines).
            for width in (20..=120).step_by(5) {
                let lines = wrap(text, 3.5, head_w(head).max(width as f64));
                assert!(lines.iter().any(|l| l.contains(head)), "{lines:?} at {width} mm");
            }
        }
        assert_eq!(caption_head("Qalin chiziq — vatarlar"), None);
    }

    /// Russian table 4's title ended in "(Н)" alone on its third line.
    #[test]
    fn a_unit_in_brackets_stays_with_its_word() {
        let text = "Таблица 4 – Реакции в кинематических парах (Н)";
        for width in (45..=90).step_by(5) {
            let lines = wrap(text, 3.5, width as f64);
            assert!(lines.iter().all(|l| !l.starts_with('(')), "{lines:?} at {width} mm");
            assert_eq!(lines.join(" "), text);
        }
    }

    #[test]
    fn wrapping_leaves_no_word_alone_on_the_last_line() {
        let h = 2.5;
        let width = |s: &str| font::metrics().width(s, font::size_for_cap(h)) + SLANT * h;
        let text = "one two three four five six seven";
        let lines = wrap(text, h, width("one two three four five six") + 0.01);
        assert_eq!(lines, ["one two three four five", "six seven"]);
        for w in [20.0, 30.0, 45.0, 60.0] {
            let long = "Thick line — graphical (chord) integration (8 divisions), thin — the exact law";
            let lines = wrap(long, h, w);
            assert_eq!(lines.join(" "), long, "{w}");
            assert!(lines.iter().all(|l| width(l) <= w + 1e-9), "{w}: {lines:?}");
        }
        // Two words: nothing to take along.
        assert_eq!(wrap("alpha beta", h, width("alpha") + 0.01), ["alpha", "beta"]);
    }
}
