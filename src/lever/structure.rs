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
    /// "I(0,1) → II(2,3) → II(4,5)"
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
    let mut parts = vec![];
    let pair = |name: &str, a: u32, b: u32, prismatic: bool| Pair { name: name.into(), links: [a, b], prismatic };
    for step in &m.steps {
        match *step {
            Step::Crank { pivot, link, .. } => {
                let n = m.links[link].number;
                pairs.push(pair(m.name(pivot), 0, n, false));
                parts.push(format!("I(0,{n})"));
            }
            Step::Rrr { p, q, b, links, .. } => {
                let (i, j) = (m.links[links[0]].number, m.links[links[1]].number);
                pairs.push(pair(m.name(p), carrier(m, p), i, false));
                pairs.push(pair(m.name(b), i, j, false));
                pairs.push(pair(m.name(q), carrier(m, q), j, false));
                parts.push(format!("II({i},{j})"));
            }
            Step::Rrp { p, d, links, .. } => {
                let (i, j) = (m.links[links[0]].number, m.links[links[1]].number);
                pairs.push(pair(m.name(p), carrier(m, p), i, false));
                pairs.push(pair(m.name(d), i, j, false));
                pairs.push(pair(&format!("{}–0", m.name(d)), j, 0, true));
                parts.push(format!("II({i},{j})"));
            }
            Step::Rpr { a, c, links, .. } => {
                let (i, j) = (m.links[links[0]].number, m.links[links[1]].number);
                pairs.push(pair(m.name(a), carrier(m, a), i, false));
                pairs.push(pair(&format!("{}–{}", m.name(a), j), i, j, true));
                pairs.push(pair(m.name(c), carrier(m, c), j, false));
                parts.push(format!("II({i},{j})"));
            }
            Step::Attach { .. } => {}
        }
    }
    let n = m.links.len();
    let p5 = pairs.len();
    let class = if m.groups.is_empty() { 1 } else { 2 };
    Structure {
        moving_links: n,
        p5,
        p4: 0,
        dof: 3 * n as i64 - 2 * p5 as i64,
        formula: parts.join(" → "),
        class,
        pairs,
    }
}
