//! Error types. Every problem with user input is an [`InputError`] that names the file, the line and the
//! column (1-based) and says what is wrong; the CLI prints it as `file:line:column: message`.

use std::fmt;
use std::path::{Path, PathBuf};

/// A problem in an input file, located to the line and column.
#[derive(Debug, Clone, PartialEq)]
pub struct InputError {
    /// The file the problem is in.
    pub file: PathBuf,
    /// 1-based line number.
    pub line: usize,
    /// 1-based column number (in characters).
    pub column: usize,
    /// What is wrong, in words a user can act on.
    pub message: String,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: {}",
            self.file.display(),
            self.line,
            self.column,
            self.message
        )
    }
}

impl std::error::Error for InputError {}

/// Every error the library returns.
#[derive(Debug)]
pub enum Error {
    /// Bad input, located in its file.
    Input(InputError),
    /// An operating-system error on a file.
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    /// A numerical method failed (no convergence, singular system, ...).
    Numerical(String),
    /// A request that is well-formed but cannot be carried out with these inputs.
    Invalid(String),
    /// The inputs are valid and the computation succeeded, but the result exceeds a design limit the user
    /// set (the CLI exits with status 4).
    DesignLimit(String),
    /// A validation case failed its stated tolerance (`slamtool validate`; the CLI exits with status 6).
    ValidationFailed(String),
}

impl Error {
    /// An operating-system error on `path`. Where a folder could not be made because a file stands in
    /// its place (`-o out.svg/figures`), the message says so instead of the bare "File exists".
    pub fn io(path: &Path, source: std::io::Error) -> Self {
        use std::io::ErrorKind;
        let source = match source.kind() {
            ErrorKind::AlreadyExists | ErrorKind::NotADirectory => {
                let blocker = if path.is_file() && source.kind() == ErrorKind::AlreadyExists {
                    Some(path.to_path_buf())
                } else {
                    crate::output_policy::file_in_the_way(path)
                };
                match blocker {
                    Some(f) => std::io::Error::new(
                        source.kind(),
                        format!(
                            "{} is a file, not a folder, so there is nothing under it; give a path \
                             that is not under a file ({source})",
                            f.display()
                        ),
                    ),
                    None => source,
                }
            }
            _ => source,
        };
        Error::Io {
            path: path.to_path_buf(),
            source,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(e) => write!(f, "{e}"),
            Error::Io { path, source } => write!(f, "{}: {}", path.display(), source),
            Error::Numerical(m) => write!(f, "numerical failure: {m}"),
            Error::Invalid(m) => write!(f, "{m}"),
            Error::DesignLimit(m) => write!(f, "design limit exceeded: {m}"),
            Error::ValidationFailed(m) => write!(f, "validation failed: {m}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io { source, .. } => Some(source),
            Error::Input(e) => Some(e),
            _ => None,
        }
    }
}

impl From<InputError> for Error {
    fn from(e: InputError) -> Self {
        Error::Input(e)
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;
