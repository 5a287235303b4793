//! Salvesen, Tuck & Faltinsen (1970) strip theory: coupled heave and pitch of a ship with forward speed U
//! in regular head waves.
//!
//! Frequency domain with e^{i w_e t}, w_e = w0 + w0^2 U / g (head seas), incident wave
//! zeta = zeta_a e^{i(w_e t + k x)} (crest at midship at t = 0, travelling towards -x).
//! Equations of motion: [-w_e^2 (M + Z) + C] eta = F, with the complex added-mass matrix
//! Z = A - i B / w_e built from the sectional Z(x) = a33(x) - i b33(x)/w_e (STF 1970, table 1, written in
//! complex form; superscript A marks the aftmost (transom) section, zero for a ship without a wetted transom):
//!
//! Z33 = int Z dx - (iU/w) Z^A
//! Z35 = -int (x + iU/w) Z dx + (iU/w)(x_A + iU/w) Z^A
//! Z53 = -int (x - iU/w) Z dx + (iU/w) x_A Z^A
//! Z55 = int (x^2 + U^2/w^2) Z dx - (iU/w) x_A (x_A + iU/w) Z^A
//!
//! which gives STF's A33 = int a33 - U/w^2 b33^A, B33 = int b33 + U a33^A, A35 = -int x a33 - U/w^2 B33^0 + ...
//! The Timman-Newman relations A35(U) = A53(-U), B35(U) = B53(-U) hold for ships without a transom.
//!
//! Restoring about the origin: C33 = rho g Awp, C35 = C53 = -rho g int x b dx,
//! C55 = rho g int x^2 b dx + rho g V (z_B - z_G).
//!
//! Exciting force per unit wave amplitude: Froude-Krylov f_FK = rho g e^{ikx} int e^{kz} dy (pressure decay
//! over the section: the Smith correction) plus diffraction f_D = w_e w0 e^{ikx} rho int psi3 n_z e^{kz} ds
//! (STF's Haskind-type form with the 2D radiation potential psi3 at w_e):
//!
//! F3 = int (f_FK + f_D) dx + U/(i w_e) f_D^A,
//! F5 = -int [x f_FK + (x + U/(i w_e)) f_D] dx - U/(i w_e) x_A f_D^A.
//!
//! Known limitation (Journee 1992, Wigley hull tests; physics.md): strip theory over-predicts the pitch
//! damping at forward speed (the U^2/w^2 B33^0 term of B55 grows with speed while the measured B55 is nearly
//! speed-independent), so pitch responses near resonance at speed are under-predicted.

use nalgebra::{Complex, Matrix2, Vector2};
use rayon::prelude::*;

use super::ShipModel;
use super::section::{self, HalfSection, Radiation, SectionMethod, frank_close_fit};
use crate::error::{Error, Result};

type C64 = Complex<f64>;

/// Strip-theory settings.
#[derive(Debug, Clone, Copy, Default)]
pub struct StripSettings {
    pub method: SectionMethod,
    pub frank: frank_close_fit::Settings,
}

/// Encounter frequency in head seas: w_e = w0 + w0^2 U / g.
pub fn encounter_frequency(omega0: f64, speed: f64, g: f64) -> f64 {
    omega0 + omega0 * omega0 * speed / g
}

/// Global hydrodynamic coefficients at one encounter frequency, indices 0 = heave, 1 = pitch.
#[derive(Debug, Clone)]
pub struct Coefficients {
    pub omega_e: f64,
    pub speed: f64,
    /// Added mass matrix A (kg, kg m, kg m^2).
    pub added_mass: [[f64; 2]; 2],
    /// Damping matrix B.
    pub damping: [[f64; 2]; 2],
    /// Complex form Z = A - i B / w_e.
    pub z: [[C64; 2]; 2],
}

/// The sectional radiation solutions of all stations at one encounter frequency.
pub struct Strips {
    pub omega_e: f64,
    /// One entry per station of the model (None where the station is dry).
    pub radiation: Vec<Option<Radiation>>,
}

/// Solve the 2D problems of all stations at encounter frequency `omega_e` (in parallel; the result is
/// independent of the thread count since each station is solved on its own).
pub fn strips(model: &ShipModel, omega_e: f64, settings: &StripSettings) -> Result<Strips> {
    model.validate()?;
    let radiation: Result<Vec<Option<Radiation>>> = model
        .stations
        .par_iter()
        .map(|st| match &st.section {
            None => Ok(None),
            Some(sec) => solve_section(sec, omega_e, model, settings).map(Some),
        })
        .collect();
    Ok(Strips {
        omega_e,
        radiation: radiation?,
    })
}

/// Where the sectional solutions at an encounter frequency come from: solved directly
/// ([`StripSettings`]) or interpolated from a table ([`super::strip_table::StripTable`]).
pub trait SectionSolutions: Sync {
    fn strips(&self, model: &ShipModel, omega_e: f64) -> Result<Strips>;
}

impl SectionSolutions for StripSettings {
    fn strips(&self, model: &ShipModel, omega_e: f64) -> Result<Strips> {
        strips(model, omega_e, self)
    }
}

fn solve_section(
    sec: &HalfSection,
    omega: f64,
    model: &ShipModel,
    s: &StripSettings,
) -> Result<Radiation> {
    match s.method {
        SectionMethod::FrankCloseFit => {
            frank_close_fit::radiation(sec, omega, model.g, model.rho, &s.frank)
        }
        SectionMethod::Lewis => section::lewis::radiation(sec, omega, model.g, model.rho),
    }
}

/// Trapezoidal integral over the stations of f(x, station index).
fn integrate<T>(model: &ShipModel, f: impl Fn(usize) -> T) -> T
where
    T: std::ops::Add<Output = T> + std::ops::Mul<f64, Output = T> + Copy + Default,
{
    let mut acc = T::default();
    let st = &model.stations;
    for i in 0..st.len().saturating_sub(1) {
        let h = st[i + 1].x - st[i].x;
        acc = acc + (f(i) + f(i + 1)) * (0.5 * h);
    }
    acc
}

/// Index of the transom station: the aftmost station, if it is wetted.
fn transom(model: &ShipModel) -> Option<usize> {
    model
        .stations
        .first()
        .and_then(|s| s.section.as_ref().map(|_| 0))
}

/// Global added mass and damping from the sectional solutions.
pub fn coefficients(model: &ShipModel, strips: &Strips, speed: f64) -> Coefficients {
    let w = strips.omega_e;
    let zx = |i: usize| {
        strips.radiation[i]
            .as_ref()
            .map_or(C64::new(0.0, 0.0), |r| r.z())
    };
    let x = |i: usize| model.stations[i].x;
    let iu = C64::new(0.0, speed / w);
    let mut z33 = integrate(model, zx);
    let mut z35 = -integrate(model, |i| (iu + x(i)) * zx(i));
    let mut z53 = -integrate(model, |i| (-iu + x(i)) * zx(i));
    let mut z55 = integrate(model, |i| zx(i) * (x(i) * x(i) + (speed / w).powi(2)));
    if let Some(a) = transom(model) {
        let (za, xa) = (zx(a), x(a));
        z33 -= iu * za;
        z35 += iu * (iu + xa) * za;
        z53 += iu * xa * za;
        z55 -= iu * xa * (iu + xa) * za;
    }
    let z = [[z33, z35], [z53, z55]];
    let mut added_mass = [[0.0; 2]; 2];
    let mut damping = [[0.0; 2]; 2];
    for j in 0..2 {
        for k in 0..2 {
            added_mass[j][k] = z[j][k].re;
            damping[j][k] = -w * z[j][k].im;
        }
    }
    Coefficients {
        omega_e: w,
        speed,
        added_mass,
        damping,
        z,
    }
}

/// Wave exciting force and moment per unit wave amplitude in head seas.
#[derive(Debug, Clone, Copy)]
pub struct Excitation {
    /// Heave force F3 (N/m), complex.
    pub f3: C64,
    /// Pitch moment F5 (N m/m), complex, positive bow down.
    pub f5: C64,
    /// Froude-Krylov parts alone.
    pub f3_fk: C64,
    pub f5_fk: C64,
}

/// Exciting force from the sectional solutions at the encounter frequency of `omega0`.
pub fn excitation(model: &ShipModel, strips: &Strips, omega0: f64, speed: f64) -> Excitation {
    let k = omega0 * omega0 / model.g;
    let we = strips.omega_e;
    let x = |i: usize| model.stations[i].x;
    let wave = |i: usize| C64::new(0.0, k * x(i)).exp();
    let fk = |i: usize| {
        model.stations[i]
            .section
            .as_ref()
            .map_or(C64::new(0.0, 0.0), |s| {
                wave(i) * (model.rho * model.g * s.froude_krylov(k))
            })
    };
    let fd = |i: usize| {
        strips.radiation[i]
            .as_ref()
            .map_or(C64::new(0.0, 0.0), |r| {
                wave(i) * r.diffraction_integral(k, model.rho) * (we * omega0)
            })
    };
    let u_iw = C64::new(0.0, -speed / we); // U/(i w_e)
    let f3_fk = integrate(model, fk);
    let f5_fk = -integrate(model, |i| fk(i) * x(i));
    let mut f3 = f3_fk + integrate(model, fd);
    let mut f5 = f5_fk - integrate(model, |i| (u_iw + x(i)) * fd(i));
    if let Some(a) = transom(model) {
        f3 += u_iw * fd(a);
        f5 -= u_iw * fd(a) * x(a);
    }
    Excitation {
        f3,
        f5,
        f3_fk,
        f5_fk,
    }
}

/// Hydrostatic restoring matrix about the origin.
pub fn restoring(model: &ShipModel) -> [[f64; 2]; 2] {
    let rg = model.rho * model.g;
    let b = |i: usize| model.stations[i].section.as_ref().map_or(0.0, |s| s.beam());
    let x = |i: usize| model.stations[i].x;
    let c33 = rg * integrate(model, b);
    let c35 = -rg * integrate(model, |i| x(i) * b(i));
    let c55 = rg * integrate(model, |i| x(i) * x(i) * b(i))
        + rg * model.volume() * (model.z_buoyancy() - model.zg);
    [[c33, c35], [c35, c55]]
}

/// Rigid-body mass matrix about the origin (G at (x_G, z_G), pitch radius of gyration about G).
pub fn mass_matrix(model: &ShipModel) -> [[f64; 2]; 2] {
    let m = model.mass;
    [
        [m, -m * model.xg],
        [
            -m * model.xg,
            m * (model.k_yy * model.k_yy + model.xg * model.xg),
        ],
    ]
}

/// Response to a regular head wave of unit amplitude.
#[derive(Debug, Clone)]
pub struct Response {
    pub omega0: f64,
    pub omega_e: f64,
    pub wave_number: f64,
    pub speed: f64,
    /// Heave per unit wave amplitude (complex; phase relative to the wave crest at midship).
    pub heave: C64,
    /// Pitch (rad) per unit wave amplitude, positive bow down.
    pub pitch: C64,
    pub excitation: Excitation,
    pub coefficients: Coefficients,
}

/// Solve the coupled heave-pitch equations at wave frequency `omega0` and speed U, with the sectional
/// solutions from `sections` (a [`StripSettings`] solves them directly).
pub fn respond<S: SectionSolutions + ?Sized>(
    model: &ShipModel,
    omega0: f64,
    speed: f64,
    sections: &S,
) -> Result<Response> {
    if !(omega0 > 0.0 && omega0.is_finite()) {
        return Err(Error::Invalid(format!(
            "wave frequency must be positive, got {omega0}"
        )));
    }
    if !speed.is_finite() || speed < 0.0 {
        return Err(Error::Invalid(format!(
            "speed must be finite and >= 0, got {speed}"
        )));
    }
    let we = encounter_frequency(omega0, speed, model.g);
    let strips = sections.strips(model, we)?;
    Ok(respond_with(model, &strips, omega0, speed))
}

/// As [`respond`], reusing sectional solutions computed at the right encounter frequency.
pub fn respond_with(model: &ShipModel, strips: &Strips, omega0: f64, speed: f64) -> Response {
    let we = strips.omega_e;
    let coef = coefficients(model, strips, speed);
    let exc = excitation(model, strips, omega0, speed);
    let m = mass_matrix(model);
    let c = restoring(model);
    let k = Matrix2::from_fn(|j, l| {
        C64::new(c[j][l] - we * we * m[j][l], 0.0) - coef.z[j][l] * (we * we)
    });
    let f = Vector2::new(exc.f3, exc.f5);
    // 2x2 by Cramer's rule (determinant is non-zero for any damped system)
    let det = k[(0, 0)] * k[(1, 1)] - k[(0, 1)] * k[(1, 0)];
    let heave = (f[0] * k[(1, 1)] - k[(0, 1)] * f[1]) / det;
    let pitch = (k[(0, 0)] * f[1] - k[(1, 0)] * f[0]) / det;
    Response {
        omega0,
        omega_e: we,
        wave_number: omega0 * omega0 / model.g,
        speed,
        heave,
        pitch,
        excitation: exc,
        coefficients: coef,
    }
}

/// Uncoupled natural periods at zero speed, T = 2 pi / w_n with w_n^2 (M + A(w_n)) = C for heave and for
/// pitch about the origin (midship) on its own, the added mass taken at the natural frequency itself
/// (secant iteration on the residual). Returns (heave, pitch) in seconds.
///
/// The uncoupled pitch period depends on the pitch axis chosen (the origin here) and ignores the heave-pitch
/// coupling of a fore-aft asymmetric ship; [`natural_mode_periods`] gives the periods of the coupled system.
pub fn natural_periods<S: SectionSolutions + ?Sized>(
    model: &ShipModel,
    sections: &S,
) -> Result<(f64, f64)> {
    let m = mass_matrix(model);
    let c = restoring(model);
    let mut out = [0.0; 2];
    for (j, o) in out.iter_mut().enumerate() {
        let w = natural_frequency(
            |w| {
                let s = sections.strips(model, w)?;
                let a = coefficients(model, &s, 0.0).added_mass[j][j];
                Ok(w * w * (m[j][j] + a) - c[j][j])
            },
            (c[j][j] / m[j][j]).sqrt(),
        )?;
        *o = 2.0 * std::f64::consts::PI / w;
    }
    Ok((out[0], out[1]))
}

/// Root w > 0 of a natural-frequency residual by the secant method, started at `w_dry` (the frequency
/// without added mass) and `w_dry / sqrt 2`.
fn natural_frequency(residual: impl Fn(f64) -> Result<f64>, w_dry: f64) -> Result<f64> {
    let mut w0 = w_dry / std::f64::consts::SQRT_2;
    let mut w1 = w_dry;
    let (mut r0, mut r1) = (residual(w0)?, residual(w1)?);
    for _ in 0..40 {
        if (r1 - r0).abs() < 1e-300 {
            break;
        }
        let w2 = (w1 - r1 * (w1 - w0) / (r1 - r0)).max(0.2 * w1);
        w0 = w1;
        r0 = r1;
        w1 = w2;
        r1 = residual(w1)?;
        if (w1 - w0).abs() < 1e-7 * w1 && w1.is_finite() {
            return Ok(w1);
        }
    }
    Err(Error::Numerical(
        "natural-frequency iteration did not converge".into(),
    ))
}

/// Natural periods of the coupled heave-pitch system at zero speed: the undamped normal modes,
/// det(C - w^2 (M + A(w))) = 0, with the added-mass matrix A (A35 = A53 at zero speed) taken at each mode's
/// own frequency. Returns (heave mode, pitch mode) in seconds; a mode is called heave where heave carries
/// the larger share of its kinetic energy, v3^2 (M + A)33 against v5^2 (M + A)55.
///
/// These are the free oscillations of a model free to heave and pitch, and they do not depend on the axis
/// the equations are written about (the uncoupled pitch period of [`natural_periods`] does). For a ship
/// symmetric fore and aft (C35 = A35 = 0, G at midship) they equal the uncoupled periods. For any 2x2
/// symmetric positive-definite pair the Rayleigh quotient puts the lower modal frequency below both
/// uncoupled ones and the higher above both: coupling separates the modes.
pub fn natural_mode_periods<S: SectionSolutions + ?Sized>(
    model: &ShipModel,
    sections: &S,
) -> Result<(f64, f64)> {
    let m = mass_matrix(model);
    let c = restoring(model);
    let det_c = c[0][0] * c[1][1] - c[0][1] * c[1][0];
    if !(c[0][0] > 0.0 && det_c > 0.0) {
        return Err(Error::Invalid(format!(
            "heave-pitch restoring matrix is not positive definite (C33 {:.6e}, det {:.6e}): \
             no natural periods",
            c[0][0], det_c
        )));
    }
    // The two roots lambda = w^2 of det(C - lambda Mt) = 0 for a total inertia Mt, lower first (the larger
    // root from the formula, the smaller from the product of the roots, for round-off).
    let roots = |mt: &[[f64; 2]; 2]| -> Result<[f64; 2]> {
        let qa = mt[0][0] * mt[1][1] - mt[0][1] * mt[1][0];
        if qa.is_nan() || qa <= 0.0 {
            return Err(Error::Numerical(
                "heave-pitch inertia matrix is not positive definite".into(),
            ));
        }
        let qb = -(c[0][0] * mt[1][1] + c[1][1] * mt[0][0] - 2.0 * c[0][1] * mt[0][1]);
        let hi = (-qb + (qb * qb - 4.0 * qa * det_c).max(0.0).sqrt()) / (2.0 * qa);
        Ok([det_c / (qa * hi), hi])
    };
    // Total inertia M + A(w), A symmetrised (A35 = A53 at zero speed up to round-off).
    let inertia = |w: f64| -> Result<[[f64; 2]; 2]> {
        let s = sections.strips(model, w)?;
        let a = coefficients(model, &s, 0.0).added_mass;
        let a35 = 0.5 * (a[0][1] + a[1][0]);
        Ok([
            [m[0][0] + a[0][0], m[0][1] + a35],
            [m[1][0] + a35, m[1][1] + a[1][1]],
        ])
    };
    let dry = roots(&m)?;
    let mut periods = [0.0; 2];
    let mut heave_share = [0.0; 2];
    for k in 0..2 {
        let w = natural_frequency(|w| Ok(w * w - roots(&inertia(w)?)?[k]), dry[k].sqrt())?;
        let mt = inertia(w)?;
        let lam = roots(&mt)?;
        // Mode shape v from (C - lambda Mt) v = 0, using the row that is further from zero relative to the
        // restoring terms (one row vanishes, up to round-off, when the coupling does).
        let d = |j: usize, l: usize| c[j][l] - lam[k] * mt[j][l];
        let scale = (c[0][0] * c[1][1]).sqrt();
        let n0 = d(0, 0).abs() / c[0][0] + d(0, 1).abs() / scale;
        let n1 = d(1, 0).abs() / scale + d(1, 1).abs() / c[1][1];
        let (v3, v5) = if n0 >= n1 {
            (-d(0, 1), d(0, 0))
        } else {
            (d(1, 1), -d(1, 0))
        };
        let (e3, e5) = (v3 * v3 * mt[0][0], v5 * v5 * mt[1][1]);
        heave_share[k] = e3 / (e3 + e5);
        periods[k] = 2.0 * std::f64::consts::PI / w;
    }
    Ok(if heave_share[0] >= heave_share[1] {
        (periods[0], periods[1])
    } else {
        (periods[1], periods[0])
    })
}
