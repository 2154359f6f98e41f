//! Do the rollouts predict the bike the master rides? The same controls, replayed open
//! loop from the same state in the rollouts' physics, against what the master did with
//! them. Cheaper rollout physics (fewer substeps, another solver) is only a saving if
//! this stays small: 2-substep QuickStep rollouts predicted a less stable bike and their
//! plans dropped it (docs/benchmarks-history.md, "rollout fidelity").

use glam::DVec3;

use super::Ride;
use crate::bike::Controls;
use crate::ode::{Solver, WorldState};
use crate::physics::RolloutStepping;
use crate::simulation::Simulation;

/// How a rollout world is stepped through its horizon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RolloutPhysics {
    pub solver: Solver,
    /// ODE steps per control step, counted from the start of a replay.
    pub stepping: RolloutStepping,
}

impl RolloutPhysics {
    /// The master's own physics.
    pub fn of(sim: &Simulation) -> Self {
        Self {
            solver: sim.config().physics.solver(),
            stepping: RolloutStepping::uniform(sim.config().substeps),
        }
    }

    /// What the planners' rollouts step with in `sim`'s physics model.
    pub fn planned_in(sim: &Simulation) -> Self {
        let model = sim.config().physics;
        Self {
            solver: model.rollout_solver(),
            stepping: model.rollout_stepping(),
        }
    }
}

/// A ride as the master rode it: the state before each control step, the controls then
/// applied, and the lean and centre of mass after it.
#[derive(Clone, Debug, Default)]
pub struct Recording {
    states: Vec<WorldState>,
    controls: Vec<Controls>,
    leans: Vec<f64>,
    centres: Vec<DVec3>,
}

impl Recording {
    /// Rides `steps` control steps with the ride's controller and intent, recording.
    pub fn ride(ride: &mut Ride, steps: usize) -> Self {
        let mut recording = Self::default();
        for _ in 0..steps {
            let before = ride.sim().world().snapshot();
            ride.step();
            let sim = ride.sim();
            recording.states.push(before);
            recording.controls.push(*sim.controls());
            recording.leans.push(sim.bike().lean(sim.world(), sim.up()));
            recording
                .centres
                .push(sim.bike().center_of_mass(sim.world()));
        }
        recording
    }

    /// Appends a recording that continues this one.
    pub fn extend(&mut self, next: Recording) {
        self.states.extend(next.states);
        self.controls.extend(next.controls);
        self.leans.extend(next.leans);
        self.centres.extend(next.centres);
    }

    pub fn len(&self) -> usize {
        self.controls.len()
    }

    pub fn is_empty(&self) -> bool {
        self.controls.is_empty()
    }
}

/// How far a replay drifted from the recording after a number of control steps:
/// the largest lean error (rad) and centre-of-mass distance (m) over the replays.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Divergence {
    pub lean: f64,
    pub position: f64,
}

/// Replays the recording in `physics` from every `every`-th recorded state, `horizon`
/// control steps each, and reports the worst divergence at each step count of `at`.
/// A replay whose world explodes counts as infinitely far.
pub fn divergence(
    sim: &Simulation,
    recording: &Recording,
    physics: RolloutPhysics,
    horizon: usize,
    every: usize,
    at: &[usize],
) -> Vec<Divergence> {
    let mut worst = vec![Divergence::default(); at.len()];
    let mut world = sim.new_world();
    world.set_solver(physics.solver);
    let (bike, up) = (sim.bike(), sim.up());
    let starts = (0..recording.len().saturating_sub(horizon)).step_by(every.max(1));
    for start in starts {
        world
            .restore(&recording.states[start])
            .expect("the recording comes from this simulation");
        let mut exploded = false;
        for step in 0..horizon {
            let k = start + step;
            bike.apply(&mut world, &recording.controls[k]);
            let (substeps, dt) = physics.stepping.ode_steps_at(step, sim.config().control_dt);
            for _ in 0..substeps {
                world.step(dt);
                exploded |= bike.explosion(&world).is_some();
            }
            let Some(slot) = at.iter().position(|&n| n == step + 1) else {
                continue;
            };
            let found = if exploded {
                Divergence {
                    lean: f64::INFINITY,
                    position: f64::INFINITY,
                }
            } else {
                Divergence {
                    lean: (bike.lean(&world, up) - recording.leans[k]).abs(),
                    position: bike.center_of_mass(&world).distance(recording.centres[k]),
                }
            };
            worst[slot].lean = worst[slot].lean.max(found.lean);
            worst[slot].position = worst[slot].position.max(found.position);
        }
    }
    worst
}
