//! A master simulation's whole state at a moment, taken and put back exactly: what a
//! rewind returns the ride to. The world's snapshot (bodies, motors, the solver's random
//! seed, what touched the ground in the last step) and what the master keeps beside it
//! (the controls it steps with, the crash monitor, the airborne clock).

use super::Simulation;
use crate::bike::{Controls, Crash, CrashMonitor, PitchRequest};
use crate::ode::WorldState;

/// Everything `Simulation::step` reads that the ride changes.
#[derive(Clone, Debug)]
pub struct SimulationState {
    world: WorldState,
    controls: Controls,
    pitch_request: PitchRequest,
    crash: CrashMonitor,
    crashed: Option<Crash>,
    airborne_for: f64,
    ground_blow: f64,
}

impl Simulation {
    /// The state now, to be put back with `restore_state`.
    pub fn state(&self) -> SimulationState {
        SimulationState {
            world: self.world.snapshot(),
            controls: self.controls,
            pitch_request: self.pitch_request,
            crash: self.crash,
            crashed: self.crashed,
            airborne_for: self.airborne_for,
            ground_blow: self.ground_blow,
        }
    }

    /// Puts back a state this simulation had (`state`): stepped on from here with the same
    /// controls, it repeats what it did then exactly.
    pub fn restore_state(&mut self, state: &SimulationState) {
        self.world
            .restore(&state.world)
            .expect("a state of this simulation has its bodies and joints");
        self.controls = state.controls;
        self.pitch_request = state.pitch_request;
        self.crash = state.crash;
        self.crashed = state.crashed;
        self.airborne_for = state.airborne_for;
        self.ground_blow = state.ground_blow;
    }
}
