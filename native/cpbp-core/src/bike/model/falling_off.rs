//! The rider falling off: after a crash the foot leaves the peg and the hand the grip,
//! and the rider's own joints go slack, so the same bodies tumble as a ragdoll. Putting
//! the bike back (a reset or a lift) puts the rider back on: every joint is switched on
//! again with the motors (`World::reset_motors`).

use super::Bike;
use crate::bike::controls::{index, Controls, ForceClass, LOWER};
use crate::ode::World;

impl Bike {
    /// Lets the rider go: the foot and the hand no longer hold the bike.
    pub fn release_rider(&self, world: &mut World) {
        for joint in self.rider_holds {
            world.set_joint_enabled(joint, false);
        }
    }

    /// How far (m) the rider's foot is from its peg and hand from its grip: millimetres
    /// while riding, more once the rider let go.
    pub fn rider_hold_gaps(&self, world: &World) -> [f64; 2] {
        [
            world.ball_anchor_gap(self.rider_holds[0]),
            world.ball_anchor_gap(self.rider_holds[1]),
        ]
    }

    /// Whether the rider is on the bike (not fallen off).
    pub fn rider_is_on(&self, world: &World) -> bool {
        world.joint_enabled(self.rider_holds[0])
    }
}

impl Controls {
    /// A fallen rider's and a riderless bike's controls: every joint aimed still at the
    /// least force there is (a dazed rider's muscle tone, which damps the tumble), the
    /// bar free to swing, the rear wheel rolling freely.
    pub fn slack() -> Self {
        let mut slack = Self::default();
        for class in [
            ForceClass::Steering,
            ForceClass::Waist,
            ForceClass::Knee,
            ForceClass::Arms,
        ] {
            let at = index::FORCE + class as usize;
            slack.set(at, LOWER[at]);
        }
        slack.set(index::FORCE + ForceClass::RearWheel as usize, 0.0);
        slack
    }
}
