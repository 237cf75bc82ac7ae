//! The `mechanism` and `analysis` sections: the lever mechanism of sheet 1 in the course's
//! terms (frame points, crank, Assur groups in order of formation, points on links) and
//! which positions the sheet draws.

use super::values::{Finite, LocalText, Name, Positive};
use crate::num::Sense;
use serde::Deserialize;
use serde_saphyr::Spanned;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MechanismSpec {
    /// Fixed points of the frame, [x, y] in metres.
    pub frame: Vec<FramePoint>,
    pub crank: CrankSpec,
    pub groups: Vec<Spanned<GroupSpec>>,
    #[serde(default)]
    pub points: Vec<PointSpec>,
    /// The slider point whose extreme positions define position 0 (default: the last group's).
    #[serde(default)]
    pub output_point: Option<Name>,
    /// Or the rocker link whose extreme angles define position 0.
    #[serde(default)]
    pub output_link: Option<Spanned<u32>>,
    /// Free text printed on the sheet: what was assumed where the figure was lost.
    #[serde(default)]
    /// Each one text, or one per language.
    pub assumptions: Vec<Spanned<LocalText>>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FramePoint {
    pub name: Name,
    pub at: [Finite; 2],
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CrankSpec {
    pub pivot: Name,
    pub pin: Name,
    pub length: Spanned<Positive>,
    /// n1, rev/min; or `omega`.
    #[serde(default)]
    pub rpm: Option<Spanned<Positive>>,
    /// ω1, 1/s (rad/s), as some tasks give it; or `rpm`.
    #[serde(default)]
    pub omega: Option<Spanned<Positive>>,
    /// `ccw` or `cw`.
    pub sense: Sense,
    #[serde(default = "one")]
    pub link: u32,
}

fn one() -> u32 {
    1
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    Left,
    Right,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Along {
    Forward,
    Backward,
}

/// An Assur group, in order of formation.
#[derive(Debug, Clone, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum GroupSpec {
    /// Two links, three revolute pairs: `point` joined to `joints[0]` by a link of
    /// `lengths[0]` and to `joints[1]` by a link of `lengths[1]`.
    Rrr(RrrSpec),
    /// Rod and slider: `point` on the guide, joined to `joint` by a rod of `length`.
    Rrp(RrpSpec),
    /// Kulisa: a block pinned at `block_at` slides along a kulisa turning about `pivot`.
    Rpr(RprSpec),
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RrrSpec {
    pub links: [u32; 2],
    pub joints: [Name; 2],
    pub point: Name,
    pub lengths: [Positive; 2],
    /// Side of the directed line `joints[0]` → `joints[1]` on which `point` lies.
    pub branch: Side,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RrpSpec {
    pub links: [u32; 2],
    pub joint: Name,
    pub point: Name,
    pub length: Positive,
    pub guide: GuideSpec,
    /// Whether the slider lies ahead of (forward) or behind the joint along the guide.
    pub branch: Along,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GuideSpec {
    /// A point of the guide line, [x, y] in metres.
    pub through: [Finite; 2],
    /// Direction of the guide, degrees counter-clockwise from the x axis.
    pub angle_deg: Finite,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RprSpec {
    /// [block, kulisa].
    pub links: [u32; 2],
    pub block_at: Name,
    pub pivot: Name,
    /// Name of the kulisa's point under the block (default: the block point + "3").
    #[serde(default)]
    pub image: Option<Name>,
    /// Drawn length of the kulisa from its pivot, metres (default: its longest reach).
    #[serde(default)]
    pub length: Option<Positive>,
}

/// A point fixed to a link, e.g. a centre of mass.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointSpec {
    pub name: Name,
    pub link: Spanned<u32>,
    pub from: Name,
    /// Direction point on the same link; absent: the point coincides with `from`.
    #[serde(default)]
    pub toward: Option<Name>,
    /// Fraction of the distance from → toward.
    #[serde(default)]
    pub ratio: Option<Finite>,
    /// Or an absolute distance from `from`, metres.
    #[serde(default)]
    pub distance: Option<Finite>,
    /// Turn of the direction, degrees counter-clockwise (ternary links).
    #[serde(default)]
    pub angle_deg: Option<Finite>,
    #[serde(default)]
    pub mass_centre: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum StartExtreme {
    /// The output's smallest coordinate along its guide (or smallest rocker angle).
    #[default]
    Min,
    Max,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalysisSpec {
    /// 12 (every 30°) or 8 (every 45°).
    #[serde(default = "twelve")]
    pub positions: Spanned<u32>,
    #[serde(default)]
    pub start: StartExtreme,
    /// Fixes position 0 at this absolute crank angle instead (degrees from +x, ccw).
    #[serde(default)]
    pub start_deg: Option<Finite>,
    /// Course crank angle φ1 of the assigned (thick) position, degrees from position 0.
    #[serde(default)]
    pub assigned_deg: Option<Spanned<Finite>>,
    /// Positions that get acceleration plans (default: four, evenly spread).
    #[serde(default)]
    pub acceleration_plans: Option<Spanned<Vec<u32>>>,
}

fn twelve() -> Spanned<u32> {
    Spanned::new(12, serde_saphyr::Location::UNKNOWN, serde_saphyr::Location::UNKNOWN)
}

impl Default for AnalysisSpec {
    fn default() -> Self {
        AnalysisSpec {
            positions: twelve(),
            start: StartExtreme::Min,
            start_deg: None,
            assigned_deg: None,
            acceleration_plans: None,
        }
    }
}
