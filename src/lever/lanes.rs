//! Numbers for solving several crank angles at once. [`Real`] is what the dyads' closed forms
//! ask of a number: `f64` is one angle, [`Lanes`] is [`LANES`] angles side by side, one per
//! lane, each operation done lane by lane (the compiler makes them SIMD instructions). [`V2`]
//! is a plane vector of either, with kurbo's `Vec2` operations in kurbo's order (a division
//! by a scalar is a product with its reciprocal), so a lane's result is the one-angle result
//! bit for bit: IEEE 754 rounds +, −, ×, ÷ and √ exactly, in a SIMD lane as in a scalar.

use super::kin::{Kin, LinkKin};
use crate::num::math;
use kurbo::Vec2;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// How many angles [`Lanes`] holds: four `f64` fill two SSE2 registers, enough independent
/// work to keep the divider and the square root unit busy. Measured on the worked example's
/// turn (before the results were written from registers): two lanes took 1.2 times as long,
/// eight 1.8 times (the registers spill).
pub const LANES: usize = 4;

/// A number the dyads' closed forms can run on.
pub trait Real:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Neg<Output = Self>
{
    /// The constant `x` (in every lane).
    fn splat(x: f64) -> Self;
    fn sqrt(self) -> Self;
    /// `f64::max`.
    fn max(self, other: Self) -> Self;
    /// [`math::sin_cos`].
    fn sin_cos(self) -> (Self, Self);
}

impl Real for f64 {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        f64::max(self, other)
    }
    #[inline(always)]
    fn sin_cos(self) -> (Self, Self) {
        math::sin_cos(self)
    }
}

/// [`LANES`] numbers, one per angle.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Lanes(pub [f64; LANES]);

impl Lanes {
    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> Lanes {
        Lanes(self.0.map(f))
    }

    #[inline(always)]
    fn zip(self, other: Lanes, f: impl Fn(f64, f64) -> f64) -> Lanes {
        Lanes(std::array::from_fn(|i| f(self.0[i], other.0[i])))
    }
}

macro_rules! lane_by_lane {
    ($($op:ident $f:ident),*) => {$(
        impl $op for Lanes {
            type Output = Lanes;
            #[inline(always)]
            fn $f(self, other: Lanes) -> Lanes {
                self.zip(other, <f64 as $op>::$f)
            }
        }
    )*};
}
lane_by_lane!(Add add, Sub sub, Mul mul, Div div);

impl Neg for Lanes {
    type Output = Lanes;
    #[inline(always)]
    fn neg(self) -> Lanes {
        self.map(|x| -x)
    }
}

impl Real for Lanes {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Lanes([x; LANES])
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        self.map(f64::sqrt)
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        self.zip(other, f64::max)
    }
    /// Lane by lane through libm: its sine and cosine have no SIMD form that rounds alike.
    #[inline(always)]
    fn sin_cos(self) -> (Self, Self) {
        let sc = self.0.map(math::sin_cos);
        (Lanes(sc.map(|x| x.0)), Lanes(sc.map(|x| x.1)))
    }
}

/// A plane vector of [`Real`]s.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct V2<T> {
    pub x: T,
    pub y: T,
}

impl<T: Real> V2<T> {
    #[inline(always)]
    pub fn new(x: T, y: T) -> Self {
        V2 { x, y }
    }
    /// The constant vector `v` (in every lane).
    #[inline(always)]
    pub fn splat(v: Vec2) -> Self {
        V2::new(T::splat(v.x), T::splat(v.y))
    }
    #[inline(always)]
    pub fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y
    }
    #[inline(always)]
    pub fn cross(self, o: Self) -> T {
        self.x * o.y - self.y * o.x
    }
    #[inline(always)]
    pub fn hypot2(self) -> T {
        self.dot(self)
    }
    #[inline(always)]
    pub fn turn_90(self) -> Self {
        V2::new(-self.y, self.x)
    }
}

impl<T: Real> Add for V2<T> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        V2::new(self.x + o.x, self.y + o.y)
    }
}

impl<T: Real> Sub for V2<T> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        V2::new(self.x - o.x, self.y - o.y)
    }
}

impl<T: Real> Neg for V2<T> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        V2::new(-self.x, -self.y)
    }
}

impl<T: Real> Mul<T> for V2<T> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, k: T) -> Self {
        V2::new(self.x * k, self.y * k)
    }
}

/// As kurbo divides: by the product with the reciprocal.
impl<T: Real> Div<T> for V2<T> {
    type Output = Self;
    #[inline(always)]
    fn div(self, k: T) -> Self {
        self * (T::splat(1.0) / k)
    }
}

impl From<Vec2> for V2<f64> {
    #[inline(always)]
    fn from(v: Vec2) -> Self {
        V2::new(v.x, v.y)
    }
}

impl From<V2<f64>> for Vec2 {
    #[inline(always)]
    fn from(v: V2<f64>) -> Self {
        Vec2::new(v.x, v.y)
    }
}

impl V2<Lanes> {
    /// Lane `k`'s vector.
    #[inline(always)]
    pub fn lane(self, k: usize) -> Vec2 {
        Vec2::new(self.x.0[k], self.y.0[k])
    }

    /// Lane `k` set to `v`.
    #[inline(always)]
    pub fn set_lane(&mut self, k: usize, v: Vec2) {
        (self.x.0[k], self.y.0[k]) = (v.x, v.y);
    }
}

/// [`Kin`] of [`Real`]s.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct KinOf<T> {
    pub p: V2<T>,
    pub v: V2<T>,
    pub a: V2<T>,
}

/// [`LinkKin`] of [`Real`]s.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LinkOf<T> {
    pub dir: V2<T>,
    pub omega: T,
    pub eps: T,
}

impl From<Kin> for KinOf<f64> {
    #[inline(always)]
    fn from(k: Kin) -> Self {
        KinOf { p: k.p.into(), v: k.v.into(), a: k.a.into() }
    }
}

impl From<KinOf<f64>> for Kin {
    #[inline(always)]
    fn from(k: KinOf<f64>) -> Self {
        Kin { p: k.p.into(), v: k.v.into(), a: k.a.into() }
    }
}

impl From<LinkOf<f64>> for LinkKin {
    #[inline(always)]
    fn from(l: LinkOf<f64>) -> Self {
        LinkKin { dir: l.dir.into(), omega: l.omega, eps: l.eps }
    }
}

impl From<LinkKin> for LinkOf<f64> {
    #[inline(always)]
    fn from(l: LinkKin) -> Self {
        LinkOf { dir: l.dir.into(), omega: l.omega, eps: l.eps }
    }
}

impl KinOf<Lanes> {
    /// The fixed point `p` in every lane.
    pub fn fixed(p: Vec2) -> Self {
        KinOf { p: V2::splat(p), v: V2::default(), a: V2::default() }
    }

    /// Lane `k`'s point.
    #[inline(always)]
    pub fn lane(&self, k: usize) -> Kin {
        Kin { p: self.p.lane(k), v: self.v.lane(k), a: self.a.lane(k) }
    }

    /// Lane `k` set to `kin`.
    #[inline(always)]
    pub fn set_lane(&mut self, k: usize, kin: Kin) {
        self.p.set_lane(k, kin.p);
        self.v.set_lane(k, kin.v);
        self.a.set_lane(k, kin.a);
    }
}

impl LinkOf<Lanes> {
    /// Lane `k`'s link.
    #[inline(always)]
    pub fn lane(&self, k: usize) -> LinkKin {
        LinkKin { dir: self.dir.lane(k), omega: self.omega.0[k], eps: self.eps.0[k] }
    }

    /// Lane `k` set to `link`.
    #[inline(always)]
    pub fn set_lane(&mut self, k: usize, link: LinkKin) {
        self.dir.set_lane(k, link.dir);
        (self.omega.0[k], self.eps.0[k]) = (link.omega, link.eps);
    }
}
