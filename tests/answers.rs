//! The answer keys: every value of every note table has an identifier
//! (`sheet<N>.<table>.<row>[.<column>]`) that the CSV, the Markdown, `results.json` and
//! the sheet share, the same in every language; and the keys' words exist in every language.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{fixture, fixture_names, root};
use std::collections::{BTreeMap, BTreeSet};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline::{self, Built};
use tmm_sheets::project::Project;
use tmm_sheets::report::{self, ForceKind, Sub, SubWord, Unit};
use tmm_sheets::sheets::words;

/// Every fixture, the gear and cam ones included, by name.
fn all_fixtures() -> Vec<(String, Project)> {
    let mut out: Vec<(String, Project)> = fixture_names().into_iter().map(|n| (n.clone(), fixture(&n))).collect();
    for dir in ["gears", "cams"] {
        let mut names: Vec<_> =
            std::fs::read_dir(root().join("fixtures").join(dir)).unwrap().map(|e| e.unwrap().path()).collect();
        names.sort();
        for p in names {
            let text = std::fs::read_to_string(&p).unwrap();
            out.push((p.display().to_string(), pipeline::load(&text).unwrap()));
        }
    }
    out
}

fn built(p: &Project, lang: Language) -> Vec<Built> {
    let mut p = p.clone();
    p.info.language = lang;
    pipeline::build(&p, &[]).unwrap()
}

fn answers_of(b: &[Built]) -> BTreeMap<String, f64> {
    let mut out = BTreeMap::new();
    for s in b {
        for t in &s.output.tables {
            for a in t.answers(&format!("sheet{}", s.output.number)) {
                assert!(out.insert(a.id.clone(), a.value).is_none(), "the identifier {} is not unique", a.id);
            }
        }
    }
    out
}

/// Identifiers are words a shell, a CSV cell and an XML id all take, unique on a project,
/// and the same whatever the sheets' language.
#[test]
fn every_value_has_one_identifier_in_every_language() {
    for (name, p) in all_fixtures() {
        let uz = answers_of(&built(&p, Language::Uz));
        assert!(!uz.is_empty(), "{name}: no answers");
        for id in uz.keys() {
            let fine = id.chars().all(|c| c.is_alphanumeric() || matches!(c, '_' | '.' | '-'));
            assert!(fine && id.starts_with("sheet"), "{name}: identifier {id:?}");
        }
        for lang in [Language::Ru, Language::En] {
            let other = answers_of(&built(&p, lang));
            assert_eq!(uz, other, "{name}: the answers differ in {lang:?}");
        }
    }
}

/// The CSV's rows, the Markdown's anchors and `results.json`'s answers name the same
/// values: each CSV cell is the answer of its row's identifier and its column's key.
#[test]
fn csv_markdown_and_results_share_the_identifiers() {
    let p = fixture("worked-example");
    let b = built(&p, Language::Ru);
    let files = pipeline::outputs(&p, &b, &[pipeline::Format::Svg]).unwrap();
    let file = |name: &str| String::from_utf8(files.iter().find(|f| f.0 == name).unwrap().1.clone()).unwrap();
    let json: serde_json::Value = serde_json::from_str(&file("results.json")).unwrap();
    let answers = json["answers"].as_object().unwrap();
    let mut seen = BTreeSet::new();
    for s in &b {
        let prefix = format!("sheet{}", s.output.number);
        let md = file(&format!("{prefix}-tables.md"));
        for t in &s.output.tables {
            let text = file(&format!("{prefix}-{}.csv", t.table.id));
            let mut reader = csv::Reader::from_reader(text.as_bytes());
            let header: Vec<String> = reader.headers().unwrap().iter().map(str::to_string).collect();
            assert_eq!(header[..3], ["id", "quantity", "unit"]);
            assert!(md.contains(&format!("<a id=\"{prefix}.{}\"></a>", t.table.id)), "{prefix}.{}", t.table.id);
            for record in reader.records() {
                let record = record.unwrap();
                let cells: Vec<&str> = record.iter().collect();
                let row = cells[0];
                assert!(md.contains(&format!("<a id=\"{row}\"></a>")), "no anchor {row} in the Markdown");
                for (k, value) in cells[3..].iter().enumerate() {
                    let id = if header.len() == 4 { row.to_string() } else { format!("{row}.{}", header[3 + k]) };
                    let a = answers.get(&id).unwrap_or_else(|| panic!("{id} is in the CSV, not in results.json"));
                    let v: f64 = value.parse().unwrap();
                    assert!((a["value"].as_f64().unwrap() - v).abs() <= 1e-9 * v.abs().max(1.0), "{id}: {a} vs {v}");
                    assert_eq!(a["unit"], cells[2], "{id}");
                    seen.insert(id);
                }
            }
        }
    }
    assert_eq!(seen.len(), answers.len(), "results.json has answers no CSV has");
}

/// The answers are the quantities they name: a few recomputed here from the project's
/// own numbers (v_A = ω1·l_OA at every position; a wheel's pitch radius m·z/2; the stage's
/// tooth numbers; r_min as results.json states it).
#[test]
fn answers_are_the_quantities_they_name() {
    let p = fixture("worked-example");
    let a = answers_of(&built(&p, Language::Uz));
    let m = &p.lever.as_ref().unwrap().mechanism;
    let v_a = (m.omega1 * m.crank().length).abs();
    let crank_pin = m.name(m.crank().pin);
    let positions: Vec<_> = a.keys().filter(|k| k.starts_with(&format!("sheet1.velocities.v_{crank_pin}."))).collect();
    assert!(positions.len() >= 8, "{positions:?}");
    for id in positions {
        assert!((a[id] - v_a).abs() < 1e-12, "{id}: {} vs ω1·l_OA = {v_a}", a[id]);
    }
    let g = p.gears.as_ref().unwrap();
    for (i, w) in g.pair.spec.z.iter().enumerate() {
        let r = g.pair.spec.module * f64::from(*w) / 2.0 * 1e3;
        assert!((a[&format!("sheet2.wheels.r.{}", i + 1)] - r).abs() < 1e-9, "r{}", i + 1);
    }
    let stage = &g.planetary.as_ref().unwrap().stage;
    assert_eq!(a["sheet2.planetary.z_1"], f64::from(stage.z[0]));
    assert_eq!(a["sheet2.planetary.K"], f64::from(stage.planets));
    assert_eq!(a["sheet2.conditions.neighbours.met"], 1.0);
    let r_min = p.cam.as_ref().unwrap().design.centre.r_min;
    assert!((a["sheet3.results.r_min"] - r_min * 1e3).abs() < 1e-9);
}

/// Every key the tables use has a word in every language: a unit in Russian is Cyrillic
/// (or a symbol), a subscript word differs from its key on a Russian sheet, a force's
/// letter and a condition's name are never empty.
#[test]
fn every_key_has_its_word_in_every_language() {
    use tmm_sheets::gears::planetary::ConditionKind::*;
    let units = [
        Unit::Mm,
        Unit::MPerS,
        Unit::MPerS2,
        Unit::PerS,
        Unit::PerS2,
        Unit::Kg,
        Unit::KgM2,
        Unit::N,
        Unit::NM,
        Unit::Deg,
        Unit::Percent,
    ];
    for u in units {
        let ru = words::unit(Language::Ru, u);
        assert!(!ru.is_empty() && !ru.chars().any(|c| c.is_ascii_alphabetic()), "{u:?} in Russian: {ru:?}");
    }
    use SubWord::*;
    for w in [Drawn, Required, Pitch, Work, Roller, AllowedRise, AllowedReturn, MaxRise, MaxReturn] {
        for lang in Language::ALL {
            assert!(!words::sub(lang, &Sub::Word(w)).is_empty(), "{w:?} in {lang:?}");
        }
        assert_ne!(words::sub(Language::Ru, &Sub::Word(w)), w.key(), "{w:?} untranslated in Russian");
    }
    for k in [ForceKind::Inertia, ForceKind::Balancing, ForceKind::Resistance, ForceKind::Gas] {
        let ru = words::sub(Language::Ru, &Sub::Force(k, "2".into()));
        assert!(ru.ends_with('2') && ru.chars().next().is_some_and(|c| ('а'..='я').contains(&c)), "{k:?}: {ru}");
    }
    for c in [Ratio, Coaxiality, Neighbours, Assembly, NoUndercut, RingTeeth, RingPlanetDifference] {
        for lang in Language::ALL {
            assert!(!words::condition(lang, c).is_empty(), "{c:?} in {lang:?}");
        }
    }
    // The CSV writes the SI units, whatever the language.
    assert_eq!(Unit::KgM2.si(), "kg·m²");
    assert_eq!(report::ascii_key("ε"), "epsilon");
}

/// Every CSV of every fixture names each of its columns in its header (no empty cell after
/// `quantity,unit`) and writes a value that rounds to zero without a minus sign.
#[test]
fn csv_headers_name_every_column_and_no_value_is_minus_zero() {
    for (name, p) in all_fixtures() {
        let b = built(&p, Language::Uz);
        for (file, bytes) in pipeline::outputs(&p, &b, &[pipeline::Format::Svg]).unwrap() {
            if !file.ends_with(".csv") {
                continue;
            }
            let text = String::from_utf8(bytes).unwrap();
            let mut reader = csv::Reader::from_reader(text.as_bytes());
            let header = reader.headers().unwrap().clone();
            assert!(header.iter().all(|h| !h.trim().is_empty()), "{name}: {file}: {header:?}");
            for record in reader.records() {
                let record = record.unwrap();
                for cell in record.iter().skip(3) {
                    let minus_zero = cell.starts_with('-') && cell[1..].chars().all(|c| c == '0' || c == '.');
                    assert!(!minus_zero, "{name}: {file}: {cell} in {record:?}");
                }
            }
        }
    }
}

/// The sheet prints every table's values as the note's Markdown does, cell for cell: a
/// whole centre distance "90" in both, the given module and clearance "5" and "0,25" as
/// given (the drawn table printed 90,00, 5,000 and 0,2500 where the Markdown had 90 and 5).
#[test]
fn the_drawn_tables_print_the_values_the_note_prints() {
    for (name, p) in all_fixtures() {
        for lang in [Language::Uz, Language::En] {
            let b = built(&p, lang);
            for s in &b {
                let prefix = format!("sheet{}", s.output.number);
                for t in &s.output.tables {
                    let md = report::markdown(t, &prefix);
                    let wanted: Vec<String> = md
                        .lines()
                        .filter(|l| l.starts_with("| <a id="))
                        // The ratio's condition is drawn as u_1H's deviation in per cent.
                        .filter(|l| !l.contains("conditions.ratio\""))
                        .flat_map(|l| {
                            let cells: Vec<String> =
                                l.trim_end_matches('|').split(" | ").skip(2).map(|c| c.trim().to_string()).collect();
                            // A condition met is "1" in the note and a word on the sheet, its
                            // limit drawn with its relation ("> 0,633", "≥ 17").
                            let words = if t.table.id == "conditions" { 1 } else { cells.len() };
                            cells.into_iter().take(words).collect::<Vec<_>>()
                        })
                        .collect();
                    let drawn = drawn_texts(&s.svg, &format!("{prefix}.table.{}", t.table.id));
                    let mut rest = drawn.iter();
                    for w in &wanted {
                        assert!(
                            rest.any(|d| d == w),
                            "{name} {lang:?} {prefix}.{}: {w} not drawn in its place (drawn: {drawn:?})",
                            t.table.id
                        );
                    }
                }
            }
        }
    }
}

/// The texts of the SVG group `id` (every group of a table split into parts), in order.
fn drawn_texts(svg: &str, id: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (start, _) in svg.match_indices(&format!("<g id=\"{id}\"")) {
        let body = &svg[start..];
        let end = body.find("</g>").unwrap_or(body.len());
        for piece in body[..end].split("</text>") {
            if let Some(open) = piece.rfind('>') {
                out.push(piece[open + 1..].to_string());
            }
        }
    }
    out
}

/// The values the project gives are printed as given, on the sheet and in the note alike:
/// the worked example's m = 5, α = 20, c* = 0,25 (sheet 2) and l = 105, β_max = 25,
/// r_rol = 15, the allowed pressure angles 45 (sheet 3), not 5,000, 0,2500, 105,0, 15,00,
/// 45,00; a computed value keeps its four significant digits (α_max = 45,00, p = 15,71).
#[test]
fn given_values_are_printed_as_given() {
    let p = fixture("worked-example");
    let b = built(&p, Language::Ru);
    let cell = |id: &str| {
        let (sheet, table) = (id.split('.').next().unwrap(), id.split('.').nth(1).unwrap());
        let s = b.iter().find(|s| format!("sheet{}", s.output.number) == sheet).unwrap();
        let t = s.output.tables.iter().find(|t| t.table.id == table).unwrap();
        let md = report::markdown(t, sheet);
        let line = md.lines().find(|l| l.contains(&format!("<a id=\"{id}\"></a>"))).unwrap().to_string();
        line.trim_end_matches(" |").rsplit(" | ").next().unwrap().to_string()
    };
    for (id, printed) in [
        ("sheet2.pair.m", "5"),
        ("sheet2.pair.alpha", "20"),
        ("sheet2.pair.h_a_star", "1"),
        ("sheet2.pair.c_star", "0,25"),
        ("sheet2.pair.a_w", "90"),
        ("sheet2.pair.p", "15,71"),
        ("sheet3.results.l", "105"),
        ("sheet3.results.beta_max", "25"),
        ("sheet3.results.r_roller", "15"),
        ("sheet3.results.alpha_allowed_rise", "45"),
        ("sheet3.results.alpha_max_rise", "45,00"),
    ] {
        assert_eq!(cell(id), printed, "{id}");
    }
}

/// A quantity a link does not have is printed "—", as the course's tables do, not a 0 that
/// reads as computed: the worked example's slider 5 has no ε, J_S or M_i; links 2–4 have
/// all three (given J_S = 0,5 / 1,1 / 36 kg·m²). The CSV and the answers keep the value 0.
#[test]
fn a_quantity_a_link_does_not_have_is_printed_as_a_dash() {
    let p = fixture("worked-example");
    let b = built(&p, Language::Ru);
    let s = b.iter().find(|s| s.output.number == 1).unwrap();
    let t = s.output.tables.iter().find(|t| t.table.id == "inertia").unwrap();
    let md = report::markdown(t, "sheet1");
    let cells = |row: &str| -> Vec<String> {
        let line = md.lines().find(|l| l.contains(&format!("<a id=\"sheet1.inertia.{row}\"></a>"))).unwrap();
        // The quantity's and its unit's cells, then one a link.
        line.trim_end_matches(" |").split(" | ").skip(2).map(str::to_string).collect()
    };
    for row in ["epsilon", "J_S", "M_i"] {
        let c = cells(row);
        assert_eq!(c.len(), 4, "{row}: {c:?}");
        assert_eq!(c[3], "—", "{row}: the slider's");
        assert!(c[..3].iter().all(|v| v.replace(',', ".").parse::<f64>().is_ok()), "{row}: {c:?}");
    }
    assert_ne!(cells("P_i")[3], "—", "the slider's inertia force is a value");
    let csv = report::csv(t, "sheet1");
    let eps = csv.lines().find(|l| l.starts_with("sheet1.inertia.epsilon,")).unwrap();
    assert!(eps.ends_with(",0.000000000"), "{eps}");
}
