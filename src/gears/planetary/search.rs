//! The search for the best valid set: only the candidates near the ratio, and no ring larger
//! than the best found so far; the ratios the scheme reaches, for a refusal's message.

use super::conditions::{check, conditions, validate_search, within};
use super::scheme::Teeth;
use super::{
    EXACT_RATIO, EXACT_SIZE_ALLOWANCE, PLANETS_SEARCHED, RING_PLANET_DIFFERENCE, Scheme, Stage, StageError, StageSpec,
};
use crate::num::math::sin;
use std::f64::consts::PI;

/// A candidate that met every condition.
#[derive(Debug, Clone, Copy)]
struct Found {
    teeth: Teeth,
    planets: u32,
    ratio: f64,
}

/// The search over one spec: the planets it may use with their sin(π/K), computed once.
struct Search<'a> {
    spec: &'a StageSpec,
    planets: Vec<(u32, f64)>,
    /// The largest of the sines: the neighbour condition's most lenient form.
    sin_max: f64,
}

impl<'a> Search<'a> {
    fn new(spec: &'a StageSpec) -> Search<'a> {
        let ks = match spec.planets {
            Some(k) => k..=k,
            None => PLANETS_SEARCHED,
        };
        let planets: Vec<(u32, f64)> = ks.map(|k| (k, sin(PI / f64::from(k)))).collect();
        let sin_max = planets.iter().map(|&(_, sin_k)| sin_k).fold(0.0, f64::max);
        Search { spec, planets, sin_max }
    }

    /// The conditions that do not depend on K or on the ratio, in integers.
    fn fixed_ok(&self, t: Teeth) -> bool {
        let s = self.spec;
        t.coaxial_sum() == u64::from(t.ring)
            && t.smallest_external() >= s.z_min
            && t.ring >= s.ring_min
            && t.ring_planet_difference() > i64::from(RING_PLANET_DIFFERENCE)
    }

    /// The numbers of planets with which `t` meets every condition but the ratio, cheaply
    /// (the sines are tabled); the same formulas as [`conditions`].
    fn planets_for(&self, t: Teeth) -> impl Iterator<Item = u32> + '_ {
        let fits = self.fixed_ok(t);
        let limit = t.neighbour_limit(self.spec.addendum);
        let number = t.assembly_number();
        self.planets
            .iter()
            .filter(move |&&(k, sin_k)| fits && sin_k > limit && number.is_multiple_of(u128::from(k)))
            .map(|&(k, _)| k)
    }

    /// Keeps `t` if it is valid and better than `best`; a set replaces `best` only after the
    /// full [`conditions`] (those of [`check`]) all hold for it.
    fn consider(&self, t: Teeth, best: &mut Option<Found>) {
        let s = self.spec;
        let ratio = t.ratio();
        if !within(ratio, s.ratio_required, s.tolerance) {
            return;
        }
        for planets in self.planets_for(t) {
            let found = Found { teeth: t, planets, ratio };
            if best.is_none_or(|b| self.better(&found, &b)) && conditions(s, t, planets).iter().all(|c| c.ok) {
                *best = Some(found);
            }
        }
    }

    /// The smallest reducer (its outer diameter: the ring, or a double planet's larger gear),
    /// then the closest ratio, then more planets (lighter loaded), then the smallest sun; the
    /// tooth numbers last make the order total.
    fn better(&self, a: &Found, b: &Found) -> bool {
        let error = |f: &Found| (f.ratio - self.spec.ratio_required).abs();
        let key = |f: &Found| (f.teeth.ring, std::cmp::Reverse(f.planets), f.teeth.sun, f.teeth.planet_sun);
        a.teeth.size().cmp(&b.teeth.size()).then(error(a).total_cmp(&error(b))).then(key(a).cmp(&key(b))).is_lt()
    }

    /// The best set of the spec's scheme, `None` when no set meets every condition.
    fn best(&self) -> Option<Found> {
        match self.spec.scheme {
            Scheme::SunPlanetRing => self.single_row(),
            Scheme::DoublePlanet => self.double_planet(),
        }
    }

    /// The ratio window [u(1 − tol), u(1 + tol)].
    fn window(&self) -> (f64, f64) {
        let s = self.spec;
        (s.ratio_required * (1.0 - s.tolerance), s.ratio_required * (1.0 + s.tolerance))
    }

    /// Single row: for each z1 the rings whose ratio 1 + z3/z1 falls in the window (one
    /// either side to spare the rounding), of the parity that makes z2 = (z3 − z1)/2 whole.
    fn single_row(&self) -> Option<Found> {
        let s = self.spec;
        let (lo, hi) = self.window();
        let mut best: Option<Found> = None;
        for z1 in s.z_min..=s.z_max {
            // No ring larger than the best reducer found can win (its size is at least its ring).
            let ring_max = best.map_or(s.z_max, |b| b.teeth.size());
            let first = floor_u32((lo - 1.0) * f64::from(z1)).saturating_sub(1).max(z1 + 2 * s.z_min).max(s.ring_min);
            let last = ceil_u32((hi - 1.0) * f64::from(z1)).saturating_add(1).min(ring_max);
            for z3 in (first..=last).filter(|z3| (z3 - z1) % 2 == 0) {
                let z2 = (z3 - z1) / 2;
                self.consider(Teeth { sun: z1, planet_sun: z2, planet_ring: z2, ring: z3 }, &mut best);
            }
        }
        best
    }

    /// Double planet: for each z1 and z2', u − 1 = z2·(z1 + z2 + z2')/(z1·z2') is a quadratic
    /// in z2 increasing with it; the z2 between the roots for the window's ends (one either
    /// side to spare the rounding) are the only candidates.
    fn double_planet(&self) -> Option<Found> {
        let s = self.spec;
        let (lo, hi) = self.window();
        let mut best: Option<Found> = None;
        for z1 in s.z_min..=s.z_max {
            // No ring larger than the best reducer found can win (its size is at least its ring).
            let ring_max = best.map_or(s.z_max, |b| b.teeth.size());
            for z2b in s.z_min..=ring_max.saturating_sub(z1 + s.z_min) {
                let room = ring_max - z1 - z2b;
                let b = f64::from(z1 + z2b);
                let c = f64::from(z1) * f64::from(z2b);
                let root = |u: f64| (-b + (b * b + 4.0 * (u - 1.0) * c).sqrt()) / 2.0;
                let (near, far) = self.neighbour_span(z1, Some(z2b));
                let first = floor_u32(root(lo)).saturating_sub(1).max(s.z_min).max(near);
                let last = ceil_u32(root(hi)).saturating_add(1).min(room).min(far);
                for z2 in first..=last {
                    let t = Teeth { sun: z1, planet_sun: z2, planet_ring: z2b, ring: z1 + z2 + z2b };
                    self.consider(t, &mut best);
                }
            }
        }
        best
    }

    /// The z2 for which neighbours can hold with the largest sin(π/K) allowed (padded by
    /// one): z2' + 2h_a* < (z1 + z2)·s and z2 + 2h_a* < (z1 + z2)·s.
    fn neighbour_span(&self, z1: u32, z2b: Option<u32>) -> (u32, u32) {
        let s = self.sin_max;
        let h2 = 2.0 * self.spec.addendum;
        let z1f = f64::from(z1);
        let low = z2b.map_or(0.0, |z| (f64::from(z) + h2) / s - z1f);
        let high = if s < 1.0 { (z1f * s - h2) / (1.0 - s) } else { f64::INFINITY };
        (floor_u32(low), ceil_u32(high))
    }

    /// Widens `span` to the least and the largest ratio among the z2 in `first..=last` that
    /// meet every condition but the ratio. The ratio grows with z2, so only the z2 whose
    /// ratio lies below the span can lower its start (scanned upward to the first valid set),
    /// and only those above it can raise its end.
    fn extremes(&self, first: u32, last: u32, teeth: impl Fn(u32) -> Teeth, span: &mut Option<(f64, f64)>) {
        let valid = |z2: &u32| self.planets_for(teeth(*z2)).next().is_some();
        let (lo, hi) = span.unwrap_or((f64::INFINITY, f64::NEG_INFINITY));
        let low = (first..=last).take_while(|&z2| teeth(z2).ratio() < lo).find(valid);
        let high = (first..=last).rev().take_while(|&z2| teeth(z2).ratio() > hi).find(valid);
        let lo = low.map_or(lo, |z2| teeth(z2).ratio().min(lo));
        let hi = high.map_or(hi, |z2| teeth(z2).ratio().max(hi));
        if lo <= hi {
            *span = Some((lo, hi));
        }
    }

    /// The ratios the scheme reaches within the spec's limits, for the refusal's message.
    fn reachable(&self) -> Option<(f64, f64)> {
        let s = self.spec;
        let mut span = None;
        for z1 in s.z_min..=s.z_max {
            match s.scheme {
                Scheme::SunPlanetRing => {
                    let (low, high) = self.neighbour_span(z1, None);
                    let ring_low = s.ring_min.saturating_sub(z1).div_ceil(2);
                    let first = low.max(s.z_min).max(ring_low);
                    let last = high.min(s.z_max.saturating_sub(z1) / 2);
                    let teeth = |z2| Teeth { sun: z1, planet_sun: z2, planet_ring: z2, ring: z1 + 2 * z2 };
                    self.extremes(first, last, teeth, &mut span);
                }
                Scheme::DoublePlanet => {
                    for z2b in s.z_min..=s.z_max.saturating_sub(z1 + s.z_min) {
                        let (low, high) = self.neighbour_span(z1, Some(z2b));
                        let first = low.max(s.z_min).max(s.ring_min.saturating_sub(z1 + z2b));
                        let last = high.min(s.z_max - z1 - z2b);
                        let teeth = |z2| Teeth { sun: z1, planet_sun: z2, planet_ring: z2b, ring: z1 + z2 + z2b };
                        self.extremes(first, last, teeth, &mut span);
                    }
                }
            }
        }
        span
    }
}

/// The smallest set giving the required ratio exactly (to [`EXACT_RATIO`]) whose size is at
/// most [`EXACT_SIZE_ALLOWANCE`] times the smallest reducer's: a teacher asks why u = 4.909
/// was drawn when 24/36/96 gives 5 exactly; a reducer a quarter larger is the price the course
/// pays for that, a ring of 373 teeth for u = 4.73 is not. `None` when the smallest reducer is
/// already exact or no exact set is near its size.
fn exact_nearby(spec: &StageSpec, smallest: Found) -> Option<Found> {
    if (smallest.ratio - spec.ratio_required).abs() <= EXACT_RATIO * spec.ratio_required {
        return None;
    }
    let allowed = (f64::from(smallest.teeth.size()) * EXACT_SIZE_ALLOWANCE).floor() as u32;
    let exact = StageSpec { tolerance: EXACT_RATIO, z_max: spec.z_max.min(allowed), ..spec.clone() };
    // Every tooth number of a set is at most its size, so `z_max` bounds the search; the best
    // set is the smallest, so it alone need be measured against the allowance.
    Search::new(&exact).best().filter(|f| f.teeth.size() <= allowed)
}

/// ⌊x⌋ as a tooth number: 0 below zero or for NaN, saturated above (Rust's casts saturate).
fn floor_u32(x: f64) -> u32 {
    x.floor() as u32
}

fn ceil_u32(x: f64) -> u32 {
    x.ceil() as u32
}

/// The best valid set: ratio within the tolerance and every condition of [`check`] met;
/// the smallest reducer (the ring z3, or z1 + 2·z2 when a double planet's larger gear reaches
/// past it) first, then the smallest |ratio error|, then more
/// planets, then the smallest z1 — unless a set at most [`EXACT_SIZE_ALLOWANCE`] times that
/// size gives the required ratio exactly: then the smallest such set, in the same order.
///
/// It runs when a sheet is built and inside property tests, so it visits only the
/// candidates near the ratio (a window of z3 per z1, or of z2 per z1 and z2'), and no ring
/// larger than the best found so far. Measured in a release build (ratios 2–50 in steps of
/// 0.1, the ignored `search_time` test of `tests/planetary.rs`), with the course's limits
/// (z ≤ 400): at most 0.05 ms for the single row and 0.13 ms for the double planet with K
/// searched; with K fixed, when most ratios are refused and the refusal scans for the
/// reachable ratios, at most 0.2 ms and 3 ms; with z ≤ 1000 at most 25 ms.
pub fn synthesise(spec: &StageSpec) -> Result<Stage, StageError> {
    validate_search(spec)?;
    let search = Search::new(spec);
    let found = search.best().map(|smallest| exact_nearby(spec, smallest).unwrap_or(smallest));
    let Some(found) = found else {
        return Err(StageError::NoSet {
            scheme: spec.scheme,
            ratio: spec.ratio_required,
            tolerance: spec.tolerance,
            reachable: search.reachable(),
            planets: spec.planets,
            z_max: spec.z_max,
        });
    };
    let z = found.teeth.to_vec(spec.scheme);
    let conditions = check(spec, &z, found.planets)?;
    Ok(Stage {
        scheme: spec.scheme,
        z,
        planets: found.planets,
        ratio: found.ratio,
        ratio_required: spec.ratio_required,
        tolerance: spec.tolerance,
        conditions,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rounding_helpers_do_not_panic() {
        assert_eq!(floor_u32(f64::NAN), 0);
        assert_eq!(ceil_u32(1e300), u32::MAX);
    }
}
