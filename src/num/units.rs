//! Metres and millimetres. The domains compute in metres; the tables, the notes and the
//! project file's lengths are in millimetres. Multiplying by 10³ and dividing by it are
//! each rounded once, so these are the conversions everywhere, written once.

/// Millimetres in a metre.
pub const MM_PER_M: f64 = 1e3;

/// A length in metres, in millimetres.
pub fn mm(metres: f64) -> f64 {
    metres * MM_PER_M
}

/// A length in millimetres, in metres (divided, so that whole millimetres give the nearest
/// double to their metres: 3 mm is 0.003).
pub fn metres(mm: f64) -> f64 {
    mm / MM_PER_M
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn millimetres_and_metres_round_trip() {
        assert_eq!(mm(0.003), 3.0);
        assert_eq!(metres(3.0), 0.003);
        for x in [0.1, 2.5, 17.0, 123.456] {
            crate::assert_near!(mm(metres(x)), x);
        }
    }
}
