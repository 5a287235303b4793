//! The wedge-equivalent correction of the MLM pressure (see [`crate::analytic::similarity_table`]):
//! every pressure of a sample is multiplied by K(beta_c) = Cp_sim(beta_c) / Cp_MLM(beta_c), beta_c the
//! local deadrise atan f'(c) at the contact point of that sample. Samples in the acoustic stage (a flat
//! keel at contact: water-hammer values) and before wetting are left as they are (K = 1).

use super::Mlm;
use crate::analytic::entry_kinematics::EntryState;
use crate::analytic::similarity_table::{PeakCorrection, peak_correction};

impl Mlm {
    /// The local deadrise atan f'(c) (rad) at the contact point of a state, or `None` before wetting or
    /// in the acoustic stage.
    pub fn contact_deadrise(&self, s: &EntryState) -> Option<f64> {
        (s.c > 0.0 && s.c_dot.is_some()).then(|| self.hist.profile.slope(s.c).atan())
    }

    /// The correction of a state (factor 1 where [`Mlm::contact_deadrise`] is `None`).
    pub fn correction(&self, s: &EntryState) -> PeakCorrection {
        self.contact_deadrise(s)
            .map_or(peak_correction(0.0), peak_correction)
    }

    /// The corrected largest pressure on the wetted part and its x ([`Mlm::peak`] times the factor).
    pub fn corrected_peak(&self, s: &EntryState) -> (f64, f64) {
        let (x, p) = self.peak(s);
        (x, p * self.correction(s).factor)
    }

    /// The correction of every kept sample.
    pub fn corrections(&self) -> Vec<PeakCorrection> {
        self.hist
            .states
            .iter()
            .map(|s| self.correction(s))
            .collect()
    }

    /// [`Mlm::sensor_histories`] with every sample multiplied by its correction factor, and the
    /// corrections (one per kept sample).
    pub fn corrected_sensor_histories(
        &self,
        panels: &[(f64, f64)],
    ) -> (Vec<Vec<f64>>, Vec<PeakCorrection>) {
        let k = self.corrections();
        let mut h = self.sensor_histories(panels);
        for row in &mut h {
            for (p, c) in row.iter_mut().zip(&k) {
                *p *= c.factor;
            }
        }
        (h, k)
    }
}
