//! The `slamtool` command line: parse arguments, call the library, print. No physics lives here.

mod cli;

fn main() -> std::process::ExitCode {
    // Behave like other Unix filters when the reader goes away (`slamtool hull info x | head`): end quietly
    // instead of failing to print.
    #[cfg(unix)]
    // SAFETY: called once at start-up before any thread exists; restores the default disposition.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    cli::main()
}
