//! CSV plot data of a motions analysis ([`crate::seakeeping::analysis::Report`]): one function per table.
//! Rows run over the speeds in the order analysed, then over the waves, seas and stations in the order
//! given. Every column name carries its unit; `station` is the fraction of Lpp aft of the FP.

use super::sanity::SlamFlag;
use super::{CsvTable, csv_number as f};
use crate::seakeeping::analysis::Report;

/// All motion tables, in the order `slamtool motions -o DIR` writes them. `warnings` (the report's and
/// the caller's sanity warnings) go into every file as notes.
pub fn tables(r: &Report, warnings: &[String]) -> Vec<CsvTable> {
    let mut t = vec![
        raos(r),
        relative_motion(r),
        entry_profiles(r),
        slam_statistics(r),
        response_spectra(r),
        operability(r),
    ];
    for table in &mut t {
        table
            .notes
            .extend(warnings.iter().map(|w| format!("warning: {w}")));
    }
    t
}

/// `raos.csv`: heave and pitch RAOs per speed and wavelength ratio, in the nondimensional forms of the tank
/// tables (heave over wave amplitude; pitch times Lpp/(2 pi wave amplitude) and over the wave slope k
/// times the wave amplitude).
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
            "speed_m_per_s",
            "froude_number",
            "wavelength_over_lpp",
            "wave_frequency_rad_per_s",
            "encounter_frequency_rad_per_s",
            "heave_over_wave_amplitude",
            "heave_phase_deg",
            "pitch_lpp_over_2pi_wave_amplitude",
            "pitch_over_wave_slope",
            "pitch_phase_deg",
        ],
        notes: Vec::new(),
        rows,
    }
}

/// `relative_motion.csv`: relative motion and velocity amplitudes per station in each regular wave, with
/// the keel-entry instant and velocity where the keel enters (empty otherwise) and Ochi's slam flag.
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
                    SlamFlag::of(t, r.slam_threshold_velocity_m_s)
                        .text()
                        .to_string(),
                ]);
            }
        }
    }
    let mut notes = vec![format!(
        "empty entry_time_s and entry_velocity_m_per_s: the keel does not emerge from the water at that \
         station; slam_flag by Ochi's criterion, threshold velocity {:.3} m/s",
        r.slam_threshold_velocity_m_s
    )];
    if rows.is_empty() {
        notes.push("no regular wave in the sea-state file".into());
    }
    CsvTable {
        file_name: "relative_motion.csv",
        header: &[
            "speed_m_per_s",
            "wave",
            "station",
            "x_m",
            "draft_m",
            "relative_motion_amplitude_m",
            "relative_velocity_amplitude_m_per_s",
            "entry_time_s",
            "entry_velocity_m_per_s",
            "slam_flag",
        ],
        notes,
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
    let notes = if rows.is_empty() {
        vec![
            "no keel entry: no regular wave, or the keel stays in the water at every station"
                .into(),
        ]
    } else {
        Vec::new()
    };
    CsvTable {
        file_name: "entry_profiles.csv",
        header: &[
            "speed_m_per_s",
            "wave",
            "station",
            "time_since_entry_s",
            "velocity_m_per_s",
            "penetration_m",
        ],
        notes,
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
                    f(r.lpp_m.recip() * (0.5 * r.lpp_m - t.x)),
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
    let mut notes = vec![
        "empty extreme_entry_velocity_m_per_s: fewer than one slam expected over the exposure time"
            .into(),
    ];
    if rows.is_empty() {
        notes.push("no irregular sea in the sea-state file".into());
    }
    CsvTable {
        file_name: "slam_statistics.csv",
        header: &[
            "sea",
            "speed_m_per_s",
            "station",
            "x_m",
            "draft_m",
            "relative_motion_variance_m2",
            "relative_velocity_variance_m2_per_s2",
            "threshold_velocity_m_per_s",
            "slam_probability",
            "slams_per_hour",
            "extreme_entry_velocity_m_per_s",
        ],
        notes,
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
    let notes = if rows.is_empty() {
        vec!["no irregular sea in the sea-state file".into()]
    } else {
        Vec::new()
    };
    CsvTable {
        file_name: "response_spectra.csv",
        header: &[
            "sea",
            "speed_m_per_s",
            "x_m",
            "wave_frequency_rad_per_s",
            "encounter_frequency_rad_per_s",
            "relative_motion_density_m2_s",
            "relative_velocity_density_m2_per_s",
        ],
        notes,
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
    let mut notes = vec![
        "empty limit_speed_m_per_s: even the lowest speed tested exceeds the slam probability limit".into(),
    ];
    if rows.is_empty() {
        notes.push("no irregular sea in the sea-state file".into());
    }
    CsvTable {
        file_name: "operability.csv",
        header: &[
            "sea",
            "speed_m_per_s",
            "max_slam_probability",
            "slam_probability_limit",
            "limit_speed_m_per_s",
        ],
        notes,
        rows,
    }
}
