//! The gears of sheet 2, pure and in SI (metres, radians): the external involute pair
//! ([`pair`]) of two wheels ([`wheel`]), its tooth outlines as the generating rack ([`rack`]) cuts them ([`tooth`]), and the
//! planetary stage's synthesis with its conditions checked honestly ([`planetary`]).

pub mod pair;
pub mod planetary;
pub mod rack;
pub mod sliding;
pub mod tooth;
pub mod wheel;
