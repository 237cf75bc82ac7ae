//! Notes set on a drawing's field in columns no wider than GOST 2.316 allows: a sheet's
//! notes run under a drawing as wide as half the sheet, and one line 380 mm long is hard to
//! follow and is not what the standard draws. Where the room is wide enough for two or more
//! 185 mm columns the paragraphs flow from one column into the next, balanced so that the
//! columns end as level as the lines allow (which also makes the notes lower).

use super::scene::{Anchor, Group, Text};
use super::text::{LINE_PITCH, wrap};
use kurbo::Point;

/// GOST 2.316: text on a drawing's field is set in columns at most 185 mm wide.
pub const COLUMN_MAX: f64 = 185.0;

/// Between two columns, mm.
pub const COLUMN_GAP: f64 = 10.0;

/// One paragraph of the notes.
#[derive(Debug, Clone)]
pub struct Para {
    pub text: String,
    /// Space after its last line, mm.
    pub after: f64,
    /// A heading ("Assumed:"): it does not end a column.
    pub keep_with_next: bool,
}

impl Para {
    pub fn new(text: impl Into<String>, after: f64) -> Para {
        Para { text: text.into(), after, keep_with_next: false }
    }

    pub fn heading(text: impl Into<String>, after: f64) -> Para {
        Para { keep_with_next: true, ..Para::new(text, after) }
    }
}

/// The notes set: every line with its place from the notes' top left (the first line's
/// baseline at 0), and the notes' height: from the first baseline to where a line after the
/// tallest column's last (its paragraph's space after included) would stand.
#[derive(Debug, Clone, Default)]
pub struct Set {
    pub lines: Vec<(Point, String)>,
    pub height: f64,
}

/// How many columns `width` mm is set in, and their width: the fewest at most
/// [`COLUMN_MAX`] wide that fill it but for a tenth of a column (300 mm: two of 145 mm,
/// where one of 185 mm left a third of the room empty and made the notes half again as
/// tall; 390 mm: two of 185 mm, not three of 123 mm).
pub fn columns(width: f64) -> (usize, f64) {
    let n = (((width + COLUMN_GAP) / (COLUMN_MAX + COLUMN_GAP) - 0.1).ceil() as usize).max(1);
    (n, ((width - (n - 1) as f64 * COLUMN_GAP) / n as f64).min(COLUMN_MAX))
}

/// One wrapped line: its text, the pitch to the next line (with the paragraph's space after
/// its last), and whether a column may end after it.
struct Line {
    text: String,
    advance: f64,
    breakable: bool,
    /// The last line of its paragraph.
    ends_para: bool,
}

/// Notes of at most this many lines in one column stay in one: a block that short reads at
/// a glance, and in two columns it scatters into one- and two-line scraps (the kulisa's
/// sheet 1: its exactness note alone on the left, the assumption 200 mm to its right).
pub const SHORT_LINES: usize = 4;

/// Sets `paras` at lettering height `h` in as many columns as `width` mm hold, or in one
/// where they are [`SHORT_LINES`] lines or fewer in it. Columns end between paragraphs
/// where that costs at most a line of height and leaves no column of one line; else notes
/// of at most twice [`SHORT_LINES`] lines stay in one column, and only longer ones have a
/// column end inside a paragraph: a sentence cut at a column's foot and taken up at the
/// next one's head reads as two notes (the worked example's assumption, "…из всех
/// вариантов" at the left's foot, "именно этот…" at the right's head).
pub fn set(paras: &[Para], h: f64, width: f64) -> Set {
    let (n, col_w) = columns(width);
    let one_w = width.min(COLUMN_MAX);
    let one_lines = lines_of(paras, h, one_w);
    let one_column = || placed(&one_lines, &[0], one_w);
    if n == 1 || one_lines.len() <= SHORT_LINES {
        return one_column();
    }
    let lines = lines_of(paras, h, col_w);
    let anywhere = placed(&lines, &balanced_starts(&lines, n, &|l| l.breakable), col_w);
    let pitch = LINE_PITCH * h;
    let between_starts = balanced_starts(&lines, n, &|l| l.breakable && l.ends_para);
    let ends = between_starts.iter().skip(1).copied().chain([lines.len()]);
    let lone = between_starts.iter().zip(ends).any(|(&from, to)| to - from < 2);
    let between = placed(&lines, &between_starts, col_w);
    if !lone && between.height <= anywhere.height + pitch + 1e-9 {
        return between;
    }
    if one_lines.len() <= 2 * SHORT_LINES { one_column() } else { anywhere }
}

/// `paras` wrapped at height `h` in a column `col_w` wide, line by line.
fn lines_of(paras: &[Para], h: f64, col_w: f64) -> Vec<Line> {
    let pitch = LINE_PITCH * h;
    let mut lines = Vec::new();
    for p in paras {
        let wrapped = wrap(&p.text, h, col_w);
        let last = wrapped.len().saturating_sub(1);
        for (i, text) in wrapped.into_iter().enumerate() {
            let end = i == last;
            // A paragraph's single line is not left alone at a column's foot or head.
            let breakable = if end { !p.keep_with_next } else { i >= 1 && last - i >= 2 };
            lines.push(Line { text, advance: pitch + if end { p.after } else { 0.0 }, breakable, ends_para: end });
        }
    }
    lines
}

/// `lines` placed in columns `col_w` wide, each column starting at its index in `starts`.
fn placed(lines: &[Line], starts: &[usize], col_w: f64) -> Set {
    let mut set = Set::default();
    for (c, range) in starts.iter().zip(starts.iter().skip(1).chain([&lines.len()])).enumerate() {
        let (from, to) = (*range.0, *range.1);
        let x = c as f64 * (col_w + COLUMN_GAP);
        let mut y = 0.0;
        for line in &lines[from..to] {
            set.lines.push((Point::new(x, y), line.text.clone()));
            y += line.advance;
        }
        set.height = set.height.max(y);
    }
    set
}

/// Where each column starts (line indices, the first 0): the lowest greatest column height
/// with which the lines, broken only after those `may_end` allows, fill at most `n` columns
/// in order.
fn balanced_starts(lines: &[Line], n: usize, may_end: &dyn Fn(&Line) -> bool) -> Vec<usize> {
    let total: f64 = lines.iter().map(|l| l.advance).sum();
    let mut best = vec![0];
    if n < 2 || lines.len() < 2 {
        return best;
    }
    // Candidate heights: every prefix's height, lowest first; the first that fits is the
    // most level.
    let mut prefix = 0.0;
    let mut candidates: Vec<f64> = Vec::with_capacity(lines.len());
    for l in lines {
        prefix += l.advance;
        candidates.push(prefix);
    }
    for &limit in candidates.iter().filter(|&&c| c * n as f64 >= total - 1e-9) {
        if let Some(starts) = fill(lines, n, limit, may_end) {
            best = starts;
            break;
        }
    }
    best
}

/// Fills columns in order, each up to `limit` mm of advances, breaking after the last line
/// that fits and `may_end` allows; None when more than `n` columns are needed.
fn fill(lines: &[Line], n: usize, limit: f64, may_end: &dyn Fn(&Line) -> bool) -> Option<Vec<usize>> {
    let mut starts = vec![0];
    let mut from = 0;
    while from < lines.len() {
        let mut used = 0.0;
        let mut cut = None;
        for (k, l) in lines.iter().enumerate().skip(from) {
            used += l.advance;
            if used > limit + 1e-9 {
                break;
            }
            if may_end(l) || k + 1 == lines.len() {
                cut = Some(k + 1);
            }
        }
        let next = cut?;
        if next == lines.len() {
            return Some(starts);
        }
        if starts.len() == n {
            return None;
        }
        starts.push(next);
        from = next;
    }
    Some(starts)
}

/// Draws `set` with its first baseline at `at`; returns where a baseline after it would be.
pub fn draw(g: &mut Group, at: Point, set: &Set, h: f64) -> f64 {
    for (p, line) in &set.lines {
        g.text(Text::new(Point::new(at.x + p.x, at.y + p.y), line.clone(), h, Anchor::Start));
    }
    at.y + set.height
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_are_at_most_185_mm_and_as_many_as_fit() {
        assert_eq!(columns(150.0), (1, 150.0));
        assert_eq!(columns(COLUMN_MAX), (1, COLUMN_MAX));
        assert_eq!(columns(300.0), (2, 145.0), "two filling the room, not one 185 mm and a gap");
        assert_eq!(columns(380.0), (2, COLUMN_MAX));
        assert_eq!(columns(390.0), (2, COLUMN_MAX), "a little spare, not three narrow ones");
        for width in [190.0, 381.0, 600.0, 800.0] {
            let (n, w) = columns(width);
            let taken = n as f64 * w + (n - 1) as f64 * COLUMN_GAP;
            assert!(w <= COLUMN_MAX && taken <= width + 1e-9 && width - taken < 0.1 * COLUMN_MAX * n as f64, "{width}");
        }
    }

    fn words(n: usize) -> String {
        (0..n).map(|i| format!("word{i}")).collect::<Vec<_>>().join(" ")
    }

    #[test]
    fn a_long_note_flows_into_level_columns_no_wider_than_allowed() {
        let paras = [
            Para::new("Drawn from the exact values.", 2.0),
            Para::heading("Assumed:", 0.5),
            Para::new(words(300), 1.0),
        ];
        let s = set(&paras, 2.5, 390.0);
        let xs: Vec<f64> = s.lines.iter().map(|(p, _)| p.x).collect();
        assert!(xs.iter().any(|&x| x > 0.0), "two columns");
        let right: Vec<&(Point, String)> = s.lines.iter().filter(|(p, _)| p.x > 0.0).collect();
        let left = s.lines.len() - right.len();
        assert!(left.abs_diff(right.len()) <= 2, "{left} lines against {}", right.len());
        let width = |t: &str| crate::drawing::text::LabelText::new(t, "").width(2.5);
        assert!(s.lines.iter().all(|(_, t)| width(t) <= COLUMN_MAX), "no line wider than a column");
        // Every word once, in order.
        let text: Vec<&str> = s.lines.iter().flat_map(|(_, t)| t.split(' ')).collect();
        assert_eq!(text[..5], ["Drawn", "from", "the", "exact", "values."]);
        assert_eq!(text.last(), Some(&"word299"));
    }

    #[test]
    fn notes_of_four_lines_or_fewer_stay_in_one_column() {
        let paras =
            [Para::new("Drawn from the exact values.", 2.0), Para::heading("Assumed:", 0.5), Para::new(words(12), 1.0)];
        let s = set(&paras, 2.5, 390.0);
        assert_eq!(s.lines.len(), 3);
        assert!(s.lines.iter().all(|(p, _)| p.x == 0.0), "{:?}", s.lines);
        // One line more: five lines in one column are set in two.
        let five = [
            paras[0].clone(),
            paras[1].clone(),
            Para::new(words(12), 1.0),
            Para::new(words(12), 1.0),
            Para::new(words(3), 1.0),
        ];
        assert!(set(&five, 2.5, 390.0).lines.iter().any(|(p, _)| p.x > 0.0));
    }

    #[test]
    fn a_short_note_is_not_cut_inside_a_sentence() {
        // The worked example's notes: a line, a heading and one paragraph of four lines in
        // two columns broke that paragraph after its second line.
        let paras = [Para::new(words(5), 2.0), Para::heading("Assumed:", 0.5), Para::new(words(70), 1.0)];
        let s = set(&paras, 2.5, 390.0);
        let n = s.lines.len();
        assert!((5..=8).contains(&n), "{n} lines");
        let last: Vec<f64> = s.lines.iter().skip(2).map(|(p, _)| p.x).collect();
        assert!(last.iter().all(|&x| x == last[0]), "the paragraph in one column: {:?}", s.lines);
        // Two paragraphs of three lines each: a column each, level, none cut.
        let two = [Para::new(words(40), 1.0), Para::new(words(40), 1.0)];
        let s = set(&two, 2.5, 390.0);
        let xs: Vec<f64> = s.lines.iter().map(|(p, _)| p.x).collect();
        let half = xs.len() / 2;
        assert!(xs[..half].iter().all(|&x| x == 0.0) && xs[half..].iter().all(|&x| x > 0.0), "{:?}", s.lines);
    }

    #[test]
    fn a_heading_does_not_end_a_column() {
        let paras = [Para::new(words(60), 1.0), Para::heading("Assumed:", 0.5), Para::new(words(60), 1.0)];
        let s = set(&paras, 2.5, 390.0);
        let at = s.lines.iter().position(|(_, t)| t == "Assumed:").unwrap();
        assert_eq!(s.lines[at].0.x, s.lines[at + 1].0.x, "the heading stands over its paragraph");
    }

    #[test]
    fn short_notes_stay_in_one_column() {
        let s = set(&[Para::new("One line.", 1.0)], 2.5, 390.0);
        assert_eq!(s.lines.len(), 1);
        assert_eq!(s.height, LINE_PITCH * 2.5 + 1.0);
        assert_eq!(set(&[], 2.5, 390.0).lines.len(), 0);
    }
}
