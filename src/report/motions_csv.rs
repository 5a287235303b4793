//! CSV plot data of a motions analysis ([`crate::seakeeping::analysis::Report`]): one function per table.
//! Rows run over the speeds in the order analysed, then over the waves, seas and stations in the order
//! given.

use super::{CsvTable, csv_number as f};
use crate::seakeeping::analysis::Report;

/// All motion tables, in the order `slamtool motions -o DIR` writes them.
pub fn tables(r: &Report) -> Vec<CsvTable> {
    vec![
        raos(r),
        relative_motion(r),
        entry_profiles(r),
        slam_statistics(r),
        response_spectra(r),
        operability(r),
    ]
}

/// `raos.csv`: heave and pitch RAOs per speed and wavelength ratio, in the nondimensional forms of the tank
/// tables (heave/zeta_a; pitch L/(2 pi zeta_a) and pitch/(k zeta_a)).
pub fn raos(r: &Report) -> CsvTable {
    let mut rows = Vec::new();
    for s in &r.speeds {
        for q in &s.raos {
            rows.push(vec![
                f(s.speed_m_s),
                f(s.froude_number),
                f(q.lambda_over_l),
                f(q.omega0),
                f(q.omega_e),
                f(q.heave),
                f(q.heave_phase_deg),
                f(q.pitch_nd),
                f(q.pitch_over_k),
                f(q.pitch_phase_deg),
            ]);
        }
    }
    CsvTable {
        file_name: "raos.csv",
        header: &[
            "speed_m_s",
            "froude",
            "lambda_over_l",
            "omega0",
            "omega_e",
            "heave_over_za",
            "heave_phase_deg",
            "pitch_l_over_2pi_za",
            "pitch_over_k_za",
            "pitch_phase_deg",
        ],
        rows,
    }
}

/// `relative_motion.csv`: relative motion and velocity amplitudes per station in each regular wave, with
/// the keel-entry instant and velocity where the keel enters (empty otherwise).
pub fn relative_motion(r: &Report) -> CsvTable {
    let mut rows = Vec::new();
    for s in &r.speeds {
        for w in &s.regular {
            for t in &w.stations {
                let (te, ve) = t
                    .keel_entry
                    .as_ref()
                    .map_or((String::new(), String::new()), |k| {
                        (f(k.t_entry), f(k.entry_velocity))
                    });
                rows.push(vec![
                    f(s.speed_m_s),
                    w.wave.clone(),
                    f(t.aft_of_fp),
                    f(t.x),
                    f(t.draft),
                    f(t.relative_motion_m),
                    f(t.relative_velocity_m_s),
                    te,
                    ve,
                ]);
            }
        }
    }
    CsvTable {
        file_name: "relative_motion.csv",
        header: &[
            "speed_m_s",
            "wave",
            "aft_of_fp",
            "x_m",
            "draft_m",
            "relative_motion_m",
            "relative_velocity_m_s",
            "t_entry_s",
            "entry_velocity_m_s",
        ],
        rows,
    }
}

/// `entry_profiles.csv`: the entry-velocity profile v(t) and penetration after each keel entry.
pub fn entry_profiles(r: &Report) -> CsvTable {
    let mut rows = Vec::new();
    for s in &r.speeds {
        for w in &s.regular {
            for t in &w.stations {
                if let Some(k) = &t.keel_entry {
                    for p in &k.samples {
                        rows.push(vec![
                            f(s.speed_m_s),
                            w.wave.clone(),
                            f(t.aft_of_fp),
                            f(p.t),
                            f(p.velocity),
                            f(p.penetration),
                        ]);
                    }
                }
            }
        }
    }
    CsvTable {
        file_name: "entry_profiles.csv",
        header: &[
            "speed_m_s",
            "wave",
            "aft_of_fp",
            "t_since_entry_s",
            "velocity_m_s",
            "penetration_m",
        ],
        rows,
    }
}

/// `slam_statistics.csv`: spectral moments, Ochi slam probability, slams per hour and the most probable
/// extreme entry velocity per station in each irregular sea (empty where fewer than one slam is expected).
pub fn slam_statistics(r: &Report) -> CsvTable {
    let mut rows = Vec::new();
    for s in &r.speeds {
        for ir in &s.irregular {
            for (t, e) in ir.stations.iter().zip(&ir.extreme_velocity_m_s) {
                rows.push(vec![
                    ir.sea.clone(),
                    f(s.speed_m_s),
                    f(t.x),
                    f(t.draft),
                    f(t.m0),
                    f(t.m2),
                    f(t.threshold_velocity),
                    f(t.probability),
                    f(t.slams_per_hour),
                    e.map(f).unwrap_or_default(),
                ]);
            }
        }
    }
    CsvTable {
        file_name: "slam_statistics.csv",
        header: &[
            "sea",
            "speed_m_s",
            "x_m",
            "draft_m",
            "m0_m2",
            "m2_m2_s2",
            "threshold_m_s",
            "probability",
            "slams_per_hour",
            "extreme_velocity_m_s",
        ],
        rows,
    }
}

/// `response_spectra.csv`: relative motion and velocity spectra per station in each irregular sea.
pub fn response_spectra(r: &Report) -> CsvTable {
    let mut rows = Vec::new();
    for s in &r.speeds {
        for ir in &s.irregular {
            for rs in &ir.response_spectra {
                for j in 0..rs.omega0.len() {
                    rows.push(vec![
                        ir.sea.clone(),
                        f(s.speed_m_s),
                        f(rs.x),
                        f(rs.omega0[j]),
                        f(rs.omega_e[j]),
                        f(rs.motion[j]),
                        f(rs.velocity[j]),
                    ]);
                }
            }
        }
    }
    CsvTable {
        file_name: "response_spectra.csv",
        header: &[
            "sea",
            "speed_m_s",
            "x_m",
            "omega0",
            "omega_e",
            "relative_motion_m2_s",
            "relative_velocity_m2_per_s",
        ],
        rows,
    }
}

/// `operability.csv`: the largest slam probability over the stations per speed, the limit and the
/// operability limit speed (empty where even the lowest speed exceeds the limit).
pub fn operability(r: &Report) -> CsvTable {
    let mut rows = Vec::new();
    for o in &r.operability {
        for (u, p) in o
            .operability
            .speeds
            .iter()
            .zip(&o.operability.max_probability)
        {
            rows.push(vec![
                o.sea.clone(),
                f(*u),
                f(*p),
                f(o.operability.limit),
                o.operability.limit_speed.map(f).unwrap_or_default(),
            ]);
        }
    }
    CsvTable {
        file_name: "operability.csv",
        header: &[
            "sea",
            "speed_m_s",
            "max_probability",
            "limit",
            "limit_speed_m_s",
        ],
        rows,
    }
}
