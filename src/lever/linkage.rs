//! A resolved mechanism: named points, numbered links, and the ordered steps
//! (crank, Assur dyads, points attached to links) that solve it at any crank angle.

use super::batch::StepPlan;
use super::dyads::{self, DyadFailure};
use super::kin::{Kin, LinkKin};
use super::lanes::{KinOf, LinkOf};
use crate::num::Sense;
use crate::num::math::Norm;
use kurbo::Vec2;

/// Index of a point in [`Mechanism::point_names`].
pub type PointId = usize;
/// Index of a link in [`Mechanism::links`] (not the course's link number).
pub type LinkId = usize;

/// How a link moves, for drawing and for the tables.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LinkKind {
    Crank,
    /// A link turning about a frame pivot (rocker, kulisa).
    Rocker,
    /// A link in plane motion (coupler, connecting rod).
    Coupler,
    /// A translating slider.
    Slider,
    /// The block of a kulisa: turns with the kulisa, slides along it.
    Block,
}

#[derive(Debug, Clone)]
pub struct Link {
    /// The course's link number (1 = crank, 0 = frame).
    pub number: u32,
    pub kind: LinkKind,
    /// Points carried by the link, in drawing order.
    pub points: Vec<PointId>,
}

/// The Assur dyads, in the course's notation of their pairs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DyadKind {
    Rrr,
    Rrp,
    Rpr,
}

impl DyadKind {
    pub fn code(self) -> &'static str {
        match self {
            DyadKind::Rrr => "RRR",
            DyadKind::Rrp => "RRP",
            DyadKind::Rpr => "RPR",
        }
    }
}

/// One step of the solution, executed in order.
#[derive(Debug, Clone)]
pub enum Step {
    Crank {
        pivot: PointId,
        pin: PointId,
        length: f64,
        link: LinkId,
    },
    Rrr {
        p: PointId,
        q: PointId,
        b: PointId,
        l_pb: f64,
        l_qb: f64,
        branch: f64,
        links: [LinkId; 2],
    },
    Rrp {
        p: PointId,
        d: PointId,
        length: f64,
        through: Vec2,
        dir: Vec2,
        branch: f64,
        links: [LinkId; 2],
    },
    /// Block pinned at `a` slides on the kulisa turning about `c`; `a3` is the kulisa's
    /// point under the block. Links are `[block, kulisa]`.
    Rpr {
        a: PointId,
        c: PointId,
        a3: PointId,
        links: [LinkId; 2],
    },
    /// A point fixed to `link`: `distance` from `from` along the direction `from → toward`
    /// turned by `angle` (counter-clockwise, radians). `ratio` is distance / |from → toward|
    /// when the link fixes that distance, which saves a square root per solve.
    Attach {
        point: PointId,
        link: LinkId,
        from: PointId,
        toward: PointId,
        distance: f64,
        angle: f64,
        ratio: Option<f64>,
    },
}

/// An Assur group as the note describes it: which step, which links.
#[derive(Debug, Clone)]
pub struct Group {
    pub kind: DyadKind,
    pub step: usize,
    pub links: [LinkId; 2],
    /// The new point the group locates (B of an RRR, D of an RRP, A3 of an RPR).
    pub point: PointId,
    /// Its joints to the rest of the chain (for the structural formula and plans).
    pub inputs: Vec<PointId>,
    /// Line of the project file that defines it (0 when unknown), for error messages.
    pub line: u64,
}

/// The output coordinate whose extremes define position 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Output {
    /// Displacement of a slider point along its guide direction.
    Slider { point: PointId, dir: Vec2 },
    /// Angle of a rocker (or kulisa) link.
    Rocker { link: LinkId },
}

#[derive(Debug, Clone)]
pub struct Mechanism {
    pub point_names: Vec<String>,
    /// Frame points with their fixed positions.
    pub frame: Vec<(PointId, Vec2)>,
    pub links: Vec<Link>,
    pub steps: Vec<Step>,
    pub groups: Vec<Group>,
    /// Signed crank speed, rad/s, counter-clockwise positive.
    pub omega1: f64,
    /// Crank angle (absolute, radians) is `theta0 + sense·φ`; see [`super::motion`].
    pub output: Output,
    /// Centres of mass, as (link, point).
    pub mass_centres: Vec<(LinkId, PointId)>,
    /// The mechanism's size (m): its longest link, or the frame's extent if larger. Lengths
    /// below [`tol::SAME_POINT`](crate::num::tol::SAME_POINT) of it are zero.
    pub size: f64,
}

/// Everything known about the mechanism at one crank angle.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct State {
    pub theta: f64,
    pub points: Vec<Kin>,
    pub links: Vec<LinkKin>,
    /// Sliding distance along each kulisa and its derivatives, indexed like `steps`.
    pub slides: Vec<(f64, f64, f64)>,
}

/// What the solver found at one crank angle, wherever it is kept: a [`State`], or one angle
/// of a [`Turn`](super::Turn) ([`Turn::at`](super::Turn::at)), read in place.
pub trait Solution {
    /// The absolute crank angle, radians.
    fn theta(&self) -> f64;
    fn point(&self, id: PointId) -> Kin;
    fn link(&self, id: LinkId) -> LinkKin;
}

impl Solution for State {
    fn theta(&self) -> f64 {
        self.theta
    }
    fn point(&self, id: PointId) -> Kin {
        self.points[id]
    }
    fn link(&self, id: LinkId) -> LinkKin {
        self.links[id]
    }
}

/// A failed step: which one, and why. [`super::motion`] turns it into a message that names
/// the Assur group and the crank angles.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("step {} of the mechanism has no solution: {why}", step + 1)]
pub struct StepFailure {
    pub step: usize,
    pub why: DyadFailure,
}

/// The driving link: its frame pivot, its pin, its length and its link.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crank {
    pub pivot: PointId,
    pub pin: PointId,
    pub length: f64,
    pub link: LinkId,
}

impl Mechanism {
    /// The crank's sense of rotation, the sign of ω1.
    pub fn sense(&self) -> Sense {
        Sense::of(self.omega1)
    }

    /// The crank, which the model always makes the first step.
    pub fn crank(&self) -> Crank {
        match self.steps.first() {
            Some(&Step::Crank { pivot, pin, length, link }) => Crank { pivot, pin, length, link },
            _ => unreachable!("the model makes the crank the first step"),
        }
    }

    pub fn point_id(&self, name: &str) -> Option<PointId> {
        self.point_names.iter().position(|n| n == name)
    }

    pub fn name(&self, id: PointId) -> &str {
        &self.point_names[id]
    }

    /// A fixed point of the frame.
    pub fn is_frame(&self, id: PointId) -> bool {
        self.frame.iter().any(|&(f, _)| f == id)
    }

    /// The point of a kulisa under its block (A3): a material point of the kulisa at this
    /// instant, not a joint.
    pub fn is_kulisa_image(&self, id: PointId) -> bool {
        self.steps.iter().any(|s| matches!(*s, Step::Rpr { a3, .. } if a3 == id))
    }

    pub fn is_mass_centre(&self, id: PointId) -> bool {
        self.mass_centres.iter().any(|&(_, p)| p == id)
    }

    /// The link with the course number `number`.
    pub fn link_by_number(&self, number: u32) -> Option<LinkId> {
        self.links.iter().position(|l| l.number == number)
    }

    /// Index of the group solved by step `step`, if the step is a group.
    pub fn group_of_step(&self, step: usize) -> Option<usize> {
        self.groups.iter().position(|g| g.step == step)
    }

    /// Solves positions, velocities and accelerations at absolute crank angle `theta`.
    pub fn solve(&self, theta: f64) -> Result<State, StepFailure> {
        let mut s = State::default();
        self.solve_into(theta, &mut s)?;
        Ok(s)
    }

    /// Like [`Mechanism::solve`], reusing the buffers of `s` (no allocation after the first
    /// call). A whole turn is quicker solved at once, [`Mechanism::solve_turn`].
    pub fn solve_into(&self, theta: f64, s: &mut State) -> Result<(), StepFailure> {
        self.prepare(theta, s);
        for (i, step) in self.steps.iter().enumerate() {
            self.run_step(i, &StepPlan::of(step, self), s).map_err(|why| StepFailure { step: i, why })?;
        }
        Ok(())
    }

    /// Solves `plans` (this mechanism's) at crank angle `theta` into `s`, up to the first
    /// step that fails.
    pub(super) fn solve_with(&self, plans: &[StepPlan], theta: f64, s: &mut State) -> Result<(), StepFailure> {
        self.prepare(theta, s);
        self.run_steps(plans, s)
    }

    /// Runs `plans` on the prepared state `s`, up to the first step that fails.
    fn run_steps(&self, plans: &[StepPlan], s: &mut State) -> Result<(), StepFailure> {
        for (i, plan) in plans.iter().enumerate() {
            self.run_step(i, plan, s).map_err(|why| StepFailure { step: i, why })?;
        }
        Ok(())
    }

    /// `s` ready for the steps at crank angle `theta`: its buffers sized (every entry is
    /// overwritten by its step, so they are only resized, not cleared) and the frame's
    /// points set.
    fn prepare(&self, theta: f64, s: &mut State) {
        s.theta = theta;
        s.points.resize(self.point_names.len(), Kin::default());
        s.links.resize(self.links.len(), LinkKin::default());
        s.slides.resize(self.steps.len(), (0.0, 0.0, 0.0));
        for &(id, p) in &self.frame {
            s.points[id] = Kin::fixed(p);
        }
    }

    /// Step `i` at the angle `s.theta`.
    #[inline(always)]
    fn run_step(&self, i: usize, plan: &StepPlan, s: &mut State) -> Result<(), DyadFailure> {
        let kin = |id: PointId| KinOf::from(s.points[id]);
        match *plan {
            StepPlan::Crank { pivot, pin, length, inv_length, link } => {
                let (k, l) = dyads::crank_of(&kin(pivot), length, inv_length, s.theta, self.omega1);
                s.points[pin] = k.into();
                s.links[link] = l.into();
            }
            StepPlan::Rrr { p, q, b, shape, links } => {
                let (sol, d2, cross) = dyads::rrr_of(&kin(p), &kin(q), &shape);
                shape.check(d2, cross)?;
                s.points[b] = sol.point.into();
                s.links[links[0]] = sol.first.into();
                s.links[links[1]] = sol.second.into();
            }
            StepPlan::Rrp { p, d, shape, links } => {
                let (sol, h, along) = dyads::rrp_of(&kin(p), &shape);
                shape.check(h, along)?;
                s.points[d] = sol.point.into();
                s.links[links[0]] = sol.first.into();
                s.links[links[1]] = sol.second.into();
            }
            StepPlan::Rpr { a, c, a3, links, min_distance, .. } => {
                let (sol, d) = dyads::rpr_of(&kin(a), &kin(c));
                dyads::rpr_check(d, min_distance)?;
                s.points[a3] = sol.a3.into();
                s.links[links[0]] = sol.kulisa.into();
                s.links[links[1]] = sol.kulisa.into();
                s.slides[i] = sol.slide;
            }
            // a point coinciding with a joint, e.g. a slider's centre of mass
            StepPlan::Joint { point, from } => s.points[point] = s.points[from],
            StepPlan::Attach { point, link, from, toward, shape } => {
                let lk = LinkOf::from(s.links[link]);
                s.points[point] = dyads::attach_of(&kin(from), kin(toward).p, &lk, &shape).into();
            }
        }
        Ok(())
    }

    /// The size [`Mechanism::size`] holds: the longest fixed length, or the frame's extent.
    pub fn measure_size(&self) -> f64 {
        let lengths = self.steps.iter().flat_map(|s| match *s {
            Step::Crank { length, .. } => vec![length],
            Step::Rrr { l_pb, l_qb, .. } => vec![l_pb, l_qb],
            Step::Rrp { length, .. } => vec![length],
            Step::Rpr { .. } => vec![],
            Step::Attach { distance, .. } => vec![distance.abs()],
        });
        let frame = self.frame.iter().flat_map(|a| self.frame.iter().map(move |b| (a.1 - b.1).norm()));
        lengths.chain(frame).fold(0.0, f64::max)
    }

    /// How far each Assur group is from failing to assemble at `s`, as (step, margin): 0 at
    /// a dead point, positive where it assembles, relative to the group's links.
    pub fn margins<'a, S: Solution + ?Sized>(&'a self, s: &'a S) -> impl Iterator<Item = (usize, f64)> + 'a {
        let p = |id: PointId| s.point(id).p;
        self.steps.iter().enumerate().filter_map(move |(i, step)| {
            let margin = match *step {
                Step::Rrr { p: a, q, l_pb, l_qb, .. } => {
                    let d = (p(q) - p(a)).norm();
                    (d - (l_pb - l_qb).abs()).min(l_pb + l_qb - d) / (l_pb + l_qb)
                }
                Step::Rrp { p: a, through, dir, length, .. } => (length - (p(a) - through).cross(dir).abs()) / length,
                Step::Rpr { a, c, .. } => (p(a) - p(c)).norm() / self.size,
                Step::Crank { .. } | Step::Attach { .. } => return None,
            };
            Some((i, margin))
        })
    }

    /// Value of the output coordinate and its time derivative.
    pub fn output_value<S: Solution + ?Sized>(&self, s: &S) -> (f64, f64) {
        match self.output {
            Output::Slider { point, dir } => {
                let k = s.point(point);
                (k.p.dot(dir), k.v.dot(dir))
            }
            Output::Rocker { link } => {
                let l = s.link(link);
                (l.angle(), l.omega)
            }
        }
    }
}
