//! The mechanism's steps ready to run ([`StepPlan`]: each with the constants its closed form
//! takes from the lengths, found once), and [`Batch`], which runs them on [`LANES`] crank
//! angles at once, one per SIMD lane: a whole turn's angles are independent, so each of
//! the dyads' divisions and square roots serves several angles, and no angle waits on
//! another's chain of them. A lane's results are [`Mechanism::solve_into`]'s bit for bit
//! (the same closed forms, [`super::lanes`]).

use super::dyads::{self, AttachShape, RrpShape, RrrShape, Solved};
use super::lanes::{KinOf, LANES, Lanes, LinkOf};
use super::linkage::{LinkId, Mechanism, PointId, State, Step};
use crate::num::tol;

/// A [`Step`] with its constants.
#[derive(Debug, Clone, Copy)]
pub enum StepPlan {
    Crank {
        pivot: PointId,
        pin: PointId,
        length: f64,
        inv_length: f64,
        link: LinkId,
    },
    Rrr {
        p: PointId,
        q: PointId,
        b: PointId,
        shape: RrrShape,
        links: [LinkId; 2],
    },
    Rrp {
        p: PointId,
        d: PointId,
        shape: RrpShape,
        links: [LinkId; 2],
    },
    Rpr {
        a: PointId,
        c: PointId,
        a3: PointId,
        links: [LinkId; 2],
        min_distance: f64,
    },
    /// `toward == from`: the point is the joint itself.
    Joint {
        point: PointId,
        from: PointId,
    },
    Attach {
        point: PointId,
        link: LinkId,
        from: PointId,
        toward: PointId,
        shape: AttachShape,
    },
}

impl StepPlan {
    #[inline(always)]
    pub fn of(step: &Step, m: &Mechanism) -> Self {
        match *step {
            Step::Crank { pivot, pin, length, link } => {
                StepPlan::Crank { pivot, pin, length, inv_length: 1.0 / length, link }
            }
            Step::Rrr { p, q, b, l_pb, l_qb, branch, links } => {
                StepPlan::Rrr { p, q, b, shape: RrrShape::new(l_pb, l_qb, branch), links }
            }
            Step::Rrp { p, d, length, through, dir, branch, links } => {
                StepPlan::Rrp { p, d, shape: RrpShape::new(length, through, dir, branch), links }
            }
            Step::Rpr { a, c, a3, links } => StepPlan::Rpr { a, c, a3, links, min_distance: tol::SAME_POINT * m.size },
            Step::Attach { point, from, toward, .. } if toward == from => StepPlan::Joint { point, from },
            Step::Attach { point, link, from, toward, distance, angle, ratio } => {
                StepPlan::Attach { point, link, from, toward, shape: AttachShape::new(distance, angle, ratio) }
            }
        }
    }
}

/// The points and links of [`LANES`] angles, indexed like [`State`]'s: what the steps read.
pub struct Batch {
    points: Vec<KinOf<Lanes>>,
    links: Vec<LinkOf<Lanes>>,
}

/// Whether `ok` holds in every lane.
#[inline(always)]
fn every_lane(ok: impl Fn(usize) -> bool) -> bool {
    (0..LANES).all(ok)
}

impl Batch {
    /// Buffers for `m`, its frame's points set.
    pub fn new(m: &Mechanism) -> Self {
        let mut points = vec![KinOf::default(); m.point_names.len()];
        for &(id, p) in &m.frame {
            points[id] = KinOf::fixed(p);
        }
        Batch { points, links: vec![LinkOf::default(); m.links.len()] }
    }

    /// Solves the crank angles `theta`, one per lane, into `states` (prepared for them);
    /// false as soon as a lane fails a step (which one, and why, is for
    /// [`Mechanism::solve_into`] to say), the steps before it written.
    #[inline(always)]
    pub fn solve(&mut self, plans: &[StepPlan], omega: f64, theta: Lanes, states: &mut [State; LANES]) -> bool {
        plans.iter().enumerate().all(|(i, plan)| self.run(i, plan, omega, theta, states))
    }

    /// Step `i`, its results kept for the steps after it and written into each lane's state
    /// at once, while they are in registers.
    #[inline(always)]
    fn run(&mut self, i: usize, plan: &StepPlan, omega: f64, theta: Lanes, states: &mut [State; LANES]) -> bool {
        let pts = &self.points;
        match *plan {
            StepPlan::Crank { pivot, pin, length, inv_length, link } => {
                let (k, l) = dyads::crank_of(&pts[pivot], length, inv_length, theta, omega);
                self.set_point(pin, k, states);
                self.set_link(link, l, states);
            }
            StepPlan::Rrr { p, q, b, shape, links } => {
                let (sol, d2, cross) = dyads::rrr_of(&pts[p], &pts[q], &shape);
                if !every_lane(|k| shape.check(d2.0[k], cross.0[k]).is_ok()) {
                    return false;
                }
                self.set_dyad(b, sol, links, states);
            }
            StepPlan::Rrp { p, d, shape, links } => {
                let (sol, h, along) = dyads::rrp_of(&pts[p], &shape);
                if !every_lane(|k| shape.check(h.0[k], along.0[k]).is_ok()) {
                    return false;
                }
                self.set_dyad(d, sol, links, states);
            }
            StepPlan::Rpr { a, c, a3, links, min_distance } => {
                let (sol, d) = dyads::rpr_of(&pts[a], &pts[c]);
                if !every_lane(|k| dyads::rpr_check(d.0[k], min_distance).is_ok()) {
                    return false;
                }
                self.set_point(a3, sol.a3, states);
                self.set_link(links[0], sol.kulisa, states);
                self.set_link(links[1], sol.kulisa, states);
                let (d, d_dot, d_ddot) = sol.slide;
                each_lane(states, |k, s| s.slides[i] = (d.0[k], d_dot.0[k], d_ddot.0[k]));
            }
            StepPlan::Joint { point, from } => self.set_point(point, pts[from], states),
            StepPlan::Attach { point, link, from, toward, shape } => {
                let kin = dyads::attach_of(&pts[from], pts[toward].p, &self.links[link], &shape);
                self.set_point(point, kin, states);
            }
        }
        true
    }

    #[inline(always)]
    fn set_point(&mut self, id: PointId, kin: KinOf<Lanes>, states: &mut [State; LANES]) {
        self.points[id] = kin;
        each_lane(states, |k, s| s.points[id] = kin.lane(k));
    }

    #[inline(always)]
    fn set_link(&mut self, id: LinkId, link: LinkOf<Lanes>, states: &mut [State; LANES]) {
        self.links[id] = link;
        each_lane(states, |k, s| s.links[id] = link.lane(k));
    }

    #[inline(always)]
    fn set_dyad(&mut self, point: PointId, sol: Solved<Lanes>, links: [LinkId; 2], states: &mut [State; LANES]) {
        self.set_point(point, sol.point, states);
        self.set_link(links[0], sol.first, states);
        self.set_link(links[1], sol.second, states);
    }
}

/// `f(k, state k)` for each lane, unrolled: with the lane a constant, a lane's x and y leave
/// their registers as one 16-byte store (a loop over the lanes made two 8-byte stores and
/// took as long as the dyads). Written for four lanes: another [`LANES`] does not compile.
#[inline(always)]
fn each_lane(states: &mut [State; LANES], mut f: impl FnMut(usize, &mut State)) {
    let [s0, s1, s2, s3] = states;
    f(0, s0);
    f(1, s1);
    f(2, s2);
    f(3, s3);
}
