//! A whole turn solved at once, stored as the solver makes it: [`Turn`] keeps the angles in
//! blocks of [`LANES`], each block's points, links and slides as the SIMD lanes hold them
//! (`batch::Block`), so the batch writes its results once, in whole registers, where they
//! are kept. One angle's results are read through [`Turn::at`] (a [`Solution`]), or copied
//! into a [`State`] where a caller needs one to keep. Copying all 360 of the worked
//! example's turn into states instead, lane by lane, as the solver did before, took a third
//! of its time: 213 KB of writes scattered over 360 states' buffers, beyond the L1 cache.

use super::batch::{Block, SlideOf, StepPlan};
use super::kin::{Kin, LinkKin};
use super::lanes::{KinOf, LANES, Lanes, LinkOf};
use super::linkage::{LinkId, Mechanism, PointId, Solution, State, Step, StepFailure};
use kurbo::Vec2;

/// The points, links and slides of every angle of a turn (see the module's doc). Its
/// buffers are reused from one [`Mechanism::solve_turn`] to the next.
#[derive(Debug, Clone, Default)]
pub struct Turn {
    thetas: Vec<f64>,
    /// Block `b`'s point `id` at `b · points_per_block + id`; its lane `k` is angle
    /// `b · LANES + k`.
    points: Vec<KinOf<Lanes>>,
    links: Vec<LinkOf<Lanes>>,
    /// Only the kulisas' steps slide: block `b`'s slide of step `i` at
    /// `b · kulisas.len() + slot`, where `kulisas[slot] == i`.
    slides: Vec<SlideOf<Lanes>>,
    kulisas: Vec<usize>,
    /// The frame the blocks' fixed points hold. No step writes a frame point (a point is
    /// located once: `project::lever::build` refuses a name defined twice), so they are set
    /// only when the turn is sized for another mechanism or grows: setting them in every
    /// block at every solve took 0.8 µs of the worked example's 12.
    frame: Vec<(PointId, Vec2)>,
    points_per_block: usize,
    links_per_block: usize,
    steps: usize,
}

impl Turn {
    /// How many angles the turn holds.
    pub fn len(&self) -> usize {
        self.thetas.len()
    }

    pub fn is_empty(&self) -> bool {
        self.thetas.is_empty()
    }

    /// The absolute crank angle of position `k`, radians.
    pub fn theta(&self, k: usize) -> f64 {
        self.thetas[k]
    }

    /// Angle `k`'s block and lane. The last block's lanes past the turn's angles hold a
    /// repeat of its last angle, not an angle of their own: asking for one is a bug.
    #[inline]
    fn place(&self, k: usize) -> (usize, usize) {
        assert!(k < self.len(), "angle {k} of a turn of {}", self.len());
        (k / LANES, k % LANES)
    }

    /// Point `id` at angle `k`.
    #[inline]
    pub fn point(&self, k: usize, id: PointId) -> Kin {
        let (b, lane) = self.place(k);
        self.points[b * self.points_per_block + id].lane(lane)
    }

    /// Link `id` at angle `k`.
    #[inline]
    pub fn link(&self, k: usize, id: LinkId) -> LinkKin {
        let (b, lane) = self.place(k);
        self.links[b * self.links_per_block + id].lane(lane)
    }

    /// The slide of step `step` at angle `k` ([`State::slides`]): zero but for a kulisa's.
    pub fn slide(&self, k: usize, step: usize) -> (f64, f64, f64) {
        let (b, lane) = self.place(k);
        let Some(slot) = self.kulisas.iter().position(|&i| i == step) else { return (0.0, 0.0, 0.0) };
        let (d, d_dot, d_ddot) = self.slides[b * self.kulisas.len() + slot];
        (d.0[lane], d_dot.0[lane], d_ddot.0[lane])
    }

    /// Angle `k`'s results, read in place.
    pub fn at(&self, k: usize) -> At<'_> {
        self.place(k);
        At { turn: self, k }
    }

    /// Every angle's results, in the order of the angles.
    pub fn positions(&self) -> impl ExactSizeIterator<Item = At<'_>> {
        (0..self.len()).map(|k| At { turn: self, k })
    }

    /// Angle `k`'s results copied into `s` (its buffers reused), as
    /// [`Mechanism::solve_into`] leaves them.
    pub fn state_into(&self, k: usize, s: &mut State) {
        let (b, lane) = self.place(k);
        let (np, nl, ns) = (self.points_per_block, self.links_per_block, self.kulisas.len());
        s.theta = self.thetas[k];
        s.points.clear();
        s.points.extend(self.points[b * np..(b + 1) * np].iter().map(|kin| kin.lane(lane)));
        s.links.clear();
        s.links.extend(self.links[b * nl..(b + 1) * nl].iter().map(|link| link.lane(lane)));
        s.slides.clear();
        s.slides.resize(self.steps, (0.0, 0.0, 0.0));
        for (&(d, d_dot, d_ddot), &i) in self.slides[b * ns..(b + 1) * ns].iter().zip(&self.kulisas) {
            s.slides[i] = (d.0[lane], d_dot.0[lane], d_ddot.0[lane]);
        }
    }

    /// Sized for the angles `thetas` of `m`, every block's frame points set. The steps'
    /// results are left as they are: every step overwrites its own.
    fn prepare(&mut self, m: &Mechanism, thetas: &[f64]) {
        let kulisas = m.steps.iter().enumerate().filter(|(_, s)| matches!(s, Step::Rpr { .. })).map(|(i, _)| i);
        let same = self.frame == m.frame
            && self.points_per_block == m.point_names.len()
            && self.links_per_block == m.links.len()
            && self.steps == m.steps.len()
            && self.kulisas.iter().copied().eq(kulisas.clone());
        if !same {
            *self = Turn {
                kulisas: kulisas.collect(),
                frame: m.frame.clone(),
                points_per_block: m.point_names.len(),
                links_per_block: m.links.len(),
                steps: m.steps.len(),
                ..Turn::default()
            };
        }
        let blocks = thetas.len().div_ceil(LANES);
        self.thetas.clear();
        self.thetas.extend_from_slice(thetas);
        self.links.resize(blocks * self.links_per_block, LinkOf::default());
        self.slides.resize(blocks * self.kulisas.len(), SlideOf::default());
        let had = self.points.len() / self.points_per_block.max(1);
        self.points.resize(blocks * self.points_per_block, KinOf::default());
        for block in self.points.chunks_mut(self.points_per_block.max(1)).skip(had) {
            for &(id, p) in &self.frame {
                block[id] = KinOf::fixed(p);
            }
        }
    }

    /// Block `b` of [`LANES`] angles, ready to be solved.
    fn block(&mut self, b: usize) -> Block<'_> {
        let (np, nl, ns) = (self.points_per_block, self.links_per_block, self.kulisas.len());
        Block {
            points: &mut self.points[b * np..(b + 1) * np],
            links: &mut self.links[b * nl..(b + 1) * nl],
            slides: &mut self.slides[b * ns..(b + 1) * ns],
            kulisas: &self.kulisas,
        }
    }
}

/// One angle of a [`Turn`]: its results, read in place.
#[derive(Debug, Clone, Copy)]
pub struct At<'a> {
    turn: &'a Turn,
    k: usize,
}

impl At<'_> {
    /// This angle's results as a [`State`] of its own.
    pub fn state(&self) -> State {
        let mut s = State::default();
        self.turn.state_into(self.k, &mut s);
        s
    }
}

impl Solution for At<'_> {
    fn theta(&self) -> f64 {
        self.turn.theta(self.k)
    }
    fn point(&self, id: PointId) -> Kin {
        self.turn.point(self.k, id)
    }
    fn link(&self, id: LinkId) -> LinkKin {
        self.turn.link(self.k, id)
    }
}

impl Mechanism {
    /// Solves every angle of `thetas` into `turn` (its buffers reused): each angle's results
    /// are [`Mechanism::solve_into`]'s, bit for bit. [`LANES`] angles at a time, one per SIMD
    /// lane (`batch::Block`, the steps' constants found once for all; the last block's
    /// missing lanes repeat its last angle): the worked example's 360 positions in 0.41 of
    /// the time one at a time takes. An angle that fails a step is solved no further; the
    /// first angle that fails is returned with its index.
    pub fn solve_turn(&self, thetas: &[f64], turn: &mut Turn) -> Result<(), (usize, StepFailure)> {
        turn.prepare(self, thetas);
        let plans = StepPlan::all(self);
        let mut first_failure = None;
        let mut one = State::default();
        for (b, thetas) in thetas.chunks(LANES).enumerate() {
            let lanes = Lanes(std::array::from_fn(|k| thetas[k.min(thetas.len() - 1)]));
            let mut block = turn.block(b);
            if block.solve(&plans, self.omega1, lanes) {
                continue;
            }
            // A lane failed: each angle alone, to find which and why.
            for (k, &theta) in thetas.iter().enumerate() {
                if let Err(f) = self.solve_with(&plans, theta, &mut one) {
                    first_failure.get_or_insert((b * LANES + k, f));
                }
                block.set_lane(k, &one);
            }
        }
        first_failure.map_or(Ok(()), Err)
    }
}
