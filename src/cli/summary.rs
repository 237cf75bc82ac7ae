//! The batch's `summary.csv` and `summary.md`: one row per variant (status, the refusal,
//! the warnings, the key answers by identifier, each sheet's layout measure, the time), and
//! in the Markdown the counts by status and by refusal kind.

use super::batch::{KEY_ANSWERS, Outcome, Status};
use crate::num::digits;
use std::collections::BTreeMap;
use std::fmt::Write as _;

fn answer(x: Option<f64>) -> String {
    // A difference of 1e-14 % is an exact agreement, printed as such.
    x.map_or(String::new(), |x| if x.abs() < 1e-9 { "0".into() } else { digits::sig(x, 6) })
}

fn layout(l: Option<[u64; 4]>) -> String {
    l.map_or(String::new(), |[c, o, out, run]| format!("{c}/{o}/{out}/{run}"))
}

/// `summary.csv`.
pub fn csv(outcomes: &[Outcome]) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut head: Vec<String> = ["task", "variant", "status", "refusal_kind", "reason", "explained", "warnings"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    head.extend(KEY_ANSWERS.iter().map(|s| s.to_string()));
    head.extend((1..=3).map(|n| format!("layout_sheet{n}")));
    head.push("seconds".into());
    w.write_record(&head).ok();
    for o in outcomes {
        let (kind, reason) = o.refusal.clone().unwrap_or_default();
        let mut row = vec![
            o.task.clone(),
            o.variant.to_string(),
            o.status.key().into(),
            kind,
            reason,
            o.explained.clone().unwrap_or_default(),
            o.warnings.join(" | "),
        ];
        row.extend(o.answers.iter().map(|&a| answer(a)));
        row.extend(o.layout.iter().map(|&l| layout(l)));
        row.push(format!("{:.3}", o.seconds));
        w.write_record(&row).ok();
    }
    String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default()
}

/// Counts of outcomes by status, and of refusals by kind.
pub fn counts(outcomes: &[Outcome]) -> (BTreeMap<Status, usize>, BTreeMap<String, usize>) {
    let mut status = BTreeMap::new();
    let mut kinds = BTreeMap::new();
    for o in outcomes {
        *status.entry(o.status).or_insert(0) += 1;
        if let (Status::Refused | Status::Failed, Some((k, _))) = (o.status, &o.refusal) {
            *kinds.entry(k.clone()).or_insert(0) += 1;
        }
    }
    (status, kinds)
}

/// `summary.md`.
pub fn markdown(outcomes: &[Outcome], seconds: f64, jobs: usize) -> String {
    let (status, kinds) = counts(outcomes);
    let mut md = format!("# The catalogue built: {} variants in {seconds:.1} s on {jobs} threads\n\n", outcomes.len());
    md.push_str("| status | variants |\n|---|---:|\n");
    for (s, n) in &status {
        writeln!(md, "| {} | {n} |", s.key()).ok();
    }
    if !kinds.is_empty() {
        md.push_str("\n| refusal kind | variants |\n|---|---:|\n");
        for (k, n) in &kinds {
            writeln!(md, "| {k} | {n} |").ok();
        }
    }
    md.push_str(
        "\n| task | variant | status | P_m, N | Δ, % | ε | ε drawn | u_1H | z_1, z_2, z_3 | r_min, mm | α_max rise, ° | layout 1 / 2 / 3 | s |\n",
    );
    md.push_str("|---|---:|---|---:|---:|---:|---:|---:|---|---:|---:|---|---:|\n");
    for o in outcomes {
        let a = |i: usize| answer(o.answers[i]);
        let z = if o.answers[5].is_some() { format!("{}, {}, {}", a(5), a(6), a(7)) } else { String::new() };
        let l: Vec<String> = o.layout.iter().map(|&l| layout(l)).collect();
        writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {z} | {} | {} | {} | {:.2} |",
            o.task,
            o.variant,
            o.status.key(),
            a(0),
            a(1),
            a(2),
            a(3),
            a(4),
            a(8),
            a(9),
            l.join(" / "),
            o.seconds
        )
        .ok();
    }
    let notes: Vec<&Outcome> = outcomes.iter().filter(|o| o.refusal.is_some() || !o.warnings.is_empty()).collect();
    if !notes.is_empty() {
        md.push_str("\n## Refusals, incomplete variants and warnings\n\n");
        for o in notes {
            if let Some((k, r)) = &o.refusal {
                writeln!(md, "- task {} variant {} ({k}): {}", o.task, o.variant, r.replace('\n', " ")).ok();
                if let Some(why) = &o.explained {
                    writeln!(md, "  - the guide's data explain it: {why}").ok();
                }
            }
            for w in &o.warnings {
                writeln!(md, "- task {} variant {} warning: {}", o.task, o.variant, w.replace('\n', " ")).ok();
            }
        }
    }
    md
}
