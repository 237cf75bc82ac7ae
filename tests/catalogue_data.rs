//! The embedded catalogue against the guide: every task and practice set with all its
//! variants, rows typed here from the guide's text (seed 001, tab-separated, decimal commas)
//! compared with the data files, the known misprints corrected with their printed values
//! kept, and every variant either a project the program reads or incomplete in the guide —
//! never a template fault — with every refusal one the task's notes explain.

use tmm_sheets::catalogue::{Catalogue, Task, Variant};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline;
use tmm_sheets::project::Kind;

fn catalogue() -> Catalogue {
    Catalogue::embedded().expect("the embedded catalogue reads")
}

#[test]
fn every_task_of_the_guide_and_every_practice_set_has_all_its_variants() {
    let cat = catalogue();
    let ids: Vec<String> = cat.tasks.iter().map(Task::id).collect();
    let mut expected: Vec<String> = (1..=15).map(|n| n.to_string()).collect();
    expected.extend(["P1", "P2", "P3"].map(String::from));
    assert_eq!(ids, expected);
    for t in &cat.tasks {
        let n = if t.is_practice() { 30 } else { 45 };
        assert_eq!(t.variants().collect::<Vec<_>>(), (1..=n).collect::<Vec<u32>>(), "task {}", t.id());
        for lang in Language::ALL {
            assert!(!t.name(lang).is_empty() && !t.kind(lang).is_empty(), "task {} names in {lang:?}", t.id());
        }
    }
}

/// Rows as the guide prints them (copied from its text), with the task's column keys in
/// the printed order (`None` where the data file holds a column the row does not print).
const GUIDE_ROWS: &[(&str, &str)] = &[
    ("1", "1\t1465\t150\t0,20\t0,9\t40\t200\t2,7\t50\t38\t30\t4,5\t19\t32\t9\t30\t100\t20\t1"),
    ("1", "17\t1465\t160\t0,14\t0,7\t29\t180\t1,7\t37\t32\t300\t4\t22\t30\t8\t37\t80\t20\t3"),
    ("1", "45\t1500\t210\t0,12\t0,85\t31\t180\t2,5\t36\t30\t60\t4,5\t20\t32\t8\t30\t105\t20\t2"),
    ("7", "12\t960\t54\t0,140\t0,55\t40\t62\t1,0\t3,1\t22\t28\t7\t50\t90\t6"),
    ("7", "38\t1420\t60\t0,110\t0,48\t45\t60\t1,12\t2,8\t19\t34\t6\t30\t100\t4"),
    ("10", "4\t950\t70\t0,8\t0,32\t0,28\t0,43\t0,20\t0,14\t1,2\t13\t20\t24\t5\t20\t0,12\t80\t40\t4"),
    ("10", "31\t950\t50\t0,06\t0,33\t0,30\t0,44\t0,10\t0,15\t1,4\t15\t18\t32\t4\t30\t0,12\t90\t40\t3"),
    ("12", "16\t750\t40\t0,65\t0,18\t0,19\t0,28\t0,160\t0,090\t0,17\t50\t20\t19\t23\t4\t21\t120\t15\t2"),
    ("12", "40\t730\t46\t0,095\t0,27\t0,28\t0,38\t0,205\t0,135\t0,22\t58\t37\t19\t27\t5\t16\t100\t30\t6"),
    ("13", "20\t750\t3.8\t0.39\t1800\t0.762\t7.3\t1.3\t0.0018\t4.5\t30\t19\t34\t6\t5.0\t3\t5\t20\t0.068\t75\t45\t2"),
    // The kinematics manual (seed 000), table 1.
    ("P1", "1\t0,050\t0,140\t50\t0,5"),
];

#[test]
fn rows_typed_from_the_guide_are_in_the_data_files_as_printed() {
    let cat = catalogue();
    for (task, line) in GUIDE_ROWS {
        let t = cat.task(task).unwrap();
        let printed: Vec<f64> = line.split('\t').map(|c| c.replace(',', ".").parse().unwrap()).collect();
        let row = t.row(printed[0] as u32).unwrap();
        let cells: Vec<f64> = row.cells.iter().map(|c| c.as_deref().unwrap().parse().unwrap()).collect();
        assert_eq!(cells, printed[1..], "task {task} variant {}", printed[0]);
    }
}

#[test]
fn the_known_misprints_are_corrected_and_their_printed_values_kept() {
    let cat = catalogue();
    // (task, variant, column, printed, corrected) — TASKS.md's list; 12.2 variant 16 is
    // corrected to 0,05 (table 12.2 repeats table 12.1's rows, errata.csv says why).
    let known = [
        ("10", 4, "l_oa", "0.8", "0.08"),
        ("12", 16, "l_oa", "0.65", "0.05"),
        ("11", 21, "n_dv", "300", "3000"),
        ("11", 30, "n_dv", "300", "3000"),
    ];
    for (task, variant, column, printed, corrected) in known {
        let t = cat.task(task).unwrap();
        let e = t.errata_of(variant).find(|e| e.column == column).unwrap_or_else(|| panic!("{task}/{variant}"));
        assert_eq!((e.printed.as_deref(), e.corrected.as_deref()), (Some(printed), Some(corrected)));
        let i = t.columns().iter().position(|c| c.key == column).unwrap();
        assert_eq!(t.row(variant).unwrap().cells[i].as_deref(), Some(printed), "the data file keeps the print");
        assert_eq!(t.cell(t.row(variant).unwrap(), i).0.as_deref(), Some(corrected), "the project uses the correction");
        assert!(!e.reason.en.is_empty() && !e.reason.ru.is_empty() && !e.reason.uz.is_empty());
    }
    // 8.1 variant 10: J = 0,22 (the column J_S2 = J_S4 of task 8).
    let t = cat.task("8").unwrap();
    let e = t.errata_of(10).next().expect("task 8 variant 10's J");
    assert_eq!((e.printed.as_deref(), e.corrected.as_deref()), (Some("0.22"), Some("0.022")));
}

/// Every variant: a project file the program reads (or refuses with a design reason the
/// task's notes give), or incomplete in the guide; never a template's or a key's fault.
#[test]
fn every_variant_is_a_readable_project_or_incomplete_in_the_guide() {
    let cat = catalogue();
    let mut counts = [0usize; 3];
    for t in &cat.tasks {
        for v in t.variants() {
            let at = format!("task {} variant {v}", t.id());
            match t.project(v, Language::En, "tmm init").unwrap_or_else(|e| panic!("{at}: {e}")) {
                Variant::Incomplete { message, .. } => {
                    assert!(message.contains("incomplete in the guide: no value for"), "{at}: {message}");
                    counts[2] += 1;
                }
                Variant::Project { text, .. } => {
                    assert!(!text.contains("${"), "{at}");
                    match pipeline::load(&text) {
                        Ok(_) => counts[0] += 1,
                        Err(pipeline::Error::Refused(r)) => {
                            assert_eq!(r.refusal.kind, Kind::Design, "{at}: {}", r.refusal);
                            assert!(t.refusal_explained(v).is_some(), "{at}: unexplained: {}", r.refusal);
                            counts[1] += 1;
                        }
                        Err(e) => panic!("{at}: {e}"),
                    }
                }
            }
        }
    }
    assert_eq!(counts.iter().sum::<usize>(), 15 * 45 + 3 * 30);
    eprintln!("read {}, refused as printed {}, incomplete {}", counts[0], counts[1], counts[2]);
}

#[test]
fn init_in_each_language_sets_the_projects_language() {
    let t = catalogue();
    let t = t.task("7").unwrap();
    for lang in Language::ALL {
        let Variant::Project { text, .. } = t.project(12, lang, "x").unwrap() else { panic!() };
        assert!(text.contains(&format!("\n  language: {}\n", lang.key())), "{lang:?}");
        assert_eq!(text.matches("  language:").count(), 1);
    }
}

/// Every value, after the errata, within the range its unit allows on a machine of the
/// course (a misread comma or a column shifted by one shows here): lengths 1 mm–3 m, speeds
/// 20–3000 rev/min, paper and tooth sizes 0.5–300 mm, angles 0–360°, masses 0.1–2000 kg.
#[test]
fn every_value_is_within_its_units_plausible_range() {
    let ranges = [
        ("m", 0.001, 3.0),
        ("rev/min", 20.0, 3000.0),
        ("mm", 0.5, 300.0),
        ("°", 0.0, 360.0),
        ("kg", 0.1, 2000.0),
        ("kg·m²", 1e-4, 50.0),
        ("kN", 0.05, 500.0),
        ("MPa", 0.01, 20.0),
        ("N", 0.1, 1e5),
        ("1/s", 1.0, 500.0),
        ("m/s", 1.0, 30.0),
    ];
    let cat = catalogue();
    let mut out = Vec::new();
    for t in &cat.tasks {
        for row in &t.rows {
            for (i, c) in t.columns().iter().enumerate() {
                let Some((_, lo, hi)) = ranges.iter().find(|(u, ..)| *u == c.unit) else { continue };
                let Some(x) = t.cell(row, i).0.and_then(|s| s.parse::<f64>().ok()) else { continue };
                if !(*lo..=*hi).contains(&x) {
                    out.push(format!("task {} variant {} {} = {x} {}", t.id(), row.variant, c.printed, c.unit));
                }
            }
        }
    }
    assert!(out.is_empty(), "{}", out.join("\n"));
}

/// The texts of `lang` in a project file written in `lang`: its comments and every
/// `lang: "…"` value (the other languages' values stand beside them on the same lines).
fn texts_in(project: &str, lang: Language) -> Vec<String> {
    let key = format!("{}: \"", lang.key());
    let mut out = Vec::new();
    for line in project.lines() {
        if let Some(comment) = line.trim_start().strip_prefix('#') {
            out.push(comment.to_string());
        }
        let mut rest = line;
        while let Some(at) = rest.find(&key) {
            let value = &rest[at + key.len()..];
            let end = value
                .char_indices()
                .find(|&(i, c)| c == '"' && !value[..i].ends_with('\\'))
                .map_or(value.len(), |(i, _)| i);
            out.push(value[..end].to_string());
            rest = &value[end..];
        }
    }
    out
}

/// A figure or a note of the guide named with a Latin letter in Russian text: «Рисунок 4,a»,
/// «рис. 2,b», «примечание g)» (the Russian guide letters them а, б, в, г, д, е, ж, з).
fn latin_letter_in_russian(text: &str) -> Option<String> {
    let lower = text.to_lowercase();
    let chars: Vec<char> = lower.chars().collect();
    let word_at = |i: usize, w: &str| chars[i..].iter().take(w.chars().count()).copied().eq(w.chars());
    for i in 0..chars.len() {
        let figure = word_at(i, "рисун") || word_at(i, "рис.");
        let note = word_at(i, "примечани");
        if !(figure || note) {
            continue;
        }
        let mut j = i;
        while j < chars.len() && (chars[j].is_alphabetic() || chars[j] == '.') && !chars[j].is_ascii() {
            j += 1;
        }
        j += usize::from(chars.get(j) == Some(&'.'));
        while chars.get(j).is_some_and(|c| c.is_whitespace()) {
            j += 1;
        }
        if figure {
            let digits = j;
            while chars.get(j).is_some_and(|c| c.is_ascii_digit() || *c == '.') {
                j += 1;
            }
            if j == digits || chars.get(j) != Some(&',') {
                continue;
            }
            j += 1;
            while chars.get(j).is_some_and(|c| c.is_whitespace()) {
                j += 1;
            }
        }
        let letter = chars.get(j).is_some_and(char::is_ascii_alphabetic);
        let alone = !chars.get(j + 1).is_some_and(|c| c.is_alphabetic());
        let closes = chars.get(j + 1) == Some(&')');
        if letter && alone && (figure || closes) {
            return Some(chars[i..(j + 2).min(chars.len())].iter().collect());
        }
    }
    None
}

/// Every variant's project file in each language speaks that language only: the Russian
/// one names the guide's figures and notes with Cyrillic letters (tasks 4, 6 and 13 still
/// wrote «примечание g)», «примечание h)», «Примечание c)») and the sun gear the course's
/// way (not «солнце»); the Uzbek (Latin script) and the English ones hold no Cyrillic letter
/// but in the garbled heading of task 1's table quoted as printed ("N_ж, N_ш").
#[test]
fn every_variants_texts_are_in_its_own_language_and_script() {
    assert_eq!(latin_letter_in_russian("Рисунок 4,a утерян").as_deref(), Some("рисунок 4,a "));
    assert_eq!(latin_letter_in_russian("задание 4, примечание g): 1460").as_deref(), Some("примечание g)"));
    assert_eq!(latin_letter_in_russian("Рисунок 4,а утерян; примечание б); столбец a (0,10 м)"), None);
    let cat = catalogue();
    let mut seen = 0;
    for t in &cat.tasks {
        for v in t.variants() {
            for lang in Language::ALL {
                let Ok(Variant::Project { text, .. }) = t.project(v, lang, "tmm init") else { continue };
                seen += 1;
                for s in texts_in(&text, lang) {
                    let at = format!("task {} variant {v} {lang:?}: {s}", t.id());
                    let unquoted = s.replace("N_ж", "").replace("N_ш", "");
                    let cyrillic = unquoted.chars().any(|c| ('\u{400}'..='\u{4ff}').contains(&c));
                    match lang {
                        Language::Ru => {
                            assert_eq!(latin_letter_in_russian(&s), None, "{at}");
                            assert!(!s.to_lowercase().contains("солнце"), "{at}");
                        }
                        Language::Uz | Language::En => assert!(!cyrillic, "{at}"),
                    }
                }
            }
        }
    }
    assert!(seen > 1500, "{seen} projects read");
}

/// The assumptions a variant prints on its sheets write symbols as the sheets do: no
/// underscore (a plain text prints it as it stands: «m_5», «J_S»), and in Russian and
/// English none of the guide's Uzbek-lettered names («φish», «Upl», «mpl», «Vor»: a
/// teacher's mark on task 13's Russian sheets) — words, or the course's symbols.
#[test]
fn every_assumption_on_a_sheet_writes_its_symbols_as_a_sheet_does() {
    const GUIDES_NAMES: [&str; 4] = ["φish", "upl", "mpl", "vor"];
    let cat = catalogue();
    let mut seen = 0;
    let mut out = Vec::new();
    for t in &cat.tasks {
        for v in t.variants() {
            let Ok(Variant::Project { text, .. }) = t.project(v, Language::Ru, "tmm init") else { continue };
            let Ok(p) = tmm_sheets::project::load(&text) else { continue };
            let lever = p.lever.iter().flat_map(|l| &l.assumptions);
            let gears = p.gears.iter().flat_map(|g| &g.assumptions);
            let cam = p.cam.iter().flat_map(|c| &c.assumptions);
            for a in lever.chain(gears).chain(cam) {
                seen += 1;
                for lang in Language::ALL {
                    let s = a.get(lang);
                    let lower = s.to_lowercase();
                    let mut words = lower.split(|c: char| !c.is_alphanumeric());
                    let guide = words.any(|w| lang != Language::Uz && GUIDES_NAMES.contains(&w));
                    if s.contains('_') || guide {
                        out.push(format!("task {} variant {v} {lang:?}: {s}", t.id()));
                    }
                }
            }
        }
    }
    assert!(seen > 1000, "{seen} assumptions read");
    out.dedup();
    assert!(out.is_empty(), "{}", out.join("\n"));
}
