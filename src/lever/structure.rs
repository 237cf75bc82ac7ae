//! Structural analysis as the note states it: links, kinematic pairs, Chebyshev's
//! degree of freedom W = 3n − 2p5 − p4, the Assur groups and the structural formula.

use super::linkage::{Mechanism, Step};

/// One lower pair: its name, the two link numbers it joins, revolute or prismatic.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Pair {
    pub name: String,
    pub links: [u32; 2],
    pub prismatic: bool,
}

#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Structure {
    pub moving_links: usize,
    pub pairs: Vec<Pair>,
    pub p5: usize,
    pub p4: usize,
    pub dof: i64,
    /// "I(0,1) → II(2,3) → II(4,5)", each group after the one it is attached to; two
    /// branches off one part both ways from it: "II(2,3) ← I(0,1) → II(4,5)".
    pub formula: String,
    /// Highest class of its groups: the class of the mechanism.
    pub class: u32,
}

/// Number of the first link that carries `point` (0 for a frame point).
fn carrier(m: &Mechanism, point: usize) -> u32 {
    if m.is_frame(point) {
        return 0;
    }
    m.links.iter().find(|l| l.points.contains(&point)).map_or(0, |l| l.number)
}

pub fn analyse(m: &Mechanism) -> Structure {
    let mut pairs = Vec::new();
    // Each part's name, its links and the links its outer joints are carried by.
    let mut parts: Vec<(String, Vec<u32>, Vec<u32>)> = vec![];
    let pair = |name: &str, a: u32, b: u32, prismatic: bool| Pair { name: name.into(), links: [a, b], prismatic };
    for step in &m.steps {
        match *step {
            Step::Crank { pivot, link, .. } => {
                let n = m.links[link].number;
                pairs.push(pair(m.name(pivot), 0, n, false));
                parts.push((format!("I(0,{n})"), vec![n], vec![0]));
            }
            Step::Rrr { p, q, b, links, .. } => {
                let (i, j) = (m.links[links[0]].number, m.links[links[1]].number);
                pairs.push(pair(m.name(p), carrier(m, p), i, false));
                pairs.push(pair(m.name(b), i, j, false));
                pairs.push(pair(m.name(q), carrier(m, q), j, false));
                parts.push((format!("II({i},{j})"), vec![i, j], vec![carrier(m, p), carrier(m, q)]));
            }
            Step::Rrp { p, d, links, .. } => {
                let (i, j) = (m.links[links[0]].number, m.links[links[1]].number);
                pairs.push(pair(m.name(p), carrier(m, p), i, false));
                pairs.push(pair(m.name(d), i, j, false));
                pairs.push(pair(&format!("{}–0", m.name(d)), j, 0, true));
                parts.push((format!("II({i},{j})"), vec![i, j], vec![carrier(m, p), 0]));
            }
            Step::Rpr { a, c, links, .. } => {
                let (i, j) = (m.links[links[0]].number, m.links[links[1]].number);
                pairs.push(pair(m.name(a), carrier(m, a), i, false));
                pairs.push(pair(&format!("{}–{}", m.name(a), j), i, j, true));
                pairs.push(pair(m.name(c), carrier(m, c), j, false));
                parts.push((format!("II({i},{j})"), vec![i, j], vec![carrier(m, a), carrier(m, c)]));
            }
            Step::Attach { .. } => {}
        }
    }
    let n = m.links.len();
    let p5 = pairs.len();
    let class = if m.groups.is_empty() { 1 } else { 2 };
    Structure { moving_links: n, p5, p4: 0, dof: 3 * n as i64 - 2 * p5 as i64, formula: formula(&parts), class, pairs }
}

/// The structural formula of `parts` (each: its name, its links, the links carrying its
/// outer joints), in the order they are solved: a group follows the last part it is
/// attached to, in one chain while each hangs on the one before ("I(0,1) → II(2,3) →
/// II(4,5)"); a group that does not starts a chain of its own from that part. Two chains
/// from one part read both ways from it ("II(2,3) ← I(0,1) → II(4,5)": a V compressor's
/// two rods on one crank); more, or from different parts, are listed ("…; II(2,3) →
/// II(6,7)").
fn formula(parts: &[(String, Vec<u32>, Vec<u32>)]) -> String {
    let part_of = |link: u32| parts.iter().position(|p| p.1.contains(&link));
    let mut chains: Vec<Vec<usize>> = Vec::new();
    for (k, (_, _, carriers)) in parts.iter().enumerate() {
        let Some(parent) = carriers.iter().filter_map(|&l| part_of(l)).filter(|&p| p < k).max() else {
            chains.push(vec![k]);
            continue;
        };
        match chains.iter_mut().find(|c| c.last() == Some(&parent)) {
            Some(chain) => chain.push(k),
            None => chains.push(vec![parent, k]),
        }
    }
    let name = |k: &usize| parts[*k].0.as_str();
    let line = |c: &[usize]| c.iter().map(name).collect::<Vec<_>>().join(" → ");
    match chains.as_slice() {
        [a, b] if a[0] == b[0] && a.len() > 1 && b.len() > 1 => {
            let back: Vec<&str> = a.iter().rev().map(name).collect();
            format!("{} → {}", back.join(" ← "), b[1..].iter().map(name).collect::<Vec<_>>().join(" → "))
        }
        _ => chains.iter().map(|c| line(c)).collect::<Vec<_>>().join("; "),
    }
}

#[cfg(test)]
mod tests {
    use super::formula;

    fn part(name: &str, links: &[u32], carriers: &[u32]) -> (String, Vec<u32>, Vec<u32>) {
        (name.to_string(), links.to_vec(), carriers.to_vec())
    }

    /// A chain reads in one line; two rods on one crank both ways from it; a group on two
    /// earlier parts follows the later one.
    #[test]
    fn a_formula_follows_each_group_from_the_part_it_hangs_on() {
        let crank = part("I(0,1)", &[1], &[0]);
        let chain = [crank.clone(), part("II(2,3)", &[2, 3], &[1, 0]), part("II(4,5)", &[4, 5], &[3, 0])];
        assert_eq!(formula(&chain), "I(0,1) → II(2,3) → II(4,5)");
        let v = [crank.clone(), part("II(2,3)", &[2, 3], &[1, 0]), part("II(4,5)", &[4, 5], &[1, 0])];
        assert_eq!(formula(&v), "II(2,3) ← I(0,1) → II(4,5)");
        let both = [crank.clone(), part("II(2,3)", &[2, 3], &[1, 0]), part("II(4,5)", &[4, 5], &[1, 3])];
        assert_eq!(formula(&both), "I(0,1) → II(2,3) → II(4,5)");
        let three = [
            crank,
            part("II(2,3)", &[2, 3], &[1, 0]),
            part("II(4,5)", &[4, 5], &[1, 0]),
            part("II(6,7)", &[6, 7], &[3, 0]),
        ];
        assert_eq!(formula(&three), "II(6,7) ← II(2,3) ← I(0,1) → II(4,5)");
    }
}
