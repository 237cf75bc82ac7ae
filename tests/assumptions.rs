//! The user's assumptions on sheets 2 and 3 are held to their notes' room as sheet 1's
//! are: too many or too long, they are refused at their field's line and refuse that sheet
//! only; as many as fit leave the sheet clean, every item on the page.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::fixture_text;
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline::{self, Error};
use tmm_sheets::project::Project;

/// The worked example with `section`'s assumptions replaced by `items` (YAML strings).
fn with_assumptions(section: &str, items: &[String]) -> String {
    let text = fixture_text("worked-example");
    let start = text.find(&format!("\n{section}:\n")).expect("the section") + 1;
    let at = start + text[start..].find("\n  assumptions:\n").expect("its assumptions") + 1;
    let list_end = text[at..].find("\n\n").map_or(text.len(), |e| at + e + 1);
    let list: String = items.iter().map(|a| format!("    - \"{a}\"\n")).collect();
    format!("{}  assumptions:\n{list}{}", &text[..at], &text[list_end..])
}

fn short(n: usize) -> Vec<String> {
    (0..n).map(|i| format!("Short assumption {i}.")).collect()
}

fn project(text: &str, lang: Language) -> Project {
    let mut p = pipeline::load(text).unwrap_or_else(|e| panic!("{e}"));
    p.info.language = lang;
    p
}

/// 20,000 words, or 100 short assumptions, of `gears` or `cam`: refused naming the field
/// at its line, blocking that sheet only; the other two still build.
#[test]
fn too_many_or_too_long_assumptions_refuse_their_own_sheet_only() {
    let words = vec![(0..20_000).map(|i| format!("word{i}")).collect::<Vec<_>>().join(" ")];
    for (section, sheet) in [("gears", 2), ("cam", 3)] {
        for items in [&words, &short(100)] {
            let text = with_assumptions(section, items);
            let field = format!("{section}.assumptions");
            let line = text.find(&format!("\n{section}:\n")).map(|s| {
                let at = s + text[s..].find("\n  assumptions:\n").unwrap() + 1;
                text[..at].lines().count() as u64 + 1
            });
            let p = project(&text, Language::Uz);
            let Err(Error::Refused(r)) = pipeline::build(&p, &[]) else { panic!("{field}: not refused") };
            assert_eq!((r.refusal.path.as_str(), Some(r.refusal.line)), (field.as_str(), line), "{}", r.refusal);
            assert!(r.refusal.cause.contains("does not fit the notes under"), "{}", r.refusal);
            assert_eq!(r.blocks, [sheet], "{}", r.refusal);
            let others: Vec<u32> = [1, 2, 3].into_iter().filter(|&n| n != sheet).collect();
            let built = pipeline::build(&p, &others).unwrap_or_else(|e| panic!("{field}: the others: {e}"));
            assert_eq!(built.iter().map(|b| b.output.number).collect::<Vec<_>>(), others);
        }
    }
}

/// The layout block of a built sheet, as `results.json` has it.
fn layout_counts(p: &Project, sheet: u32) -> Result<[u64; 4], Error> {
    let built = pipeline::build(p, &[sheet])?;
    let layout = &built[0].output.results["layout"];
    Ok(tmm_sheets::drawing::layout::FAULTS.map(|k| layout[k].as_u64().expect("a count")))
}

/// As many short assumptions as the notes hold (found by bisection), and three: the sheet
/// builds with nothing crossed, overlapping, out of its region or off the page, in every
/// language; one more is refused.
#[test]
fn the_most_assumptions_that_fit_leave_the_sheet_clean() {
    for (section, sheet) in [("gears", 2), ("cam", 3)] {
        for lang in [Language::Uz, Language::Ru, Language::En] {
            let counts = |n: usize| layout_counts(&project(&with_assumptions(section, &short(n)), lang), sheet);
            assert_eq!(counts(3).unwrap(), [0; 4], "{section}, {lang:?}: three");
            let (mut fits, mut refused) = (3, 100);
            while refused - fits > 1 {
                let mid = (fits + refused) / 2;
                if counts(mid).is_ok() { fits = mid } else { refused = mid }
            }
            assert!(fits >= 6, "{section}, {lang:?}: only {fits} short assumptions fit");
            assert_eq!(counts(fits).unwrap(), [0; 4], "{section}, {lang:?}: {fits}");
        }
    }
}
