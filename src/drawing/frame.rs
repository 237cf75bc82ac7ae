//! The A1 sheet's frame (GOST 2.301) and title block (GOST 2.104, form 1), drawn from
//! `templates/sheet-a1.yaml`: page size, margins, the block's lines, captions and fields.

use super::labels::Common;
use super::scene::{Anchor, Group, MAIN, THIN, Text};
use super::text::{Fitted, LINE_PITCH, SLANT, TooLong, fit, paragraph_stretched, wrap};
use crate::num::tol;
use kurbo::{Point, Rect};
use serde::Deserialize;

const SOURCE: &str = include_str!("../../templates/sheet-a1.yaml");

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Template {
    page: [f64; 2],
    margins: Margins,
    title_block: BlockTemplate,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Margins {
    left: f64,
    top: f64,
    right: f64,
    bottom: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct BlockTemplate {
    size: [f64; 2],
    main: Vec<[f64; 4]>,
    thin: Vec<[f64; 4]>,
    captions: Vec<Caption>,
    fields: Vec<Field>,
    name_field: [f64; 4],
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Caption {
    key: CaptionKey,
    at: [f64; 2],
    h: f64,
    anchor: TemplateAnchor,
    /// The right edge of a start-anchored caption's cell: the captions with one share one
    /// height, the largest up to their own at which the longest fits (Uzbek "Tasdiqladi"
    /// takes 2.3 mm in the 17 mm column).
    #[serde(default)]
    right: Option<f64>,
}

/// Room kept between a caption and its cell's right rule, mm.
const CAPTION_CLEAR: f64 = 0.4;
/// The smallest lettering a caption is reduced to, mm (GOST 2.304's smallest).
const SMALLEST_CAPTION: f64 = 1.8;

impl Caption {
    /// The largest lettering up to its own, to 0.1 mm, at which the caption fits its cell.
    fn fitting_height(&self, text: &str) -> f64 {
        let Some(right) = self.right else { return self.h };
        // The width is proportional to the height.
        let per_mm = crate::font::metrics().width(text, crate::font::size_for_cap(1.0)) + SLANT;
        let h = (right - self.at[0] - CAPTION_CLEAR) / per_mm;
        ((h * 10.0).floor() / 10.0).clamp(SMALLEST_CAPTION, self.h)
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Field {
    field: FieldName,
    cell: [f64; 4],
    h: f64,
    anchor: TemplateAnchor,
    /// Room kept each side between the cell's rules and the text, mm ([`CELL_PAD`]'s by
    /// default): the letter's 5 mm cell holds a 3.5 mm capital only with less (at the
    /// default it fell to 2.5 mm and read as a lowercase "у", a teacher's review).
    #[serde(default)]
    pad: Option<f64>,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(rename_all = "lowercase")]
enum TemplateAnchor {
    Start,
    Middle,
    End,
}

impl From<TemplateAnchor> for Anchor {
    fn from(a: TemplateAnchor) -> Anchor {
        match a {
            TemplateAnchor::Start => Anchor::Start,
            TemplateAnchor::Middle => Anchor::Middle,
            TemplateAnchor::End => Anchor::End,
        }
    }
}

/// The title block's fixed captions (the [`Common`] labels `tb_…`).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(rename_all = "snake_case")]
enum CaptionKey {
    Change,
    SheetNo,
    Doc,
    Sign,
    Date,
    Drawn,
    Checked,
    TechControl,
    StdControl,
    Approved,
    Lit,
    Mass,
    Scale,
}

impl CaptionKey {
    fn text(self, c: &Common) -> &str {
        match self {
            CaptionKey::Change => c.tb_change(),
            CaptionKey::SheetNo => c.tb_sheet_no(),
            CaptionKey::Doc => c.tb_doc(),
            CaptionKey::Sign => c.tb_sign(),
            CaptionKey::Date => c.tb_date(),
            CaptionKey::Drawn => c.tb_drawn(),
            CaptionKey::Checked => c.tb_checked(),
            CaptionKey::TechControl => c.tb_tech_control(),
            CaptionKey::StdControl => c.tb_std_control(),
            CaptionKey::Approved => c.tb_approved(),
            CaptionKey::Lit => c.tb_lit(),
            CaptionKey::Mass => c.tb_mass(),
            CaptionKey::Scale => c.tb_scale(),
        }
    }
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(rename_all = "lowercase")]
enum FieldName {
    Designation,
    /// The document's letter in the first "Lit." cell: "У", a student's (educational) work.
    Letter,
    Student,
    Supervisor,
    Scale,
    Sheet,
    Sheets,
    Organisation,
}

fn template() -> &'static Template {
    static T: std::sync::OnceLock<Template> = std::sync::OnceLock::new();
    T.get_or_init(|| serde_saphyr::from_str(SOURCE).expect("templates/sheet-a1.yaml is valid (tested)"))
}

/// The frame's group id.
pub const FRAME: &str = "frame";
/// The title block's group id.
pub const TITLE_BLOCK: &str = "title-block";
/// GOST 2.104's box 26's group id.
pub const DESIGNATION_BOX: &str = "designation-box";

pub const A1_W: f64 = 841.0;
pub const A1_H: f64 = 594.0;

/// The page size from the template, mm.
pub fn page() -> (f64, f64) {
    let t = template();
    (t.page[0], t.page[1])
}

/// The inside of the frame.
pub fn inner() -> Rect {
    let t = template();
    let m = &t.margins;
    Rect::new(m.left, m.top, t.page[0] - m.right, t.page[1] - m.bottom)
}

/// The title block's rectangle, in the frame's bottom-right corner.
pub fn title_block_rect() -> Rect {
    let f = inner();
    let [w, h] = template().title_block.size;
    Rect::new(f.x1 - w, f.y1 - h, f.x1, f.y1)
}

/// GOST 2.104's box 26, 70 × 14 mm in the frame's top-left corner: the designation again,
/// turned 180° (a sheet larger than A4 whose title block runs along its long side).
pub fn designation_box() -> Rect {
    let f = inner();
    Rect::new(f.x0, f.y0, f.x0 + 70.0, f.y0 + 14.0)
}

/// Room kept between box 26 and a heading beside or under it, mm.
const BOX_GAP: f64 = 1.5;

/// Where a heading line set at `at` (its baseline's start) in `h` mm lettering starts clear
/// of box 26: right of it where the line would run into it, else where it is. Each sheet's
/// first heading stands in the frame's top-left corner.
pub fn clear_of_designation_box(at: Point, h: f64) -> Point {
    let b = designation_box().inflate(BOX_GAP, BOX_GAP);
    // The lettering's ascent (capitals and their accents) above the baseline and its
    // descenders below.
    let (top, bottom) = (at.y - 1.1 * h, at.y + 0.3 * h);
    if at.x < b.x1 && top < b.y1 && bottom > b.y0 { Point::new(b.x1, at.y) } else { at }
}

/// Draws box 26 with the designation turned 180° (none for an empty designation), in the
/// designation's lettering where it fits, down to 2.5 mm over two lines.
pub fn designation_box_group(designation: &str) -> Result<Group, TooLong> {
    let r = designation_box();
    let mut g = Group::new(DESIGNATION_BOX, r);
    rect_path(&mut g, r);
    if designation.is_empty() {
        return Ok(g);
    }
    let f = fit_cell(designation, r, (7.0, CELL_PAD.0), FieldName::Designation.source(), "box 26 (top left)")?;
    // Turned 180° about its baseline's middle, a line's letters hang below it: the first
    // line (read with the sheet turned) is the lowest.
    let pitch = LINE_PITCH * f.h;
    let block = f.h + pitch * (f.lines.len() as f64 - 1.0);
    let first = r.center().y + block / 2.0 - f.h;
    for (i, line) in f.lines.iter().enumerate() {
        // Set from its start, half its advance right of the middle (it runs leftwards):
        // renderers centre a condensed, turned line each its own way (a PDF viewer put it
        // 14 mm left of the box, librsvg 22 mm right).
        let mut t = Text::new(Point::ZERO, line.clone(), f.h, Anchor::Start).with_stretch(f.stretch);
        t.at = Point::new(r.center().x + t.advance() / 2.0, first - pitch * i as f64);
        t.rotate = 180.0;
        g.text(t);
    }
    Ok(g)
}

/// The title block's name field (sheet name, project title, course), on the sheet.
pub fn name_field_rect() -> Rect {
    let [x0, y0, x1, y1] = template().title_block.name_field;
    Rect::new(x0, y0, x1, y1) + title_block_rect().origin().to_vec2()
}

/// What the title block says.
pub struct TitleBlock<'a> {
    pub designation: &'a str,
    pub sheet_name: &'a str,
    pub project_title: &'a str,
    pub student: &'a str,
    pub supervisor: &'a str,
    pub organisation: &'a str,
    pub scale: &'a str,
    pub sheet_no: u32,
    /// The number of sheets of the whole project.
    pub sheet_count: u32,
    /// The names of all the project's sheets: each title block letters its own at the height
    /// at which the longest fits, so the three blocks match (sheet 1's long name was 2.5 mm
    /// beside sheet 2's 3.5 mm). Empty: this sheet's name alone decides.
    pub project_sheet_names: &'a [String],
}

fn rect_path(g: &mut Group, r: Rect) {
    g.path(vec![r.origin(), Point::new(r.x1, r.y0), Point::new(r.x1, r.y1), Point::new(r.x0, r.y1)], true, MAIN);
}

pub fn frame(g: &mut Group) {
    rect_path(g, inner());
}

/// Room left between a cell's lines and its text, mm (horizontal, vertical).
const CELL_PAD: (f64, f64) = (0.75, 0.5);
/// The name field's margin each side, mm.
const NAME_PAD: f64 = 2.0;

impl FieldName {
    /// The project file's field the value comes from, for messages.
    fn source(self) -> &'static str {
        match self {
            FieldName::Designation => "project.designation",
            FieldName::Student => "project.student",
            FieldName::Supervisor => "project.supervisor",
            FieldName::Organisation => "project.institution and project.group",
            FieldName::Letter | FieldName::Scale | FieldName::Sheet | FieldName::Sheets => "the title block",
        }
    }
}

/// Draws fitted lines in `cell`, the block centred vertically, each line placed by `anchor`.
fn draw_fitted(g: &mut Group, cell: Rect, f: &Fitted, anchor: Anchor) {
    let top = cell.center().y - f.height() / 2.0;
    let x = match anchor {
        Anchor::Start => cell.x0 + CELL_PAD.0,
        Anchor::Middle => cell.center().x,
        Anchor::End => cell.x1 - CELL_PAD.0,
    };
    paragraph_stretched(g, Point::new(x, top + f.h), &f.lines, (f.h, f.stretch), anchor);
}

/// `text` fitted into `cell` (less its padding), or the refusal naming `field`.
fn fit_cell(text: &str, cell: Rect, (h, pad): (f64, f64), field: &str, place: &str) -> Result<Fitted, TooLong> {
    let (w, ht) = (cell.width() - 2.0 * pad, cell.height() - 2.0 * CELL_PAD.1);
    fit(text, w, ht, h).ok_or_else(|| TooLong::new(field, text, place, (cell.width(), cell.height())))
}

/// Draws the title block; a project text too long for its cell even at 2.5 mm over several
/// lines is refused, naming the field.
pub fn title_block(g: &mut Group, l: &Common, tb: &TitleBlock) -> Result<(), TooLong> {
    let t = &template().title_block;
    let r = title_block_rect();
    let o = r.origin().to_vec2();
    let p = |x: f64, y: f64| Point::new(x, y) + o;
    rect_path(g, r);
    for (lines, pen) in [(&t.main, MAIN), (&t.thin, THIN)] {
        for &[x1, y1, x2, y2] in lines {
            g.line(p(x1, y1), p(x2, y2), pen);
        }
    }
    let column_h =
        t.captions.iter().filter(|c| c.right.is_some()).map(|c| c.fitting_height(c.key.text(l))).reduce(f64::min);
    for c in &t.captions {
        let h = if c.right.is_some() { column_h.unwrap_or(c.h) } else { c.h };
        g.text(Text::new(p(c.at[0], c.at[1]), c.key.text(l), h, c.anchor.into()));
    }
    let sheet = format!("{} {}", l.tb_sheet_no(), tb.sheet_no);
    let sheets = format!("{} {}", l.tb_sheets(), tb.sheet_count);
    for f in &t.fields {
        let value = match f.field {
            FieldName::Designation => tb.designation,
            FieldName::Letter => l.tb_lit_letter(),
            FieldName::Student => tb.student,
            FieldName::Supervisor => tb.supervisor,
            FieldName::Scale => tb.scale,
            FieldName::Sheet => &sheet,
            FieldName::Sheets => &sheets,
            FieldName::Organisation => tb.organisation,
        };
        if value.is_empty() {
            continue;
        }
        let [x0, y0, x1, y1] = f.cell;
        let cell = Rect::new(x0, y0, x1, y1) + o;
        let fitted = fit_cell(value, cell, (f.h, f.pad.unwrap_or(CELL_PAD.0)), f.field.source(), "title-block cell")?;
        draw_fitted(g, cell, &fitted, f.anchor.into());
    }
    let [x0, y0, x1, y1] = t.name_field;
    name_field(g, Rect::new(x0, y0, x1, y1) + o, tb, l)
}

/// The name field: the project's title (the product's name, largest), the sheet's name (the
/// document's) and the course, each fitted, stacked and centred.
fn name_field(g: &mut Group, r: Rect, tb: &TitleBlock, l: &Common) -> Result<(), TooLong> {
    const GAP: f64 = 2.0;
    /// The sheet's name may take this much of the field's height, mm.
    const SHEET_NAME_H: f64 = 12.0;
    // Wider margins than a cell's: a centred line as wide as the field reads as touching
    // its rules.
    let w = r.width() - 2.0 * NAME_PAD;
    let ours = |text: &str, ht: f64, h: f64| {
        fit(text, w, ht, h).unwrap_or_else(|| Fitted { lines: wrap(text, 2.5, w), h: 2.5, stretch: 1.0 })
    };
    // The height every sheet's name fits at, and the tallest block they take at it, so that
    // the project's title gets the same room on every sheet.
    let names = tb.project_sheet_names.iter().map(String::as_str).chain([tb.sheet_name]);
    let name_h = names.clone().map(|n| ours(n, SHEET_NAME_H, 3.5).h).fold(3.5, f64::min);
    let name = ours(tb.sheet_name, SHEET_NAME_H, name_h);
    let names_height = names.map(|n| ours(n, SHEET_NAME_H, name_h).height()).fold(0.0, f64::max);
    let course = ours(l.tb_course(), 2.5 * 1.3, 2.5);
    let title_room = r.height() - 2.0 * CELL_PAD.1 - names_height - course.height() - 2.0 * GAP;
    let title = fit(tb.project_title, w, title_room, 5.0).ok_or_else(|| {
        TooLong::new("project.title", tb.project_title, "title block's name field", (r.width(), r.height()))
    })?;
    let blocks = [title, name, course];
    let height = blocks.iter().map(Fitted::height).sum::<f64>() + GAP * 2.0;
    let mut top = r.center().y - height / 2.0;
    for b in &blocks {
        paragraph_stretched(g, Point::new(r.center().x, top + b.h), &b.lines, (b.h, b.stretch), Anchor::Middle);
        top += b.height() + GAP;
    }
    Ok(())
}

/// Whether `r` lies inside `outer` (for the layout tests).
pub fn is_inside(outer: Rect, r: Rect) -> bool {
    r.x0 >= outer.x0 - tol::PAPER
        && r.y0 >= outer.y0 - tol::PAPER
        && r.x1 <= outer.x1 + tol::PAPER
        && r.y1 <= outer.y1 + tol::PAPER
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::labels::Language;

    #[test]
    fn template_is_a1_with_gost_margins_and_a_185_by_55_block() {
        assert_eq!(page(), (A1_W, A1_H));
        assert_eq!(inner(), Rect::new(20.0, 5.0, 836.0, 589.0));
        assert_eq!(title_block_rect(), Rect::new(651.0, 534.0, 836.0, 589.0));
        // Form 1's left part: the header row at 20–25 mm, then six signature rows, and the
        // first column line stopping at the header (columns 1–2 merge below it).
        let rows: Vec<(f64, &str)> = template()
            .title_block
            .captions
            .iter()
            .filter(|c| c.at[0] < 10.0)
            .map(|c| (c.at[1], c.key.text(Common::get(Language::Ru))))
            .collect();
        assert_eq!(
            rows,
            [
                (23.8, "Изм."),
                (28.8, "Разраб."),
                (33.8, "Пров."),
                (38.8, "Т.контр."),
                (48.8, "Н.контр."),
                (53.8, "Утв.")
            ]
        );
        assert!(template().title_block.main.contains(&[7.0, 0.0, 7.0, 25.0]));
        let l = Common::get(Language::Ru);
        let captions: Vec<&str> = template().title_block.captions.iter().map(|c| c.key.text(l)).collect();
        assert!(captions.contains(&"Разраб.") && captions.contains(&"Масштаб"), "{captions:?}");
        let block = Rect::from_origin_size(Point::ZERO, (185.0, 55.0));
        let t = &template().title_block;
        for &[x1, y1, x2, y2] in t.main.iter().chain(&t.thin) {
            assert!(is_inside(block, Rect::new(x1.min(x2), y1.min(y2), x1.max(x2), y1.max(y2))));
        }
    }

    /// The document's letter stands at 3.5 mm in its 5 mm cell in every language (at the
    /// cells' usual padding it fell to 2.5 mm and read as a lowercase "у"), inside the cell.
    #[test]
    fn the_documents_letter_is_a_3_5_mm_capital_inside_its_cell() {
        let tb = TitleBlock {
            designation: "TMM KP 05.00.00",
            sheet_name: "",
            project_title: "x",
            student: "",
            supervisor: "",
            organisation: "",
            scale: "",
            sheet_no: 1,
            sheet_count: 3,
            project_sheet_names: &[],
        };
        let r = title_block_rect();
        let cell = Rect::new(135.0, 20.0, 140.0, 35.0) + r.origin().to_vec2();
        for lang in [Language::Uz, Language::Ru, Language::En] {
            let l = Common::get(lang);
            let mut g = Group::new("tb", r);
            title_block(&mut g, l, &tb).expect("fits");
            let letter = g.texts().find(|t| t.text == l.tb_lit_letter()).expect("the letter is drawn");
            assert_eq!(letter.h, 3.5, "{lang:?}");
            // The box is the advance plus the slant; the letter's side bearing (over 0.1 mm)
            // keeps its ink off the rule.
            let room = cell.inflate(0.1, 0.0);
            assert!(is_inside(room, letter.bbox()), "{lang:?}: {:?} outside {cell:?}", letter.bbox());
        }
    }
}
