//! The two schemes and their tooth numbers by role: the ratio u_1H and the integers the
//! conditions are decided in (the coaxial sum, the assembly number, the reducer's size).

use std::fmt;

/// The kinematic scheme of the stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scheme {
    SunPlanetRing,
    DoublePlanet,
}

impl Scheme {
    pub const ALL: [Scheme; 2] = [Scheme::SunPlanetRing, Scheme::DoublePlanet];

    /// The name the project file uses.
    pub fn key(self) -> &'static str {
        match self {
            Scheme::SunPlanetRing => "sun-planet-ring",
            Scheme::DoublePlanet => "double-planet",
        }
    }

    /// How many tooth numbers the scheme has: [z1, z2, z3] or [z1, z2, z2', z3].
    pub fn teeth(self) -> usize {
        match self {
            Scheme::SunPlanetRing => 3,
            Scheme::DoublePlanet => 4,
        }
    }

    /// u_1H of the tooth numbers `z`; 0.0 (no ratio, since u_1H > 1 always) when `z` has the
    /// wrong count or a zero, so that no input yields a non-finite number ([`check`](super::check) refuses
    /// such input with [`StageError::BadTeeth`](super::StageError::BadTeeth)).
    pub fn ratio(self, z: &[u32]) -> f64 {
        Teeth::of(self, z).map_or(0.0, Teeth::ratio)
    }
}

impl fmt::Display for Scheme {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// The teeth by role; the single row has one planet gear, so `planet_sun == planet_ring`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Teeth {
    pub(super) sun: u32,
    /// z2, meshing the sun.
    pub(super) planet_sun: u32,
    /// z2' (z2 in the single row), meshing the ring.
    pub(super) planet_ring: u32,
    pub(super) ring: u32,
}

impl Teeth {
    pub(super) fn of(scheme: Scheme, z: &[u32]) -> Option<Teeth> {
        if z.contains(&0) {
            return None;
        }
        match (scheme, z) {
            (Scheme::SunPlanetRing, &[sun, planet, ring]) => {
                Some(Teeth { sun, planet_sun: planet, planet_ring: planet, ring })
            }
            (Scheme::DoublePlanet, &[sun, planet_sun, planet_ring, ring]) => {
                Some(Teeth { sun, planet_sun, planet_ring, ring })
            }
            _ => None,
        }
    }

    pub(super) fn to_vec(self, scheme: Scheme) -> Vec<u32> {
        match scheme {
            Scheme::SunPlanetRing => vec![self.sun, self.planet_sun, self.ring],
            Scheme::DoublePlanet => vec![self.sun, self.planet_sun, self.planet_ring, self.ring],
        }
    }

    /// u_1H = 1 + z2·z3/(z1·z2'); with one planet gear written as 1 + z3/z1, the guide's form.
    pub(super) fn ratio(self) -> f64 {
        let [z1, z2, z2b, z3] = [self.sun, self.planet_sun, self.planet_ring, self.ring].map(u64::from);
        if z2 == z2b { 1.0 + z3 as f64 / z1 as f64 } else { 1.0 + (z2 * z3) as f64 / (z1 * z2b) as f64 }
    }

    /// z1 + z2 + z2' (z1 + 2z2): the ring's teeth for equal centre distances in both meshes.
    pub(super) fn coaxial_sum(self) -> u64 {
        u64::from(self.sun) + u64::from(self.planet_sun) + u64::from(self.planet_ring)
    }

    /// (max(z2, z2') + 2h_a*)/(z1 + z2): the planet's tip diameter over the distance from
    /// the sun's centre, in modules; sin(π/K) must exceed it for the tips of neighbours to
    /// clear each other (their centres are 2a·sin(π/K) apart).
    pub(super) fn neighbour_limit(self, addendum: f64) -> f64 {
        let largest = self.planet_sun.max(self.planet_ring);
        (f64::from(largest) + 2.0 * addendum) / (u64::from(self.sun) + u64::from(self.planet_sun)) as f64
    }

    /// (z1·z2' + z2·z3)/gcd(z2, z2') (z1 + z3 in the single row): K planets can be put in
    /// evenly spaced only when K divides it.
    pub(super) fn assembly_number(self) -> u128 {
        let [z1, z2, z2b, z3] = [self.sun, self.planet_sun, self.planet_ring, self.ring].map(u128::from);
        (z1 * z2b + z2 * z3) / u128::from(gcd(self.planet_sun, self.planet_ring))
    }

    /// The reducer's outer diameter in modules (tips aside): the ring, or a double planet's
    /// larger gear z2 reaching past it (2a + z2 = z1 + 2·z2); the single row has z1 + 2z2 = z3.
    pub(super) fn size(self) -> u32 {
        self.ring.max(self.sun + 2 * self.planet_sun)
    }

    pub(super) fn smallest_external(self) -> u32 {
        self.sun.min(self.planet_sun).min(self.planet_ring)
    }

    /// z3 − z2', signed: an arbitrary set given to [`check`] may have a smaller ring.
    pub(super) fn ring_planet_difference(self) -> i64 {
        i64::from(self.ring) - i64::from(self.planet_ring)
    }
}

fn gcd(a: u32, b: u32) -> u32 {
    let (mut a, mut b) = (a, b);
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gcd_does_not_return_zero() {
        assert_eq!(gcd(12, 18), 6);
        assert_eq!(gcd(0, 0), 1);
    }
}
