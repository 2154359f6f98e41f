//! Planning off the game thread. While the master simulates control step t with control
//! u_t, a planning thread restores the master's state at the start of step t into its own
//! replica, simulates u_t to predict the state at t + 1, and plans step t + 1 from there.
//! At the next control-step boundary the game takes the plan over (the hand-over); if it
//! is late it does not stall: the game keeps replaying the previous best trajectory open
//! loop (or, with none, the arcade controller) and takes the plan that is for the step it
//! has reached once one arrives. If the planning thread dies (a panic), the game keeps
//! riding on the arcade controller and the failure is kept, with its message, for the
//! ride to report.

use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use glam::DVec3;

use super::arcade::ArcadeController;
use super::learned::PolicyNetwork;
use super::plan_result::{Diagnostics, PlanPhases};
use super::planner::PlannerSpec;
use super::planning_session::{PlanningConfig, PlanningSession};
use super::Goal;
use crate::bike::Controls;
use crate::ode::WorldState;
use crate::simulation::Simulation;

/// What the game thread asks of the planning thread.
enum Message {
    Plan(Box<Request>),
    /// Dies with this message, as a bug in the planner would (tests of the fallback).
    Fail(String),
}

/// What the planning thread plans: the plan for master step `step`, made from the state
/// one step earlier and the control applied during that step.
struct Request {
    epoch: u64,
    step: u64,
    start: WorldState,
    applied: Controls,
    goal: Goal,
    config: PlanningConfig,
    network: Option<Arc<PolicyNetwork>>,
    reset: bool,
}

/// A finished plan.
#[derive(Clone, Debug)]
pub struct Plan {
    /// Plans from before a reset have an older epoch and are dropped.
    epoch: u64,
    /// The master step its first control is for.
    pub step: u64,
    /// The chosen sequence's controls (the best trajectory's, or MPPI's average), one per
    /// control step from `step` on.
    pub sequence: Vec<Controls>,
    pub best_cost: f64,
    /// Trajectories it was planned with (N).
    pub trajectories: usize,
    pub blowups: usize,
    /// The planner's own numbers about the plan (C-PBP: "resamples", "fallen steps").
    pub diagnostics: Diagnostics,
    pub planning_ms: f64,
    /// Where the planner's own time went (within `planning_ms`, which also counts the
    /// replica's prediction step and the hand-over's copies).
    pub phases: PlanPhases,
    /// Every trajectory's centre-of-mass path; `best` and `warm` index into it.
    pub paths: Vec<Vec<DVec3>>,
    pub best: usize,
    /// The refinement's (optimizer) or the arcade rollout's (combined) trajectory.
    pub warm: Option<usize>,
}

/// How the hand-overs went: waits at the boundary and plans that came too late.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HandoverStats {
    /// Milliseconds the game thread waited for a plan at the last boundary.
    pub last_wait_ms: f64,
    pub max_wait_ms: f64,
    pub total_wait_ms: f64,
    /// Boundaries passed, and those at which no plan for that step was ready.
    pub boundaries: u64,
    pub late: u64,
}

impl HandoverStats {
    pub fn mean_wait_ms(&self) -> f64 {
        self.total_wait_ms / self.boundaries.max(1) as f64
    }
}

/// How long the game thread waits at a control-step boundary for the plan of the step
/// about to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlanWait {
    /// At most this long; a later plan is taken over at a later step while the last best
    /// trajectory plays on (the game: a slow plan must not stall the frame).
    AtMost(Duration),
    /// Until the plan comes: every step uses a fresh plan, so a ride repeats exactly
    /// whatever the machine's speed or load (headless tests and experiments).
    EveryPlan,
}

/// The planning thread and the game thread's side of the hand-over.
pub struct PlanningThread {
    requests: Option<Sender<Message>>,
    replies: Receiver<Plan>,
    worker: Option<JoinHandle<()>>,
    outstanding: bool,
    plan: Option<Plan>,
    arcade: ArcadeController,
    step: u64,
    /// Control steps since the last reset: the first has no plan by design (nothing was
    /// planned for it), which is not a late plan.
    steps_since_reset: u64,
    epoch: u64,
    reset_pending: bool,
    /// How long the game thread waits at a boundary for a plan before falling back.
    pub wait: PlanWait,
    pub stats: HandoverStats,
    /// Why the planning thread died, once it has: the arcade controller drives from then
    /// on.
    failure: Option<String>,
}

impl PlanningThread {
    /// Starts a planning thread with its own replica of `sim`, planning with the planner
    /// `spec` builds.
    pub fn new(sim: &Simulation, spec: &'static PlannerSpec, wait: PlanWait) -> Self {
        let (request_tx, request_rx) = channel::<Message>();
        let (reply_tx, reply_rx) = channel::<Plan>();
        let replica = sim.replica();
        let worker = std::thread::Builder::new()
            .name("cpbp-planner".into())
            .spawn(move || plan_requests(replica, spec, request_rx, reply_tx))
            .expect("the planning thread could not start");
        Self {
            requests: Some(request_tx),
            replies: reply_rx,
            worker: Some(worker),
            outstanding: false,
            plan: None,
            arcade: ArcadeController::default(),
            step: 0,
            steps_since_reset: 0,
            epoch: 0,
            reset_pending: true,
            wait,
            stats: HandoverStats::default(),
            failure: None,
        }
    }

    /// Why the planning thread died, if it did (the arcade controller drives instead).
    pub fn failure(&self) -> Option<&str> {
        self.failure.as_deref()
    }

    /// Makes the planning thread die with `message` as a panic in the planner would: for
    /// tests of the fallback and of how the failure is reported.
    pub fn inject_fault(&mut self, message: &str) {
        if let Some(sender) = &self.requests {
            let _ = sender.send(Message::Fail(message.to_owned()));
        }
    }

    /// Forgets plans (after a reset, a lift or a teleport): they were for another state.
    pub fn reset(&mut self) {
        self.plan = None;
        self.arcade.reset();
        self.reset_pending = true;
        self.epoch += 1;
        self.steps_since_reset = 0;
    }

    /// The most recent plan taken over (for statistics and drawing).
    pub fn plan(&self) -> Option<&Plan> {
        self.plan.as_ref()
    }

    /// The controls for the master's next step; call once per control step, then step.
    /// `network` is what a planner that follows one (guided) follows.
    pub fn controls(
        &mut self,
        sim: &Simulation,
        goal: &Goal,
        config: &PlanningConfig,
        network: Option<&Arc<PolicyNetwork>>,
    ) -> Controls {
        self.take_plan();
        // Run every step, used or not, so its memory is in step with the master whenever
        // a plan is missing.
        let fallback = self.arcade.controls_of(sim, goal);
        let planned = self.plan.as_ref().and_then(|plan| {
            let offset = self.step.checked_sub(plan.step)?;
            plan.sequence.get(offset as usize).copied()
        });
        let controls = planned.unwrap_or(fallback);
        if !self.outstanding {
            let request = Request {
                epoch: self.epoch,
                step: self.step + 1,
                start: sim.world().snapshot(),
                applied: controls,
                goal: *goal,
                config: config.clone(),
                network: network.cloned(),
                reset: std::mem::take(&mut self.reset_pending),
            };
            if let Some(sender) = &self.requests {
                self.outstanding = sender.send(Message::Plan(Box::new(request))).is_ok();
                if !self.outstanding {
                    self.note_death();
                }
            }
        }
        self.step += 1;
        self.steps_since_reset += 1;
        controls
    }

    /// At a boundary: wait (as `wait` says) for the plan of the step about to run.
    fn take_plan(&mut self) {
        let started = Instant::now();
        let mut fresh = false;
        while self.outstanding {
            let reply = match self.wait {
                PlanWait::AtMost(limit) => self
                    .replies
                    .recv_timeout(limit.saturating_sub(started.elapsed())),
                PlanWait::EveryPlan => self
                    .replies
                    .recv()
                    .map_err(|_| RecvTimeoutError::Disconnected),
            };
            match reply {
                Ok(plan) => {
                    self.outstanding = false;
                    if plan.epoch == self.epoch && plan.step <= self.step {
                        fresh |= plan.step == self.step;
                        self.plan = Some(plan);
                    }
                }
                Err(RecvTimeoutError::Timeout) => break,
                Err(RecvTimeoutError::Disconnected) => {
                    self.outstanding = false;
                    self.note_death();
                }
            }
        }
        let waited = started.elapsed().as_secs_f64() * 1000.0;
        let stats = &mut self.stats;
        stats.last_wait_ms = waited;
        stats.max_wait_ms = stats.max_wait_ms.max(waited);
        stats.total_wait_ms += waited;
        stats.boundaries += 1;
        stats.late += u64::from(!fresh && self.steps_since_reset > 0);
    }

    /// The planning thread hung up: keep why (its panic message), stop asking it for
    /// plans, and let the arcade controller drive.
    fn note_death(&mut self) {
        self.requests = None;
        self.plan = None;
        let Some(worker) = self.worker.take() else {
            return;
        };
        let why = match worker.join() {
            Ok(()) => "the planning thread stopped".to_owned(),
            Err(panic) => panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "the planning thread panicked".to_owned()),
        };
        self.failure = Some(why);
    }
}

impl Drop for PlanningThread {
    fn drop(&mut self) {
        // Closing the channel ends the thread's loop after the plan in hand.
        self.requests = None;
        if let Some(worker) = self.worker.take() {
            let _ = worker.join();
        }
    }
}

/// The planning thread's loop: one plan per request until the game side hangs up.
fn plan_requests(
    mut replica: Simulation,
    spec: &'static PlannerSpec,
    requests: Receiver<Message>,
    replies: Sender<Plan>,
) {
    let mut optimizer: Option<PlanningSession> = None;
    for message in requests {
        let request = match message {
            Message::Plan(request) => request,
            Message::Fail(why) => panic!("{why}"),
        };
        let started = Instant::now();
        if replica.world_mut().restore(&request.start).is_err() {
            continue;
        }
        replica.set_controls(request.applied);
        replica.set_pitch_request(request.goal.pitch_request());
        replica.step();
        let optimizer = match &mut optimizer {
            Some(o) if o.config == request.config => o,
            // The automatic N moves N while riding: keep the planner, its memory and its
            // worlds rather than building them anew.
            Some(o) if o.config.differs_only_in_trajectories(&request.config) => {
                o.set_trajectories(&replica, request.config.trajectories);
                o
            }
            slot => slot.insert(PlanningSession::new(&replica, spec, request.config.clone())),
        };
        if request.reset {
            optimizer.reset();
        }
        optimizer.follow(request.network);
        optimizer.note_applied(&request.applied);
        optimizer.controls(&replica, &request.goal);
        let Some(result) = optimizer.last_plan() else {
            continue;
        };
        let plan = Plan {
            epoch: request.epoch,
            step: request.step,
            sequence: optimizer.chosen_sequence(),
            best_cost: result.best_cost,
            trajectories: optimizer.config.trajectories,
            blowups: result.blowups,
            diagnostics: result.diagnostics.clone(),
            planning_ms: started.elapsed().as_secs_f64() * 1000.0,
            phases: optimizer.phases(),
            paths: result
                .trajectories
                .iter()
                .map(|t| t.path.iter().map(|x| DVec3::from_array(*x)).collect())
                .collect(),
            best: result.best,
            warm: result.warm,
        };
        if replies.send(plan).is_err() {
            return;
        }
    }
}
