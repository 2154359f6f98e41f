//! The suspension: a telescopic fork (the lower legs slide along the steering axis) and a
//! swingarm pivoting on the frame, each sprung and damped by an ODE joint spring
//! (`cpbp_ode::Spring`), with hard stops at the ends of travel.
//!
//! Where the numbers come from:
//! - **Travel** 130 mm at each wheel: the 120–140 mm, the class's range (Honda
//!   CB300R 130 mm front; KTM 390 Duke about 140 mm front, 150 mm rear; manufacturers'
//!   specifications).
//! - **Rider sag** 30 % of travel: the usual road setting (setup guides quote 25–35 %,
//!   e.g. Thede & Parks, *Race Tech's Motorcycle Suspension Bible*, 2010). The model is
//!   built at sag, so the springs' preload is derived from the static loads: the bike
//!   stands at its built pose with the rider aboard.
//! - **Rates** 18 N/mm for the fork (both legs, along the tubes; about 0.9 kg/mm a leg,
//!   what road forks of this class run for a 75 kg rider) and 20 N/mm at the rear wheel:
//!   with about 100 kg sprung on each end they put the bounce near 2 Hz, where road
//!   motorcycles' bounce and pitch modes lie (Cossalter, *Motorcycle Dynamics*, 2006:
//!   in-plane modes 1.5–3 Hz, wheel hop 10–15 Hz).
//! - **Damping** 0.4 of critical for the sprung mass each end carries: road dampers sit
//!   between a quarter and a half of critical (Foale, *Motorcycle Handling and Chassis
//!   Design*, 2002). One linear damper for bump and rebound alike.

use glam::DVec3;

/// Travel, sag, rates and damping of both ends. Part of [`super::BikeParams`].
#[derive(Clone, Debug, PartialEq)]
pub struct Suspension {
    /// Fork travel along the tubes (m).
    pub front_travel: f64,
    /// Rear travel at the wheel (m).
    pub rear_travel: f64,
    /// Share of the fork's travel used at rest with the rider aboard…
    pub sag: f64,
    /// … and of the rear's. Riders set the rear a little deeper (setup guides: 25–30 %
    /// front, 30–35 % rear); braking hard the rear unloads and extends by its sag, and a
    /// rear that tops out before the front has dived lifts its wheel off the road.
    pub rear_sag: f64,
    /// Fork spring rate, both legs together, along the tubes (N/m).
    pub front_rate: f64,
    /// Rear spring rate at the wheel (N/m): the shock's rate over the lever ratio squared.
    pub rear_rate: f64,
    /// Damping as a fraction of critical for the sprung mass each end carries.
    pub damping_ratio: f64,
}

impl Default for Suspension {
    fn default() -> Self {
        Self {
            front_travel: 0.13,
            rear_travel: 0.13,
            sag: 0.30,
            rear_sag: 0.30,
            front_rate: 18_000.0,
            rear_rate: 20_000.0,
            damping_ratio: 0.4,
        }
    }
}

impl Suspension {
    /// The fork slider's travel (m; extension positive, 0 as built at sag).
    pub fn front_travel_range(&self) -> (f64, f64) {
        let sag = self.sag * self.front_travel;
        (sag - self.front_travel, sag)
    }

    /// The swingarm's travel as an angle about the pivot (rad; extension positive, 0 as
    /// built) for a swingarm reaching `reach` (m) behind the pivot.
    pub fn rear_travel_range(&self, reach: f64) -> (f64, f64) {
        let sag = self.rear_sag * self.rear_travel / reach;
        (sag - self.rear_travel / reach, sag)
    }

    /// Damping rate (N·s/m) for `rate` (N/m) carrying `sprung_mass` (kg).
    pub fn damping(&self, rate: f64, sprung_mass: f64) -> f64 {
        2.0 * self.damping_ratio * (rate * sprung_mass.max(1.0)).sqrt()
    }
}

/// How the weight of bike and rider at rest divides between the wheels: ground forces
/// (N) under each contact point from the centre of mass's place between them.
pub fn static_wheel_loads(
    center_of_mass: DVec3,
    rear_contact_x: f64,
    front_contact_x: f64,
    weight: f64,
) -> (f64, f64) {
    let front = weight * (center_of_mass.x - rear_contact_x) / (front_contact_x - rear_contact_x);
    (weight - front, front)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn travel_splits_at_the_sag() {
        let s = Suspension::default();
        let (lo, hi) = s.front_travel_range();
        assert!((hi - 0.039).abs() < 1e-12 && (hi - lo - 0.13).abs() < 1e-12);
        let (lo, hi) = s.rear_travel_range(0.5);
        assert!((hi * 0.5 - 0.039).abs() < 1e-12 && ((hi - lo) * 0.5 - 0.13).abs() < 1e-12);
    }

    #[test]
    fn loads_by_hand() {
        // 1000 N with the centre of mass a quarter of the way from the rear contact.
        let (rear, front) = static_wheel_loads(DVec3::new(-0.25, 0.7, 0.0), -0.5, 0.5, 1000.0);
        assert!((rear - 750.0).abs() < 1e-9 && (front - 250.0).abs() < 1e-9);
        // 0.4 of critical for 18 N/mm and 100 kg: 0.8·√(1.8·10⁶) ≈ 1073 N·s/m.
        let c = Suspension::default().damping(18_000.0, 100.0);
        assert!((c - 1073.3).abs() < 0.1, "{c}");
    }
}
