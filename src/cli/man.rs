//! `slamtool man [--out DIR]`: manual pages. Each page has the usual sections from the command definition,
//! then EXAMPLES (the examples of its `--help`) and EXIT STATUS.

use std::path::{Path, PathBuf};

use clap::Args;
use clap_mangen::Man;

use super::{exit, global};

/// Examples at the end of `slamtool man --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool man | man -l -
  slamtool man --out man/man1      # slamtool.1 and slamtool-<command>.1 for every command
  MANPATH=man man slamtool-entry-wedge";

#[derive(Debug, Args)]
pub struct ManArgs {
    /// Write one page per command (slamtool.1, slamtool-hull-info.1, ...) into this folder instead of
    /// printing the top page on stdout.
    #[arg(short, long, value_name = "DIR")]
    out: Option<PathBuf>,
}

pub fn run(a: ManArgs, cmd: clap::Command) -> slamtool::Result<()> {
    let mut cmd = cmd.disable_help_subcommand(true);
    cmd.build();
    match a.out {
        None => {
            let page = render(&cmd).map_err(|e| slamtool::Error::io(Path::new("<stdout>"), e))?;
            print!("{page}");
        }
        Some(dir) => {
            std::fs::create_dir_all(&dir).map_err(|e| slamtool::Error::io(&dir, e))?;
            let mut n = 0;
            write_pages(&cmd, &dir, &mut n)?;
            global::note(&format!("{n} manual pages"));
            println!("{}", global::files_written_line(&dir));
        }
    }
    Ok(())
}

/// Write the page of `cmd` and of every visible subcommand below it.
fn write_pages(cmd: &clap::Command, dir: &Path, n: &mut usize) -> slamtool::Result<()> {
    let name = cmd.get_display_name().unwrap_or(cmd.get_name());
    let path = dir.join(format!("{name}.1"));
    let page = render(cmd).map_err(|e| slamtool::Error::io(&path, e))?;
    slamtool::files::write_text_atomic(&path, &page)?;
    *n += 1;
    for sub in cmd.get_subcommands().filter(|s| !s.is_hide_set()) {
        write_pages(sub, dir, n)?;
    }
    Ok(())
}

/// One manual page as roff text.
fn render(cmd: &clap::Command) -> std::io::Result<String> {
    let man = Man::new(cmd.clone()).source(slamtool::provenance::TOOL);
    let mut out = Vec::new();
    man.render_title(&mut out)?;
    man.render_name_section(&mut out)?;
    man.render_synopsis_section(&mut out)?;
    man.render_description_section(&mut out)?;
    if cmd.get_arguments().any(|a| !a.is_hide_set()) {
        man.render_options_section(&mut out)?;
    }
    if cmd.has_subcommands() {
        man.render_subcommands_section(&mut out)?;
    }
    let mut text = String::from_utf8_lossy(&out).into_owned();
    let examples = cmd
        .get_after_long_help()
        .map(|h| h.to_string())
        .and_then(|h| h.split("\n\nExit status:").next().map(str::to_string))
        .and_then(|h| h.strip_prefix("Examples:\n").map(str::to_string));
    if let Some(ex) = examples {
        text += ".SH EXAMPLES\n.nf\n";
        text += &verbatim(&ex);
        text += ".fi\n";
    }
    text += ".SH \"EXIT STATUS\"\n.nf\n";
    text += &verbatim(exit::TABLE.trim_start_matches("Exit status:\n"));
    text += ".fi\n";
    let mut version = Vec::new();
    man.render_version_section(&mut version)?;
    text += &String::from_utf8_lossy(&version);
    Ok(text)
}

/// Text as roff no-fill lines: backslashes and hyphens escaped, no line taken for a request.
fn verbatim(text: &str) -> String {
    let mut s = String::new();
    for line in text.lines() {
        let line = line.trim_start_matches("  ");
        let line = line.replace('\\', "\\e").replace('-', "\\-");
        if line.starts_with('.') || line.starts_with('\'') {
            s.push_str("\\&");
        }
        s.push_str(&line);
        s.push('\n');
    }
    s
}
