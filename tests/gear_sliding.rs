//! Sheet 2's diagram of specific sliding: λ1 at B1 and λ2 at B2 against the textbook's
//! λ1 = 1 − (g − x)/(u·x), λ2 = 1 − u·x/(g − x) (x from N1 along N1N2 = g = a_w·sin α_w,
//! N1B2 = √(r_a1² − r_b1²), N2B1 = √(r_a2² − r_b2²)), computed here from the pair's radii in
//! `results.json`; its ordinates at B1 and B2 drawn at its stated scale; drawn where the mesh
//! leaves a wheel's inside empty.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::root;
use tmm_sheets::drawing::scene::LineType;
use tmm_sheets::pipeline;

fn sheet2(text: &str) -> pipeline::Built {
    pipeline::build(&pipeline::load(text).unwrap(), &[2]).unwrap().remove(0)
}

/// The textbook's λ1 at B1 and λ2 at B2 from the pair's results.
fn textbook(r: &serde_json::Value) -> [Option<f64>; 2] {
    let p = &r["pair"];
    let f = |v: &serde_json::Value| v.as_f64().unwrap();
    let radii = |k: &str, i: usize| f(&p["radii"][k][i]);
    let (aw, alpha) = (f(&p["centre_distance"]), f(&p["working_pressure_angle_deg"]).to_radians());
    let g = aw * alpha.sin();
    let u = f(&p["ratio"]);
    let reach = |i: usize| (radii("tip", i).powi(2) - radii("base", i).powi(2)).sqrt();
    // Neither contact goes below where a wheel's involute begins (r_b·t from its N along the
    // line); where that is N itself the sliding is unbounded: no value.
    let from_n = |i: usize| (f(&p["involute_from"][i]).powi(2) - radii("base", i).powi(2)).max(0.0).sqrt();
    let (x_b1, x_b2) = ((g - reach(1)).max(from_n(0)), reach(0).min(g - from_n(1)));
    [(x_b1 > 0.0).then(|| 1.0 - (g - x_b1) / (u * x_b1)), (x_b2 < g).then(|| 1.0 - u * x_b2 / (g - x_b2))]
}

#[test]
fn the_specific_sliding_at_the_active_lines_ends_is_the_textbooks() {
    let dir = root().join("fixtures/gears");
    let mut texts: Vec<(String, String)> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .map(|p| (p.file_stem().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    texts.push(("worked-example".into(), pipeline::DEFAULT_PROJECT.to_string()));
    for (name, text) in texts {
        let b = sheet2(&text);
        let r = &b.output.results;
        let sliding = &r["sliding"];
        // A wheel's inside leaves room for it on the handbook's pair and the double planet.
        if ["handbook-khk", "shifted-double-planet"].contains(&name.as_str()) {
            assert!(sliding.is_object(), "{name}: no diagram of specific sliding");
        }
        if !sliding.is_object() {
            continue;
        }
        let expected = textbook(r);
        let drawn = [sliding["lambda1_b1"].as_f64(), sliding["lambda2_b2"].as_f64()];
        for i in 0..2 {
            let ok = match (drawn[i], expected[i]) {
                (Some(d), Some(e)) => (d - e).abs() <= 1e-9 * e.abs().max(1.0),
                (d, e) => d.is_none() && e.is_none(),
            };
            assert!(ok, "{name}: λ{} = {:?} against the textbook's {:?}", i + 1, drawn[i], expected[i]);
        }
        // An end of the active line at its N (interference) is named with it on the axis.
        let mesh = b.output.scene.groups.iter().find(|g| g.id == "mesh").unwrap();
        let part = mesh.parts.iter().find(|p| p.id == "mesh.sliding").unwrap();
        for (i, b_sub) in ["₁", "₂"].iter().enumerate() {
            let at_n = mesh.items[part.items.clone()].iter().any(|item| match item {
                tmm_sheets::drawing::scene::Item::Text(t) => {
                    t.text == "N" && t.sub == (i + 1).to_string() && t.tail == format!(" ≡ B{b_sub}")
                }
                _ => false,
            });
            assert_eq!(at_n, expected[i].is_none(), "{name}: N{} named with B{} on the axis", i + 1, i + 1);
        }
        // Laid as the mesh lays N1N2: N1 right of P, N2 left of it, in both.
        let x_of = |inside: bool, sub: &str| {
            mesh.items.iter().enumerate().find_map(|(k, item)| match item {
                tmm_sheets::drawing::scene::Item::Text(t)
                    if t.text == "N" && t.sub == sub && part.items.contains(&k) == inside =>
                {
                    Some(t.at.x)
                }
                _ => None,
            })
        };
        let (n1, n2) = (x_of(true, "1").unwrap(), x_of(true, "2").unwrap());
        let (m1, m2) = (x_of(false, "1"), x_of(false, "2"));
        assert!(n1 > n2, "{name}: the diagram's N1 at {n1:.1}, N2 at {n2:.1}");
        if let (Some(m1), Some(m2)) = (m1, m2) {
            assert!(m1 > m2, "{name}: the mesh's N1 at {m1:.1}, N2 at {m2:.1}");
        }
        let expected: Vec<f64> = expected.into_iter().flatten().collect();
        // The dashed ordinates at B1 and B2, at μ_λ, are those values (or reach the plot's
        // floor where the sliding runs off it).
        let mu = sliding["mu_lambda"].as_f64().unwrap();
        let dashed: Vec<f64> = mesh.items[part.items.clone()]
            .iter()
            .filter_map(common::path_points)
            .filter(|(_, pen)| pen.line == LineType::Dashed)
            .map(|(pts, _)| (pts[1].y - pts[0].y).abs() * mu)
            .collect();
        assert_eq!(dashed.len(), expected.len(), "{name}: the ordinates at B1 and B2 inside N1N2");
        let floor = dashed.iter().copied().fold(0.0, f64::max);
        for i in 0..expected.len() {
            let want = (-expected[i]).min(floor);
            assert!((dashed[i] - want).abs() < 0.05 * mu, "{name}: ordinate {} at λ {}", dashed[i], expected[i]);
        }
    }
}

/// Found by the stress test: a pair alone's mesh region reaches over the title block's
/// column, and the diagram took the room there, entering the title block. It keeps off it.
#[test]
fn a_pair_alones_sliding_diagram_keeps_off_the_title_block() {
    let text = "project:\n  title: {uz: \"Sinov\", ru: \"Проба\", en: \"Stress\"}\n  designation: {uz: \"MMN KL 00.00.00\", ru: \"ТММ КП 00.00.00\", en: \"TMM CP 00.00.00\"}\n  language: en\n\ngears:\n  pair: {module: 13.49, z: [100, 22]}\n";
    let b = sheet2(text);
    let l = &b.output.results["layout"];
    let faults = common::layout_faults(l);
    assert!(faults.is_empty(), "{faults:?}: {}", l["problems"]);
    assert!(b.output.results["sliding"].is_object(), "the diagram found room elsewhere");
}

/// The λ axis is marked at λ = 1, the most a flank slides (at the other wheel's N), with
/// its round ticks, each at its value's height at the stated μ_λ: the worked example's axis
/// read only −6, −4, −2 under the curves' tops. On every gear fixture with the diagram and
/// the worked example, in every language.
#[test]
fn the_lambda_axis_is_marked_at_one_and_at_its_round_values() {
    use tmm_sheets::drawing::labels::Language;
    use tmm_sheets::drawing::scene::Item;
    let dir = root().join("fixtures/gears");
    let mut texts: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .map(|p| std::fs::read_to_string(&p).unwrap())
        .collect();
    texts.push(pipeline::DEFAULT_PROJECT.to_string());
    let mut checked = 0;
    for text in &texts {
        for lang in Language::ALL {
            let mut p = pipeline::load(text).unwrap();
            p.info.language = lang;
            let b = pipeline::build(&p, &[2]).unwrap().remove(0);
            let Some(mu) = b.output.results["sliding"]["mu_lambda"].as_f64() else { continue };
            let mesh = b.output.scene.groups.iter().find(|g| g.id == "mesh").unwrap();
            let part = mesh.parts.iter().find(|p| p.id == "mesh.sliding").unwrap();
            // The axis's values: the part's texts that read as numbers, with their heights.
            let mut ticks: Vec<(f64, f64)> = mesh.items[part.items.clone()]
                .iter()
                .filter_map(|item| match item {
                    Item::Text(t) if t.sub.is_empty() && t.tail.is_empty() => {
                        t.text.replace('−', "-").replace(',', ".").parse::<f64>().ok().map(|v| (v, t.at.y))
                    }
                    _ => None,
                })
                .collect();
            ticks.sort_by(|a, b| a.0.total_cmp(&b.0));
            assert!(ticks.iter().any(|t| t.0 == 1.0), "{lang:?}: no «1» on the λ axis: {ticks:?}");
            assert!(ticks.len() >= 3, "{lang:?}: {ticks:?}");
            let (top_v, top_y) = ticks[ticks.len() - 1];
            for &(v, y) in &ticks {
                let want = top_y + (top_v - v) / mu;
                assert!((y - want).abs() < 1e-6, "{lang:?}: «{v}» at {y:.3} mm, its height at μ_λ {want:.3}");
            }
            checked += 1;
        }
    }
    assert!(checked >= 6, "{checked} diagrams");
}
