//! The mechanism's steps ready to run ([`StepPlan`]: each with the constants its closed form
//! takes from the lengths, found once), and [`Block`], which runs them on [`LANES`] crank
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
        /// Which of the mechanism's kulisas (in the order of the steps): where a
        /// [`Block`] keeps its slide.
        slot: usize,
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
    /// The plans of all of `m`'s steps, in order, the kulisas numbered.
    pub fn all(m: &Mechanism) -> Vec<StepPlan> {
        let mut kulisas = 0..;
        let mut number = |plan| match plan {
            StepPlan::Rpr { a, c, a3, links, min_distance, .. } => {
                StepPlan::Rpr { a, c, a3, links, min_distance, slot: kulisas.next().unwrap_or_default() }
            }
            plan => plan,
        };
        m.steps.iter().map(|step| number(StepPlan::of(step, m))).collect()
    }

    /// Step `step`'s plan (a kulisa's `slot` 0: see [`StepPlan::all`]).
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
            // numbered by `all`: one step alone does not know its place
            Step::Rpr { a, c, a3, links } => {
                StepPlan::Rpr { a, c, a3, links, min_distance: tol::SAME_POINT * m.size, slot: 0 }
            }
            Step::Attach { point, from, toward, .. } if toward == from => StepPlan::Joint { point, from },
            Step::Attach { point, link, from, toward, distance, angle, ratio } => {
                StepPlan::Attach { point, link, from, toward, shape: AttachShape::new(distance, angle, ratio) }
            }
        }
    }
}

/// A slide along a kulisa ([`State::slides`]) of [`LANES`] angles: the distance and its
/// first and second time derivatives.
pub type SlideOf<T> = (T, T, T);

/// The points, links and slides of [`LANES`] angles, indexed like [`State`]'s: where each
/// step writes its results and reads those of the steps before it. It borrows one block of
/// a [`Turn`](super::turn::Turn), so the results are stored where the turn keeps them, in
/// whole SIMD registers, and never copied (see [`super::turn`]).
pub struct Block<'a> {
    pub points: &'a mut [KinOf<Lanes>],
    pub links: &'a mut [LinkOf<Lanes>],
    /// Kulisa by kulisa (`StepPlan::Rpr`'s slot).
    pub slides: &'a mut [SlideOf<Lanes>],
    /// The step of each kulisa.
    pub kulisas: &'a [usize],
}

/// Whether `ok` holds in every lane.
#[inline(always)]
fn every_lane(ok: impl Fn(usize) -> bool) -> bool {
    (0..LANES).all(ok)
}

impl Block<'_> {
    /// Solves the crank angles `theta`, one per lane, the block's frame points already set;
    /// false as soon as a lane fails a step (which one, and why, is for
    /// [`Mechanism::solve_into`] to say), the steps before it written.
    #[inline(always)]
    pub fn solve(&mut self, plans: &[StepPlan], omega: f64, theta: Lanes) -> bool {
        plans.iter().all(|plan| self.run(plan, omega, theta))
    }

    /// One step, its results kept for the steps after it.
    #[inline(always)]
    fn run(&mut self, plan: &StepPlan, omega: f64, theta: Lanes) -> bool {
        let pts = &mut *self.points;
        match *plan {
            StepPlan::Crank { pivot, pin, length, inv_length, link } => {
                let (k, l) = dyads::crank_of(&pts[pivot], length, inv_length, theta, omega);
                pts[pin] = k;
                self.links[link] = l;
            }
            StepPlan::Rrr { p, q, b, shape, links } => {
                let (sol, d2, cross) = dyads::rrr_of(&pts[p], &pts[q], &shape);
                if !every_lane(|k| shape.check(d2.0[k], cross.0[k]).is_ok()) {
                    return false;
                }
                self.set_dyad(b, sol, links);
            }
            StepPlan::Rrp { p, d, shape, links } => {
                let (sol, h, along) = dyads::rrp_of(&pts[p], &shape);
                if !every_lane(|k| shape.check(h.0[k], along.0[k]).is_ok()) {
                    return false;
                }
                self.set_dyad(d, sol, links);
            }
            StepPlan::Rpr { a, c, a3, links, min_distance, slot } => {
                let (sol, d) = dyads::rpr_of(&pts[a], &pts[c]);
                if !every_lane(|k| dyads::rpr_check(d.0[k], min_distance).is_ok()) {
                    return false;
                }
                pts[a3] = sol.a3;
                self.links[links[0]] = sol.kulisa;
                self.links[links[1]] = sol.kulisa;
                self.slides[slot] = sol.slide;
            }
            StepPlan::Joint { point, from } => pts[point] = pts[from],
            StepPlan::Attach { point, link, from, toward, shape } => {
                pts[point] = dyads::attach_of(&pts[from], pts[toward].p, &self.links[link], &shape);
            }
        }
        true
    }

    #[inline(always)]
    fn set_dyad(&mut self, point: PointId, sol: Solved<Lanes>, links: [LinkId; 2]) {
        self.points[point] = sol.point;
        self.links[links[0]] = sol.first;
        self.links[links[1]] = sol.second;
    }

    /// Lane `k` set to the one angle's state `s`.
    pub fn set_lane(&mut self, k: usize, s: &State) {
        for (lanes, &kin) in self.points.iter_mut().zip(&s.points) {
            lanes.set_lane(k, kin);
        }
        for (lanes, &link) in self.links.iter_mut().zip(&s.links) {
            lanes.set_lane(k, link);
        }
        for (lanes, &i) in self.slides.iter_mut().zip(self.kulisas) {
            let (d, d_dot, d_ddot) = s.slides[i];
            (lanes.0.0[k], lanes.1.0[k], lanes.2.0[k]) = (d, d_dot, d_ddot);
        }
    }
}
