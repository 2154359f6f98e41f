//! Wheelie control: the drive's torque is cut as the front wheel unloads, as a road bike's
//! anti-wheelie does (e.g. Bosch's motorcycle stability control, which also estimates the
//! lift from the chassis's state). With tyres that grip with the load they carry, full
//! throttle at the rear wheel (up to 700 N·m, about 1 g) lifts the front of this bike at
//! any speed: launched towards 25 km/h it loops over. The sensor is the fork itself: with
//! the front wheel loaded the fork sits near its sag, unloaded it tops out, whatever the
//! slope underfoot. Stateless, so a rollout restored from a snapshot cuts as the master.

/// Where the cut starts and where it is complete, as fork compression (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WheelieControl {
    /// At or above this compression the drive gets all the torque asked for.
    pub full_torque_above: f64,
    /// At or below this compression (the fork near full extension) it gets none.
    pub no_torque_below: f64,
}

impl Default for WheelieControl {
    /// The front carries about 100 kg at 39 mm of sag (18 N/mm): the cut starts when it
    /// carries a fifth of that and is complete when it carries a twentieth, so the front
    /// skims the road under full throttle instead of rising.
    fn default() -> Self {
        Self {
            full_torque_above: 0.008,
            no_torque_below: 0.002,
        }
    }
}

impl WheelieControl {
    /// Share (0–1) of the asked drive torque let through at fork compression `front` (m).
    pub fn torque_share(&self, front: f64) -> f64 {
        if !front.is_finite() {
            return 0.0;
        }
        let span = self.full_torque_above - self.no_torque_below;
        ((front - self.no_torque_below) / span).clamp(0.0, 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cut_ramps_from_loaded_to_topped_out() {
        let control = WheelieControl::default();
        assert_eq!(control.torque_share(0.039), 1.0);
        assert_eq!(control.torque_share(0.008), 1.0);
        assert!((control.torque_share(0.005) - 0.5).abs() < 1e-12);
        assert_eq!(control.torque_share(0.0), 0.0);
        assert_eq!(control.torque_share(f64::NAN), 0.0);
    }
}
