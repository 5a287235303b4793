//! The `slamtool` command line: parse arguments, call the library, print. No physics lives here.

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
