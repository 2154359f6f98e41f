//! What the planner plans over: a system it can save, restore and step, one instance per
//! particle.

/// A simulated system the planner can branch: one instance per particle, all built alike.
/// Instances are stepped on several threads at once, each by one thread at a time. A
/// thread may step several particles in one instance, restoring each particle's state
/// before its step: whatever a step depends on must be in `State`, except for the
/// particle that follows the system's `policy`, which keeps its own instance.
pub trait RolloutSystem: Send {
    /// Everything needed to put an instance back into a state (a world snapshot).
    type State: Clone + Send + Sync;
    fn save(&self) -> Self::State;
    fn restore(&mut self, state: &Self::State);
    /// Applies control `u` for planning step `step` and simulates it; returns the step's
    /// state cost (squared, tolerance-scaled), or `None` when the simulation blew up.
    fn step(&mut self, u: &[f64], step: usize) -> Option<f64>;
    /// A prior that depends on the current state (the thesis's pose prior): per dimension
    /// a mean and a standard deviation (infinite for dimensions it says nothing about).
    fn client_prior(&self) -> Option<(Vec<f64>, Vec<f64>)> {
        None
    }
    /// A few numbers describing the state, scaled to about unit size, that the local
    /// refinement regresses controls on. None (the default): no refinement.
    fn features(&self) -> Vec<f64> {
        Vec::new()
    }
    /// The control the system's own controller would choose now (for the combined mode's
    /// arcade controller), when it has one: particle 1 follows it live under
    /// [`WarmStart::Policy`](super::WarmStart::Policy).
    fn policy(&mut self, _step: usize) -> Option<Vec<f64>> {
        None
    }
    /// A point to draw the trajectory through (the bike's centre of mass), if any.
    fn trace_point(&self) -> Option<[f64; 3]> {
        None
    }
    /// The cost of the rest of a longer horizon from the current state (a learned
    /// cost-to-go), added to the cost of a plan's last step; None (the default): a plan
    /// ends with its last step.
    fn terminal_cost(&self) -> Option<f64> {
        None
    }
    /// Whether the last step left the system fallen past recovering (the bike on the
    /// ground with anything but its wheels and feet): C-PBP counts the steps simulated
    /// after a fall (`FALLEN_STEPS`). False (the default): it never falls.
    fn fallen(&self) -> bool {
        false
    }
    /// What a cost-to-go is learned from at the current state (the policy's features);
    /// empty (the default): the system records no samples for one.
    fn value_features(&self) -> Vec<f64> {
        Vec::new()
    }
}
