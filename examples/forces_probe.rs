//! Prints the force analysis of a project (a development aid).
use tmm_sheets::{analysis, pipeline};
fn main() {
    let path = std::env::args().nth(1);
    let text = path.map(|p| std::fs::read_to_string(p).unwrap()).unwrap_or_else(|| pipeline::DEFAULT_PROJECT.to_string());
    let p = match pipeline::load(&text) { Ok(p) => p, Err(e) => { eprintln!("{e}: {:?}", e); return; } };
    let k = analysis::kinematics(&p.mechanism, &p.settings).unwrap();
    let fa = analysis::forces(&p.mechanism, &k, p.settings.forces.as_ref().unwrap()).unwrap();
    let f = &fa.forces;
    for a in &f.applied { println!("on {} {:?} at ({:.4},{:.4}) F=({:.3},{:.3}) |F|={:.3}", p.mechanism.links[a.on].number, a.kind, a.at.x, a.at.y, a.force.x, a.force.y, a.force.hypot()); }
    for i in &f.inertia { println!("link {} P_i={:.3} M_i={:.4}", p.mechanism.links[i.link].number, i.force.hypot(), i.moment); }
    println!("P_m={:.9} lever={:.9} power={:.9} M_m={:.4}", f.p_m, f.p_m_lever, f.p_m_power, f.m_m);
    for l in 0..p.mechanism.links.len() { println!("residual {} {:?}", p.mechanism.links[l].number, f.residual(l)); }
}
