//! `sweeps/slurm.sh` on a real Slurm: a single-node cluster (slurmctld and slurmd from Debian's
//! `slurm-wlm` package, on localhost, in a temporary folder, no munge: `auth/none`) runs the script as a job
//! array of four shards and then its merge step as a dependent job, and the merged result must equal the
//! unsharded sweep. Ignored by default (it needs the package and root, and takes about a minute):
//!
//! ```sh
//! apt-get install -y slurm-wlm
//! cargo test --release --test slurm_cluster -- --ignored --nocapture
//! ```

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use slamtool::sweep;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The Slurm daemons of the test cluster; stopped (by their pid files) when dropped.
struct Cluster {
    dir: PathBuf,
    conf: PathBuf,
}

impl Cluster {
    fn start(dir: &Path) -> Cluster {
        for tool in ["slurmctld", "slurmd", "sbatch", "squeue", "sinfo"] {
            let found = Command::new("sh")
                .args(["-c", &format!("command -v {tool}")])
                .output()
                .is_ok_and(|o| o.status.success());
            assert!(
                found,
                "{tool} not found: install Debian's slurm-wlm (apt-get install -y slurm-wlm)"
            );
        }
        for d in ["state", "spool", "log"] {
            std::fs::create_dir_all(dir.join(d)).unwrap();
        }
        // Ports away from Slurm's defaults (6817/6818), so that a real installation is left alone.
        let port = 20000 + (std::process::id() % 20000) as u16;
        let cpus = std::thread::available_parallelism().map_or(1, |n| n.get().min(2));
        let d = dir.display();
        let conf = format!(
            "ClusterName=slamtooltest\nSlurmctldHost=localhost\nSlurmctldPort={port}\nSlurmdPort={}\n\
             SlurmUser=root\nSlurmdUser=root\nAuthType=auth/none\nCredType=cred/none\n\
             StateSaveLocation={d}/state\nSlurmdSpoolDir={d}/spool\nSlurmctldPidFile={d}/slurmctld.pid\n\
             SlurmdPidFile={d}/slurmd.pid\nSlurmctldLogFile={d}/log/slurmctld.log\n\
             SlurmdLogFile={d}/log/slurmd.log\nProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n\
             SelectType=select/cons_tres\nSelectTypeParameters=CR_CPU\nMpiDefault=none\nReturnToService=2\n\
             NodeName=localhost CPUs={cpus} State=UNKNOWN\n\
             PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP\n",
            port + 1
        );
        let path = dir.join("slurm.conf");
        std::fs::write(&path, conf).unwrap();
        let c = Cluster {
            dir: dir.to_path_buf(),
            conf: path,
        };
        let s = Command::new("slurmctld")
            .args(["-i", "-f"])
            .arg(&c.conf)
            .status()
            .unwrap();
        assert!(s.success(), "slurmctld did not start: {}", c.logs());
        let s = Command::new("slurmd")
            .arg("-f")
            .arg(&c.conf)
            .args(["-N", "localhost"])
            .status()
            .unwrap();
        assert!(s.success(), "slurmd did not start: {}", c.logs());
        // Wait for the node to be idle.
        let t0 = Instant::now();
        loop {
            let o = c.run("sinfo", &["-h", "-o", "%t"]);
            if o.trim() == "idle" {
                break;
            }
            assert!(
                t0.elapsed() < Duration::from_secs(60),
                "the node is '{}', not idle, after 60 s: {}",
                o.trim(),
                c.logs()
            );
            std::thread::sleep(Duration::from_millis(500));
        }
        c
    }

    fn command(&self, tool: &str) -> Command {
        let mut c = Command::new(tool);
        c.env("SLURM_CONF", &self.conf);
        c
    }

    fn run(&self, tool: &str, args: &[&str]) -> String {
        let o = self.command(tool).args(args).output().unwrap();
        assert!(
            o.status.success(),
            "{tool} {args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        String::from_utf8_lossy(&o.stdout).into_owned()
    }

    fn logs(&self) -> String {
        ["slurmctld.log", "slurmd.log"]
            .iter()
            .map(|f| std::fs::read_to_string(self.dir.join("log").join(f)).unwrap_or_default())
            .collect::<Vec<_>>()
            .join("\n")
    }
}

impl Drop for Cluster {
    fn drop(&mut self) {
        for f in ["slurmd.pid", "slurmctld.pid"] {
            if let Ok(pid) = std::fs::read_to_string(self.dir.join(f)) {
                let _ = Command::new("kill").arg(pid.trim()).status();
            }
        }
    }
}

#[test]
#[ignore = "starts a single-node Slurm (Debian's slurm-wlm, root); about a minute"]
fn slurm_job_array_and_merge_equal_the_unsharded_sweep() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let cluster = Cluster::start(&dir.join("slurm"));
    // A small analytic sweep (9 cases) over the bundled Ochi hull, so that each of 4 shards has cases.
    let sweep_file = dir.join("small.toml");
    std::fs::write(
        &sweep_file,
        format!(
            "name = \"slurm\"\nhull = \"{ROOT}/hulls/ochi-vform.toml\"\nsea = \"{ROOT}/sea_states/ochi-1958.toml\"\n\
             loading = \"test-condition\"\nfidelity = \"analytic\"\n\n[bow_region]\nfull_aft_of_fp = 0.1\n\
             zero_aft_of_fp = 0.3\n\n[grid]\nspeed_m_s = [1.6, 2.0, 2.4]\n\
             flare_scale = {{ start = 0.8, stop = 1.2, count = 3 }}\n"
        ),
    )
    .unwrap();
    let bin = env!("CARGO_BIN_EXE_slamtool");
    let whole = dir.join("whole");
    let o = Command::new(bin)
        .arg("sweep")
        .arg(&sweep_file)
        .arg("-o")
        .arg(&whole)
        .arg("-q")
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    // The script as its header says: the array, then the merge as a dependent job. --cpus-per-task=1
    // overrides the script's 2 so that the one-node cluster can run its tasks.
    let out = dir.join("cluster-out");
    let script = Path::new(ROOT).join("sweeps/slurm.sh");
    let submit = |extra: &[&str], env: &[(&str, &str)]| -> String {
        let mut c = cluster.command("sbatch");
        c.arg("--parsable")
            .arg("--cpus-per-task=1")
            .arg(format!("--chdir={ROOT}"))
            .arg(format!("--output={}/job-%A_%a.log", dir.display()))
            .args(extra)
            .arg(&script)
            .env("SWEEP", &sweep_file)
            .env("OUT", &out)
            .env("SLAMTOOL", bin)
            .env_remove("MERGE_ONLY");
        for (k, v) in env {
            c.env(k, v);
        }
        let o = c.output().unwrap();
        assert!(
            o.status.success(),
            "sbatch: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        String::from_utf8_lossy(&o.stdout).trim().to_string()
    };
    let array = submit(&[], &[]);
    let merge = submit(
        &[
            &format!("--dependency=afterany:{array}"),
            "--array=0",
            "--export=ALL,MERGE_ONLY=1",
        ],
        &[],
    );
    let t0 = Instant::now();
    loop {
        let q = cluster.run("squeue", &["-h", "-j", &format!("{array},{merge}")]);
        if q.trim().is_empty() {
            break;
        }
        assert!(
            t0.elapsed() < Duration::from_secs(600),
            "jobs still queued after 10 min:\n{q}\n{}",
            cluster.logs()
        );
        std::thread::sleep(Duration::from_secs(1));
    }
    let job_logs = || {
        let mut s = String::new();
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "log") {
                s += &format!(
                    "== {}\n{}",
                    p.display(),
                    std::fs::read_to_string(&p).unwrap_or_default()
                );
            }
        }
        s
    };
    for i in 0..4 {
        let shard = sweep::merge::read(&out.join(format!("shard-{i}-of-4")))
            .unwrap_or_else(|e| panic!("shard {i}: {e}\n{}", job_logs()));
        assert!(shard.cases.iter().all(|c| c.index % 4 == i));
    }
    let merged = sweep::merge::read(&out).unwrap_or_else(|e| panic!("{e}\n{}", job_logs()));
    let whole = sweep::merge::read(&whole).unwrap();
    assert_eq!(merged.shard, None);
    assert_eq!(merged.cases, whole.cases);
    assert!(merged.warnings.is_empty(), "{:?}", merged.warnings);
    for f in ["results.csv", "cases.csv", "best.csv"] {
        let a = std::fs::read(dir.join("whole").join(f)).unwrap();
        let b = std::fs::read(out.join(f)).unwrap();
        assert!(
            a == b,
            "{f} differs between the Slurm run and the unsharded sweep"
        );
    }
    println!("Slurm: array job {array} (4 shards) and merge job {merge} equal the unsharded sweep");
}
