//! Texts that read as one phrase: two level texts of one size on one baseline, the second
//! starting about a word's space after the first ends, with no line between them. A teacher
//! read «S5 H = 288,6 mm» (a point's name beside a dimension's value) and «P_и3 G3 = 4,415 N»
//! as one phrase each; neither text crosses a line or the other, so the overlap and crossing
//! measures pass them.

use super::obstacles::Obstacles;
use super::scene::{Scene, Text};
use kurbo::Rect;

/// Texts closer than this many lettering heights, end to start, read as one phrase: a word
/// space of the sheet's font is about 0.35 of the height, and two texts are read apart only
/// with a clear gap of about three letters (at 1.2, «φ₁ = 150,0°  1», 3 mm apart in 2.5 mm
/// lettering, still read as one).
pub const APART: f64 = 2.0;
/// Baselines closer than this share of the height are one line.
const ONE_LINE: f64 = 0.4;
/// Texts whose letters' boxes share this much of the lower one's height are on one line too
/// (a 2.5 mm «S/H» 1.2 mm under a 3.5 mm «μP = 60 N/mm»'s baseline, reading as one line).
const SHARED: f64 = 0.75;
/// Heights within this ratio are one size (a subscript is 0.7 of its symbol).
const ONE_SIZE: f64 = 1.5;

/// The drawings whose numbers are positions' ([`numbers_point`]): elsewhere a number names
/// a link (a planetary stage's velocity picture's «0», «1», «H») or a value.
const POSITIONS_DRAWN: [&str; 3] = ["mechanism", "profile", "nomogram"];

/// Two texts that run together: their groups' ids, their plain texts and the gap between
/// them, mm.
#[derive(Debug, Clone, PartialEq)]
pub struct RunTogether {
    pub group: String,
    pub first: String,
    pub second: String,
    pub gap: f64,
    pub at: kurbo::Point,
}

/// Every pair of level texts of `scene` that run together, `strokes` the sheet's drawn lines
/// (a line between two texts parts them: a table's cell border).
pub fn run_together(scene: &Scene, strokes: &Obstacles) -> Vec<RunTogether> {
    // Each level text with its group, its letters' box and its words, found once.
    let mut texts: Vec<(&str, &Text, Rect, String)> = scene
        .groups
        .iter()
        .flat_map(|g| g.texts().filter(|t| t.rotate == 0.0).map(move |t| (g.id.as_str(), t, t.core_box(), t.plain())))
        .filter(|(.., words)| !words.trim().is_empty())
        .collect();
    // By baseline: a text's partners on its line are a short run of its neighbours (a
    // sheet has a thousand texts, and the measure runs for every sheet built).
    texts.sort_by(|a, b| a.1.at.y.total_cmp(&b.1.at.y));
    let mut out = Vec::new();
    for (k, (ga, a, ra, wa)) in texts.iter().enumerate() {
        let reach = ONE_SIZE * a.h;
        let from = texts.partition_point(|t| t.1.at.y < a.at.y - reach);
        for (j, (_, b, rb, wb)) in texts.iter().enumerate().skip(from) {
            if b.at.y > a.at.y + reach {
                break;
            }
            let h = a.h.min(b.h);
            let shared = ra.y1.min(rb.y1) - ra.y0.max(rb.y0);
            let one_line = (a.at.y - b.at.y).abs() <= ONE_LINE * h || shared >= SHARED * ra.height().min(rb.height());
            let gap = rb.x0 - ra.x1;
            if j == k || !one_line || rb.x0 <= ra.x0 || gap >= APART * h || gap < -0.5 * h {
                continue;
            }
            // The words read only for a pair close enough (a sheet has a thousand texts).
            let numbered = POSITIONS_DRAWN.contains(ga) && (numbers_point(wa, wb) || numbers_point(wb, wa));
            if !numbered && a.h.max(b.h) > ONE_SIZE * h {
                continue;
            }
            // Two statements side by side read as a list («λ₁ = −15,09  λ₂ = −4,669»), a
            // statement and a name as the name's value — unless brackets close the first
            // («K (μ_P = 4 N/mm)  T (…»: two details' captions).
            let phrase = !continues(wa, wb) && !closed(wa) && states_value(wa) != states_value(wb);
            if !phrase && !numbered {
                continue;
            }
            let between = Rect::new(ra.x1.min(rb.x0), ra.y0.max(rb.y0), ra.x1.max(rb.x0), ra.y1.min(rb.y1));
            if between.width() > 0.05 && strokes.segment_meets(between) {
                continue;
            }
            out.push(RunTogether { group: (*ga).to_string(), first: wa.clone(), second: wb.clone(), gap, at: a.at });
        }
    }
    // In the sheet's reading order, whatever the sort left of equal baselines.
    out.sort_by(|p, q| (p.at.y, p.at.x).partial_cmp(&(q.at.y, q.at.x)).unwrap_or(std::cmp::Ordering::Equal));
    out
}

/// Whether `b` written after `a` is meant as one phrase: punctuation says so (a sum's
/// "+ G_2", a list's "…;", an opened bracket).
fn continues(a: &str, b: &str) -> bool {
    let (end, start) = (a.trim_end(), b.trim_start());
    end.ends_with([';', ',', '(', ':', '=', '+', '−', '-', '·'])
        || start.starts_with(['+', '−', '-', '=', '(', ')', ',', ';', '·', '/'])
}

/// Whether `number` beside `name` reads as one designation with it: a position's number
/// a word's space from a point's letter, of any size («2 A», «O 11»: the guide's A₂, O₁₁).
fn numbers_point(number: &str, name: &str) -> bool {
    is_position_number(number) && is_point_name(name)
}

/// A position's number: digits and primes, or a run of them joined by «≡» («5′ ≡ 6»).
fn is_position_number(text: &str) -> bool {
    let text = text.trim();
    text.starts_with(|c: char| c.is_ascii_digit()) && text.chars().all(|c| c.is_ascii_digit() || "′≡ ".contains(c))
}

/// A point's name: a Latin letter and a short index, one word («A», «O1», «S2»; not a
/// Greek symbol's «ω»).
fn is_point_name(text: &str) -> bool {
    let text = text.trim();
    text.starts_with(|c: char| c.is_ascii_alphabetic())
        && text.chars().count() <= 3
        && text.chars().all(char::is_alphanumeric)
}

/// Whether `text` ends by closing a bracket: what it states stays inside it.
fn closed(text: &str) -> bool {
    text.trim_end().ends_with(')')
}

/// Whether `text` states a value ("H = 288,6 mm": a name, " = ", a value): a name beside
/// it reads as the value's.
pub fn states_value(text: &str) -> bool {
    text.contains(" = ")
}

/// The level texts among `texts` that state a value: those a text on their line keeps off.
pub fn level_statements<'a>(texts: impl Iterator<Item = &'a Text>) -> impl Iterator<Item = &'a Text> {
    texts.filter(|t| t.rotate == 0.0 && states_value(&t.plain()))
}

/// The bands beside the level statements among `texts` that another text, of lettering
/// `h` high or higher, keeps clear of ([`level_band`]; two texts run together within
/// [`APART`] of the smaller's height).
pub fn statement_bands<'a>(texts: impl Iterator<Item = &'a Text>, h: f64) -> impl Iterator<Item = Rect> {
    level_statements(texts).map(move |t| level_band(t.core_box(), APART * t.h.min(h)))
}

/// The room beside a text of lettering height `h` on its line that another keeps clear of,
/// where either states a value ([`run_together`] counts the pairs that do not), mm: the
/// band of the letters' middle half, `apart` wider on either side (a text above or below
/// on another line does not meet it).
pub fn level_band(letters: Rect, apart: f64) -> Rect {
    let quarter = letters.height() / 4.0;
    Rect::new(letters.x0 - apart, letters.y0 + quarter, letters.x1 + apart, letters.y1 - quarter)
}

#[cfg(test)]
mod tests {
    use crate::drawing::layout;
    use crate::drawing::scene::{Anchor, Item, MAIN, Text};
    use kurbo::Point;

    /// How many pairs run together in a scene of `texts` and the lines `lines`.
    fn counted(texts: &[Text], lines: &[(Point, Point)]) -> usize {
        let mut items: Vec<Item> = texts.iter().cloned().map(Item::Text).collect();
        let mut g = crate::drawing::scene::Group::new("g", kurbo::Rect::new(0.0, 0.0, 100.0, 100.0));
        for &(a, b) in lines {
            g.line(a, b, MAIN);
        }
        items.extend(g.items);
        // In a mechanism's drawing, where numbers are positions'.
        let mut scene = layout::tests::scene(items);
        scene.groups[0].id = "mechanism".into();
        layout::measure(&scene).texts_run_together
    }

    fn at(x: f64, y: f64, text: &str, h: f64) -> Text {
        Text::new(Point::new(x, y), text, h, Anchor::Start)
    }

    /// A name 2 or 5 mm after a statement on its baseline runs into it; 8 mm after, on
    /// another line, across a drawn line, or continuing it with punctuation, it does not; a
    /// name of 5 mm lettering beside a 3.5 mm statement still does (a teacher read «S5 H =
    /// 288,6 mm» as one phrase, and «φ₁ = 150,0° 1» at 3 mm in 2.5 mm lettering); two
    /// statements side by side read as a list.
    #[test]
    fn a_name_a_words_space_from_a_statement_runs_into_it() {
        let statement = at(10.0, 50.0, "H = 288,6 mm", 3.5);
        let end = statement.core_box().x1;
        let name = |gap: f64, dy: f64, h: f64| at(end + gap, 50.0 + dy, "S", h);
        assert_eq!(counted(&[statement.clone(), name(2.0, 0.0, 3.5)], &[]), 1);
        assert_eq!(counted(&[name(-30.0 - end, 0.0, 3.5), statement.clone()], &[]), 0, "far before it");
        assert_eq!(counted(&[statement.clone(), name(2.0, 0.0, 5.0)], &[]), 1, "a larger name");
        assert_eq!(counted(&[statement.clone(), name(5.0, 0.0, 3.5)], &[]), 1, "5 mm apart");
        assert_eq!(counted(&[statement.clone(), name(8.0, 0.0, 3.5)], &[]), 0, "8 mm apart");
        assert_eq!(counted(&[statement.clone(), name(2.0, 4.0, 3.5)], &[]), 0, "on the next line");
        let wall = (Point::new(end + 1.0, 40.0), Point::new(end + 1.0, 60.0));
        assert_eq!(counted(&[statement.clone(), name(2.0, 0.0, 3.5)], &[wall]), 0, "a cell's border between");
        let sum = at(end + 1.5, 50.0, "+ G", 3.5);
        assert_eq!(counted(&[statement.clone(), sum], &[]), 0, "a sum goes on");
        let names = [at(10.0, 50.0, "b", 3.5), at(13.0, 50.0, "a", 3.5)];
        assert_eq!(counted(&names, &[]), 0, "two points' names state no value");
        let list = at(end + 2.0, 50.0, "λ₂ = −4,669", 3.5);
        assert_eq!(counted(&[statement.clone(), list], &[]), 0, "two statements are a list");
        let caption = at(10.0, 50.0, "K (μ = 4 N/mm)", 3.5);
        let next = at(caption.core_box().x1 + 3.0, 50.0, "T (", 3.5);
        assert_eq!(counted(&[caption, next], &[]), 0, "a bracket closes a caption");
    }

    /// Texts of two sizes whose baselines differ by more than [`super::ONE_LINE`] of the
    /// smaller still stand on one line where their letters share most of its height: an
    /// axis's «S/H» (2.5 mm) 1.2 mm under the baseline of «μP = 60 N/mm» (3.5 mm), 3 mm
    /// after it, read as one line (the two-cylinder compressor's English sheet 1); 3 mm
    /// under it they do not.
    #[test]
    fn a_smaller_text_whose_letters_share_a_lines_height_stands_on_it() {
        let name = at(10.0, 50.0, "S/H", 2.5);
        let statement = |dy: f64| {
            let mu = at(name.core_box().x1 + 3.0, 50.0 - dy, "μ", 3.5);
            Text { sub: "P".into(), tail: " = 60 N/mm".into(), ..mu }
        };
        assert_eq!(counted(&[name.clone(), statement(1.2)], &[]), 1);
        assert_eq!(counted(&[name.clone(), statement(0.0)], &[]), 1, "on its baseline");
        assert_eq!(counted(&[name.clone(), statement(3.0)], &[]), 0, "a line higher");
    }

    /// A position's number a word's space from a point's letter, before or after it, reads
    /// as the letter's index whatever their sizes («2 A», «O 11»: a teacher read a crank's
    /// «2» 1.8 mm before «A» as A₂); 8 mm off it, or beside another number, a tick's value or
    /// a name that is not a point's, it does not.
    #[test]
    fn a_position_number_beside_a_points_letter_reads_as_its_index() {
        let letter = |x: f64, name: &str| at(x, 50.0, name, 5.0);
        let number = |x: f64, text: &str, h: f64| at(x, 50.0, text, h);
        let after = |name: &Text, gap: f64| name.core_box().x1 + gap;
        let a = letter(10.0, "A");
        assert_eq!(counted(&[a.clone(), number(after(&a, 1.8), "2", 2.5)], &[]), 1, "«A 2»");
        assert_eq!(counted(&[a.clone(), number(after(&a, 4.0), "5′ ≡ 6", 3.5)], &[]), 1, "a joined run");
        assert_eq!(counted(&[a.clone(), number(after(&a, 8.0), "2", 3.5)], &[]), 0, "8 mm off");
        let two = number(10.0, "11", 3.5);
        assert_eq!(counted(&[two.clone(), letter(after(&two, 1.5), "O1")], &[]), 1, "«11 O1»");
        assert_eq!(counted(&[two.clone(), number(after(&two, 1.5), "4", 2.5)], &[]), 0, "two numbers");
        assert_eq!(counted(&[two.clone(), letter(after(&two, 1.5), "S/H")], &[]), 0, "an axis's name");
        let tick = number(10.0, "0,5", 2.5);
        assert_eq!(counted(&[tick.clone(), letter(after(&tick, 1.5), "P")], &[]), 0, "a tick's value");
        let link = number(10.0, "0", 3.5);
        let mut picture =
            layout::tests::scene(vec![Item::Text(link.clone()), Item::Text(letter(after(&link, 1.5), "H"))]);
        picture.groups[0].id = "planetary".into();
        assert_eq!(layout::measure(&picture).texts_run_together, 0, "a link's number in a velocity picture");
    }
}
