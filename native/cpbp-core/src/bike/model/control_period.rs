//! One control period of the bike, the one way every world that carries a bike is
//! stepped: the master, the planning thread's replica (both through `Simulation::step`)
//! and every planning step of every rollout. They differ only in how finely they step
//! and in what they watch while it runs, both arguments here, so a rule added to the
//! bike's step (an assist, a new check) reaches the plans and the ride at once.

use glam::DVec3;

use super::Bike;
use crate::bike::controls::Controls;
use crate::bike::wheelie_control::PitchRequest;
use crate::ode::World;

/// What a caller watches while `Bike::step_control_period` runs.
pub trait PeriodWatch {
    /// Once, after the controls are set and before the first ODE step.
    fn started(&mut self, _world: &World) {}
    /// After each ODE step (of `dt` seconds) that did not blow the simulation up.
    fn stepped(&mut self, _world: &World, _dt: f64) {}
}

/// A closure watches each ODE step.
impl<F: FnMut(&World, f64)> PeriodWatch for F {
    fn stepped(&mut self, world: &World, dt: f64) {
        self(world, dt)
    }
}

/// The simulation blew up during a period: why, as `Bike::explosion` says.
#[derive(Clone, Debug, PartialEq)]
pub struct Exploded(pub String);

impl Bike {
    /// Steps `world` one control period with `controls` held: the pitch `asked` for (as
    /// far as the bike's wheelie control holds it; `up` is against gravity), then
    /// `substeps` ODE steps of `dt` each (a modulating front brake set again before each,
    /// `FrontBrake::modulates`). The period stops at the first step that blows
    /// the simulation up, before `watch` sees it. Returns the pitch held.
    pub fn step_control_period(
        &self,
        world: &mut World,
        controls: &Controls,
        asked: PitchRequest,
        up: DVec3,
        (substeps, dt): (usize, f64),
        watch: &mut impl PeriodWatch,
    ) -> Result<PitchRequest, Exploded> {
        let held = self.held_pitch(world, up, asked);
        self.apply_pitching(world, controls, held, up);
        watch.started(world);
        for _ in 0..substeps {
            self.modulate_front_brake(world, controls, held, up, dt);
            self.move_legs(world, up, dt);
            world.step(dt);
            if let Some(reason) = self.explosion(world) {
                return Err(Exploded(reason));
            }
            watch.stepped(world, dt);
        }
        Ok(held)
    }
}
