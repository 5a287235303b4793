//! The exit status of every command, decided in one place.
//!
//! | status | meaning |
//! |---|---|
//! | 0 | success |
//! | 1 | bad input: an input file or an option value is wrong (the message says where) |
//! | 2 | usage: unknown option, missing argument (reported by the argument parser) |
//! | 3 | numerical failure of a run (an SPH run diverged, a solver did not converge) |
//! | 4 | a design limit was exceeded |
//! | 5 | an I/O error (a file cannot be read or written) |
//! | 6 | a validation case failed its tolerance (`slamtool validate`; known failures do not count) |

use slamtool::Error;

/// Success.
pub const OK: u8 = 0;
/// Bad input (file or option value).
pub const BAD_INPUT: u8 = 1;
/// Command-line usage error (clap's own status).
pub const USAGE: u8 = 2;
/// Numerical failure of a run.
pub const NUMERICAL: u8 = 3;
/// A design limit exceeded.
pub const DESIGN_LIMIT: u8 = 4;
/// An I/O error.
pub const IO: u8 = 5;
/// A validation case failed (known failures excepted).
pub const VALIDATION_FAILED: u8 = 6;

/// The exit status for an error.
pub fn code(e: &Error) -> u8 {
    match e {
        Error::Input(_) | Error::Invalid(_) => BAD_INPUT,
        Error::Numerical(_) => NUMERICAL,
        Error::DesignLimit(_) => DESIGN_LIMIT,
        Error::Io { .. } => IO,
        Error::ValidationFailed(_) => VALIDATION_FAILED,
    }
}

/// The table of exit statuses as help and manual-page text.
pub const TABLE: &str = "\
Exit status:
  0  success
  1  bad input: an input file or option value is wrong (the message says where)
  2  usage: unknown option or missing argument
  3  numerical failure of a run (an SPH run diverged, a solver did not converge)
  4  a design limit was exceeded
  5  I/O error: a file cannot be read or written
  6  validation: a case of `slamtool validate` failed its tolerance";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_error_kind_has_its_own_status() {
        let io = Error::io(
            std::path::Path::new("x"),
            std::io::Error::from(std::io::ErrorKind::NotFound),
        );
        assert_eq!(code(&io), IO);
        assert_eq!(code(&Error::Invalid("x".into())), BAD_INPUT);
        assert_eq!(code(&Error::Numerical("x".into())), NUMERICAL);
        assert_eq!(code(&Error::DesignLimit("x".into())), DESIGN_LIMIT);
        assert_eq!(
            code(&Error::ValidationFailed("x".into())),
            VALIDATION_FAILED
        );
        assert_eq!(OK, 0);
        assert_eq!(USAGE, 2);
    }
}
