//! The wheels' motors: the rear's from the throttle's and brake's targets, through the
//! wheelie control when the bike has one, and the front brake.

use glam::DVec3;

use super::{Bike, Part};
use crate::bike::controls::{index, Controls, ForceClass};
use crate::bike::drive::{brake_level, drives};
use crate::bike::front_brake::{FrontBrake, OverFrontTyre};
use crate::bike::params::GRAVITY;
use crate::bike::wheelie_control::PitchRequest;
use crate::ode::World;

impl Bike {
    /// Sets the rear wheel's motor from the controls' target and force tuning; driving,
    /// the wheelie control keeps the front down (or, with `held.lift` > 0, holds a
    /// wheelie of that height), lets an overrunning wheel slow gently, and in the air
    /// with `held.air` ≠ 0 spins the wheel up or brakes it.
    pub(super) fn set_rear_motor(
        &self,
        world: &mut World,
        controls: &Controls,
        held: PitchRequest,
        up: DVec3,
    ) {
        let c = controls.values();
        let driving = drives(controls);
        let lift = held.lift;
        match &self.params.wheelie_control {
            Some(control) if held.air != 0.0 => {
                // Spun up (towards the throttle's speed and the hold's headroom beyond
                // it, no further) the wheel's reaction lifts the nose; braked, it drops.
                let target = if held.air > 0.0 {
                    c[index::REAR_WHEEL].max(0.0) + control.headroom_spin(self.params.wheel_radius)
                } else {
                    0.0
                };
                let torque =
                    self.rear_torque(world, held.air > 0.0) * held.air.abs() * control.air_share;
                world.set_motor(self.rear_axle, 0, target, torque);
            }
            Some(control) if driving && lift > 0.0 => {
                let (ahead, rate) = self.weight_ahead_of_support(world, up, lift);
                let share = control.hold_share(ahead, rate);
                // Driving, the hold aims above the throttle's speed (which, once reached,
                // would leave no torque to lift with) and past that lets the wheel run
                // free rather than brake it; braking, it holds the wheel still.
                let (target, share) = if share >= 0.0 {
                    let headroom = control.headroom_spin(self.params.wheel_radius);
                    let limit = c[index::REAR_WHEEL] + headroom;
                    let running_free = world.hinge_rate(self.rear_axle) >= limit;
                    (limit, if running_free { 0.0 } else { share })
                } else {
                    (0.0, -share)
                };
                let full = self.rear_torque(world, target > 0.0);
                world.set_motor(self.rear_axle, 0, target, full * share);
            }
            control => {
                // Driving (not braking, which holds the wheel still), the anti-wheelie
                // may cut.
                let drive_share = match control {
                    Some(control) if driving => {
                        let overrun = control.overrun_margin / self.params.wheel_radius;
                        if world.hinge_rate(self.rear_axle) > c[index::REAR_WHEEL] + overrun {
                            control.overrun_share
                        } else {
                            control.torque_share(self.fork_compression(world))
                        }
                    }
                    // Braking with a front brake too, the rear gets its share of the
                    // trigger (`FrontBrake::rear_share`).
                    _ => match &self.params.front_brake {
                        Some(front) if brake_level(controls) > 0.0 => {
                            front.rear_share * self.righting_share(world, front, up)
                        }
                        _ => 1.0,
                    },
                };
                let target = match &self.params.front_brake {
                    Some(front) if brake_level(controls) > 0.0 && held.stoppie == 0.0 => {
                        front.abs_floor(self.forward_speed(world, up), self.params.wheel_radius)
                    }
                    _ => c[index::REAR_WHEEL],
                };
                let force = c[index::FORCE + ForceClass::RearWheel as usize];
                let full = self.rear_torque(world, driving);
                world.set_motor(self.rear_axle, 0, target, full * force * drive_share);
            }
        }
    }

    /// The most torque (N·m) on the rear wheel now: the drive's (`driving`, less above
    /// the speed its power limit starts at) or the rear brake's.
    fn rear_torque(&self, world: &World, driving: bool) -> f64 {
        let drive = &self.params.rear_drive;
        if driving {
            drive.drive_torque(world.hinge_rate(self.rear_axle))
        } else {
            drive.brake_torque
        }
    }

    /// Sets a modulating front brake again before a physics step of `dt` seconds
    /// (outside a stoppie, whose hold keeps its setting for the period): the tipping
    /// limit reads the bike as it is now and the ramp rises by `dt`. Other brakes keep the
    /// period's setting, as the reference bike was evaluated.
    pub(super) fn modulate_front_brake(
        &self,
        world: &mut World,
        controls: &Controls,
        held: PitchRequest,
        up: DVec3,
        dt: f64,
    ) {
        match &self.params.front_brake {
            Some(brake) if brake.modulates() && held.stoppie == 0.0 => {
                self.set_front_brake(world, controls, held, up, dt);
            }
            _ => {}
        }
    }

    /// Sets the front brake `dt` seconds after its last setting (0 at the start of a
    /// control period): with the triggers' brake (the controls' rear wheel held still
    /// with some force), lifting off as the rear unloads, or holding a stoppie when
    /// `held.stoppie` > 0; free otherwise. A bike without one keeps its front wheel free.
    /// A brake that ramps may only let off at 0 s: `modulate_front_brake` raises it
    /// before each physics step, so a bike stepped outside `step_control_period` does not
    /// brake with a ramp.
    pub(super) fn set_front_brake(
        &self,
        world: &mut World,
        controls: &Controls,
        held: PitchRequest,
        up: DVec3,
        dt: f64,
    ) {
        let Some(brake) = &self.params.front_brake else {
            return;
        };
        let level = brake_level(controls);
        let (share, ramps) = if level == 0.0 {
            (0.0, false)
        } else if held.stoppie > 0.0 {
            let (ahead, rate) = self.weight_ahead_of_support(world, up, -held.stoppie);
            (brake.hold_share(ahead, rate), false)
        } else {
            let window = brake.lift_off_share(self.suspension_compression(world).1);
            let speed = self.forward_speed(world, up);
            let eased = brake.eased(speed);
            let lean = self.lean(world, up);
            let cornering = brake.cornering_share(lean, speed);
            let righting = brake.righting_share(lean, speed, self.full_lock_lean_speed2());
            let tipping = self.tipping_limit(world, brake, up);
            let (steer, lock) = (self.steering(world).0, self.params.steer_limit);
            let bar = brake.walking_bar_share(speed, steer, lock);
            (
                level * window * eased * cornering * righting * tipping * bar,
                true,
            )
        };
        // ABS keeps the wheels turning, except in a stoppie the rider asked for: the hold
        // needs the wheel stopped to pitch the bike over it (the rear's ABS is off then too).
        let floor = if held.stoppie > 0.0 {
            0.0
        } else {
            brake.abs_floor(self.forward_speed(world, up), self.params.wheel_radius)
        };
        let mut torque = brake.max_torque * share;
        if ramps && brake.modulates() {
            let current = world.motor_state(self.front_axle).max_force[0];
            torque = brake.ramped(current, torque, dt);
        }
        world.set_motor(self.front_axle, 0, floor, torque);
    }

    /// The share of either brake the righting reserve lets through now
    /// (`FrontBrake::righting_share`): it eases the rear brake the trigger shares out as
    /// well, which alone would otherwise take the bike below the speed it stands up at.
    fn righting_share(&self, world: &World, brake: &FrontBrake, up: DVec3) -> f64 {
        let (lean, speed) = (self.lean(world, up), self.forward_speed(world, up));
        brake.righting_share(lean, speed, self.full_lock_lean_speed2())
    }

    /// g·L / (tan δ·cos ε) (m²/s²): times sin θ, the speed squared at which the bike's
    /// tightest turn (the bar at its lock δ) holds a lean θ (`FrontBrake::righting_share`).
    fn full_lock_lean_speed2(&self) -> f64 {
        let p = &self.params;
        GRAVITY * p.wheelbase / (p.steer_limit.tan() * p.rake.cos())
    }

    /// The share of the front brake's full torque its tipping limit allows now
    /// (`FrontBrake::tipping_limit`; 1 with the limit off). The road is the terrain under
    /// the front tyre as its contacts met it in the last step (`World::body_ground_normal`),
    /// so the rule reads the slope and needs nothing of the rear wheel, which skims the
    /// road near the limit; a front wheel in the air brakes nothing.
    fn tipping_limit(&self, world: &World, brake: &FrontBrake, up: DVec3) -> f64 {
        if brake.tipping_share <= 0.0 {
            return 1.0;
        }
        let front_wheel = self.body(Part::FrontWheel);
        let Some(normal) = world.body_ground_normal(front_wheel) else {
            return 1.0;
        };
        let heading = self.heading(world, up);
        let along = (heading - normal * heading.dot(normal)).normalize_or(heading);
        let (_, contact) = self.tyre_contacts(world, normal);
        let weight = self.center_of_mass(world) - contact;
        let velocity =
            self.center_of_mass_velocity(world) - world.body_linear_velocity(front_wheel);
        let over = OverFrontTyre {
            behind: -weight.dot(along),
            height: weight.dot(normal),
            behind_rate: -velocity.dot(along),
            height_rate: velocity.dot(normal),
            load: self.mass(world) * GRAVITY * normal.dot(up),
        };
        brake.tipping_limit(&over, self.params.wheel_radius)
    }
}
