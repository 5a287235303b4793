//! Records the git commit the binary is built from, for the provenance of every result, with "-modified"
//! appended when the sources (src/, build.rs, Cargo.toml, Cargo.lock) differ from that commit. A build from
//! a tarball (no git, or not a repository) records "unknown" and never fails.
//!
//! It also records the SHA-256 of the solver sources (`src/source_hash.rs`, compiled here as the same
//! file the library uses), the part of the run cache's key that makes a changed solver miss.

use std::process::Command;

#[path = "src/source_hash.rs"]
#[allow(dead_code)]
mod source_hash;

/// Output of `git args...`, trimmed, if git exists and succeeds.
fn git(args: &[&str]) -> Option<String> {
    let o = Command::new("git").args(args).output().ok()?;
    let s = String::from_utf8(o.stdout).ok()?.trim().to_string();
    (o.status.success() && !s.is_empty()).then_some(s)
}

fn main() {
    let commit = git(&["rev-parse", "HEAD"]).unwrap_or_else(|| "unknown".to_string());
    // A build from sources that differ from the commit is marked, so that no result claims a commit it
    // was not computed with. `git status` prints nothing (and git() gives None) for a clean tree.
    let dirty = commit != "unknown"
        && git(&[
            "status",
            "--porcelain",
            "--untracked-files=no",
            "--",
            "src",
            "build.rs",
            "Cargo.toml",
            "Cargo.lock",
        ])
        .is_some();
    let commit = if dirty {
        format!("{commit}-modified")
    } else {
        commit
    };
    println!("cargo:rustc-env=SLAMTOOL_GIT_COMMIT={commit}");
    let root = std::path::PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    match source_hash::source_hash(&root, source_hash::SOLVER_SOURCES) {
        Ok(h) => println!("cargo:rustc-env=SLAMTOOL_SOLVER_SOURCES_SHA256={h}"),
        // A build without its solver sources cannot say what its runs depend on: refuse it.
        Err(e) => {
            eprintln!("build.rs: cannot hash the solver sources: {e}");
            std::process::exit(1);
        }
    }
    println!("cargo:rerun-if-changed=build.rs");
    // Re-check the working tree whenever a source changes.
    for p in ["src", "Cargo.toml", "Cargo.lock"] {
        println!("cargo:rerun-if-changed={p}");
    }
    // Rebuild when HEAD moves: HEAD itself (a branch switch) and the branch it points to (a commit). In a
    // worktree these live outside the source tree, so ask git where they are.
    let mut watch = vec![git(&["rev-parse", "--git-path", "HEAD"])];
    if let Some(branch) = git(&["symbolic-ref", "-q", "HEAD"]) {
        watch.push(git(&["rev-parse", "--git-path", &branch]));
        watch.push(git(&["rev-parse", "--git-path", "packed-refs"]));
    }
    for p in watch.into_iter().flatten() {
        if std::path::Path::new(&p).exists() {
            println!("cargo:rerun-if-changed={p}");
        }
    }
}
