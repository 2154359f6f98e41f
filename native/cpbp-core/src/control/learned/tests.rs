//! The model file's contract: what is written reads back the same, a network computes
//! what its weights say, and anything broken or foreign is refused with a reason.

use std::collections::HashMap;

use safetensors::tensor::TensorView;
use safetensors::{Dtype, SafeTensors};

use super::*;
use crate::bike::Controls;
use crate::bike::{CONTROL_DIM, DRIVE_ENTRIES};

/// One linear layer passing feature `o` through to output `o`, with normalisations that
/// are easy to compute by hand.
fn pass_through() -> NetworkParts {
    let mut weight = vec![0.0; OUTPUT_COUNT * FEATURE_COUNT];
    (0..OUTPUT_COUNT).for_each(|o| weight[o * FEATURE_COUNT + o] = 1.0);
    NetworkParts {
        input_mean: vec![1.0; FEATURE_COUNT],
        input_std: vec![2.0; FEATURE_COUNT],
        layers: vec![(weight, vec![0.5; OUTPUT_COUNT])],
        output_mean: vec![-1.0; OUTPUT_COUNT],
        output_std: vec![3.0; OUTPUT_COUNT],
        training: "by hand".into(),
        bike: crate::bike::BikeParams::default().identity(),
    }
}

/// Two layers: 4 tanh units reading the first features, then a linear read-out.
fn two_layers() -> NetworkParts {
    let hidden: Vec<f32> = (0..4 * FEATURE_COUNT)
        .map(|i| ((i % 7) as f32 - 3.0) * 0.1)
        .collect();
    let out: Vec<f32> = (0..OUTPUT_COUNT * 4)
        .map(|i| (i % 5) as f32 * 0.2)
        .collect();
    NetworkParts {
        input_mean: vec![0.0; FEATURE_COUNT],
        input_std: vec![1.0; FEATURE_COUNT],
        layers: vec![(hidden, vec![0.1; 4]), (out, vec![0.0; OUTPUT_COUNT])],
        output_mean: vec![0.0; OUTPUT_COUNT],
        output_std: vec![1.0; OUTPUT_COUNT],
        training: "test".into(),
        bike: crate::bike::BikeParams::default().identity(),
    }
}

#[test]
fn the_network_decides_every_entry_but_the_drives() {
    let entries = output_entries();
    assert_eq!(entries.len() + DRIVE_ENTRIES.len(), CONTROL_DIM);
    assert!(entries.iter().all(|e| !DRIVE_ENTRIES.contains(e)));
    assert!(entries.windows(2).all(|w| w[0] < w[1]));
}

#[test]
fn a_linear_layer_computes_what_its_weights_say() {
    let network = PolicyNetwork::new(pass_through()).unwrap();
    let mut features = [0.0; FEATURE_COUNT];
    features[0] = 5.0; // normalised (5 − 1) / 2 = 2; + 0.5 bias = 2.5; −1 + 2.5·3 = 6.5
    let out = network.evaluate(&features).unwrap();
    assert!((out[0] - 6.5).abs() < 1e-6, "{}", out[0]);
    // Feature 0 normalises to −0.5; + 0.5 = 0; −1 + 0 = −1.
    assert!((out[1] + 1.0).abs() < 1e-6, "{}", out[1]);
}

#[test]
fn hidden_layers_squash_with_tanh() {
    let parts = two_layers();
    let network = PolicyNetwork::new(parts.clone()).unwrap();
    let features: [f64; FEATURE_COUNT] = std::array::from_fn(|i| (i as f64 * 0.37).sin());
    let (hidden, out) = (&parts.layers[0], &parts.layers[1]);
    let h: Vec<f32> = (0..4)
        .map(|j| {
            let row = &hidden.0[j * FEATURE_COUNT..(j + 1) * FEATURE_COUNT];
            let sum: f32 = row.iter().zip(&features).map(|(w, x)| w * *x as f32).sum();
            (sum + hidden.1[j]).tanh()
        })
        .collect();
    let expected: f32 = (0..4).map(|j| out.0[2 * 4 + j] * h[j]).sum();
    let found = network.evaluate(&features).unwrap()[2];
    assert!(
        (found - f64::from(expected)).abs() < 1e-6,
        "{found} vs {expected}"
    );
}

#[test]
fn a_model_reads_back_as_it_was_written() {
    let network = PolicyNetwork::new(two_layers()).unwrap();
    let again = PolicyNetwork::parse(&network.to_bytes()).unwrap();
    assert_eq!(again.parts(), network.parts());
    let features = [0.3; FEATURE_COUNT];
    assert_eq!(again.evaluate(&features), network.evaluate(&features));
}

#[test]
fn a_state_with_a_non_finite_number_is_not_evaluated() {
    let network = PolicyNetwork::new(pass_through()).unwrap();
    let mut features = [0.0; FEATURE_COUNT];
    features[7] = f64::NAN;
    assert_eq!(network.evaluate(&features), Err(NonFiniteFeature(7)));
    features[7] = 0.0;
    features[3] = f64::INFINITY;
    assert_eq!(network.evaluate(&features), Err(NonFiniteFeature(3)));
}

#[test]
fn inputs_far_outside_the_training_data_are_held_to_its_edge() {
    let network = PolicyNetwork::new(pass_through()).unwrap();
    let mut far = [0.0; FEATURE_COUNT];
    far[0] = 1e30;
    let mut edge = [0.0; FEATURE_COUNT];
    edge[0] = 1.0 + 8.0 * 2.0;
    assert_eq!(network.evaluate(&far), network.evaluate(&edge));
}

#[test]
fn broken_parts_are_refused() {
    let mut short = pass_through();
    short.input_std.pop();
    let mut zero_spread = pass_through();
    zero_spread.output_std[0] = 0.0;
    let mut nan_weight = two_layers();
    nan_weight.layers[1].0[3] = f32::NAN;
    let mut wrong_width = two_layers();
    wrong_width.layers[1].0.pop();
    let mut no_layers = pass_through();
    no_layers.layers.clear();
    for parts in [short, zero_spread, nan_weight, wrong_width, no_layers] {
        assert!(matches!(
            PolicyNetwork::new(parts),
            Err(ModelError::NotAModel(..))
        ));
    }
}

/// A written model with one metadata entry replaced.
fn with_metadata(key: &str, value: &str) -> Vec<u8> {
    let bytes = PolicyNetwork::new(pass_through()).unwrap().to_bytes();
    let file = SafeTensors::deserialize(&bytes).unwrap();
    let (_, header) = SafeTensors::read_metadata(&bytes).unwrap();
    let mut meta: HashMap<String, String> = header.metadata().clone().unwrap();
    meta.insert(key.into(), value.into());
    let tensors: Vec<(String, TensorView<'_>)> = file.tensors();
    safetensors::serialize(tensors, Some(meta)).unwrap()
}

#[test]
fn a_model_for_other_features_or_another_format_is_refused() {
    let message = |bytes: &[u8]| match PolicyNetwork::parse(bytes) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("accepted"),
    };
    let version = message(&with_metadata("features_version", "0"));
    assert!(version.contains("features_version is '0'"), "{version}");
    assert!(version.contains("make train"), "{version}");
    let names = message(&with_metadata("features", "speed,lean"));
    assert!(names.contains("does not fit this build"), "{names}");
    let format = message(&with_metadata("format", "something-else"));
    assert!(format.contains("not a Counter-Steer policy"), "{format}");
    let layers = message(&with_metadata("layers", "two"));
    assert!(layers.contains("how many layers"), "{layers}");
}

#[test]
fn a_corrupt_or_missing_file_is_refused_with_a_reason() {
    let bytes = PolicyNetwork::new(pass_through()).unwrap().to_bytes();
    for broken in [&bytes[..bytes.len() / 2], &b"not a model"[..], &[][..]] {
        assert!(matches!(
            PolicyNetwork::parse(broken),
            Err(ModelError::NotAModel(..))
        ));
    }
    let mut flipped = bytes.clone();
    flipped[9] ^= 0x55; // inside the JSON header
    assert!(PolicyNetwork::parse(&flipped).is_err());
    let missing = std::path::Path::new("/nonexistent/counter-steer/policy.safetensors");
    let error = PolicyNetwork::load(missing).err().unwrap().to_string();
    assert!(
        error.contains("cannot be read") && error.contains("policy.safetensors"),
        "{error}"
    );
    // Float64 where float32 belongs.
    let file = SafeTensors::deserialize(&bytes).unwrap();
    let wide = vec![0u8; FEATURE_COUNT * 8];
    let mut tensors: Vec<(String, TensorView<'_>)> = file
        .tensors()
        .into_iter()
        .filter(|(name, _)| name != "input.mean")
        .collect();
    tensors.push((
        "input.mean".into(),
        TensorView::new(Dtype::F64, vec![FEATURE_COUNT], &wide).unwrap(),
    ));
    let (_, header) = SafeTensors::read_metadata(&bytes).unwrap();
    let retyped = safetensors::serialize(tensors, header.metadata().clone()).unwrap();
    let error = PolicyNetwork::parse(&retyped).err().unwrap().to_string();
    assert!(error.contains("not float32"), "{error}");
}

#[test]
fn the_features_of_a_bike_at_rest_read_as_expected() {
    use std::sync::Arc;

    use glam::{DQuat, DVec3};

    use crate::bike::{DriveInput, Placement, RiderPosition};
    use crate::simulation::{Simulation, SimulationConfig};
    use crate::terrain::Terrain;

    let spawn = Placement {
        position: DVec3::new(0.0, 0.1, 0.0),
        rotation: DQuat::IDENTITY,
    };
    let mut sim = Simulation::new(
        SimulationConfig::default(),
        Arc::new(Terrain::flat()),
        spawn,
    );
    for _ in 0..30 {
        sim.step();
    }
    let drive = DriveInput {
        throttle: 0.5,
        brake: 0.0,
        max_speed: 4.0,
    };
    let goal = Goal {
        lean: 0.2,
        drive,
        rider: RiderPosition {
            forward: 0.5,
            right: 0.0,
        },
    };
    let (bike, world, up) = (sim.bike(), sim.world(), sim.up());
    let f = features(bike, world, &goal, up);
    let at = |name: &str| f[FEATURE_NAMES.iter().position(|n| *n == name).unwrap()];
    assert!(f.iter().all(|x| x.is_finite()));
    assert!(at("speed").abs() < 0.05 && at("lean").abs() < 0.05, "{f:?}");
    assert!(at("up_y") > 0.99, "upright on flat ground: {f:?}");
    assert_eq!(at("rear_touches") + at("front_touches"), 2.0);
    assert_eq!(
        (at("goal_lean"), at("throttle"), at("rider_forward")),
        (0.2, 0.5, 0.5)
    );
    assert!((at("goal_lean_error") - (0.2 - at("lean"))).abs() < 1e-12);
    assert!((at("speed_error") - (4.0 - at("speed"))).abs() < 1e-12);
    // The network's controls keep the drive's entries for the throttle.
    let network = PolicyNetwork::new(pass_through()).unwrap();
    let controls = network.controls(bike, world, &goal, up).unwrap();
    let mut expected = Controls::default();
    drive.apply(bike.params().wheel_radius, &mut expected);
    for entry in DRIVE_ENTRIES {
        assert_eq!(controls.get(entry), expected.get(entry));
    }
}

#[test]
fn the_committed_model_is_in_the_form_make_train_writes_it() {
    // Sorted header: a rerun of `make train` can be compared with it byte for byte.
    let bytes = std::fs::read(super::project_model(crate::bike::REFERENCE_BIKE))
        .expect("the committed model");
    assert!(
        super::sort_header(bytes.clone()) == bytes,
        "header not sorted"
    );
}

#[test]
fn a_model_says_which_bike_it_was_trained_on() {
    let reference = crate::bike::BikeParams::default();
    let policy = LoadedPolicy::parse(&PolicyNetwork::new(pass_through()).unwrap().to_bytes(), "m");
    assert_eq!(policy.other_bike(&reference), None);
    let other = crate::bike::BikeParams {
        wheelbase: 1.2,
        ..reference.clone()
    };
    let told = policy.other_bike(&other).expect("another bike is told");
    assert!(told.contains(&reference.identity()) && told.contains(&other.identity()));
    // A model written before bikes were recorded was trained on the reference bike.
    let older = LoadedPolicy::parse(&with_metadata("bike", ""), "older");
    assert_eq!(older.other_bike(&reference), None);
}

#[test]
fn a_bike_without_a_model_of_its_own_is_told_so() {
    let missing = super::project_policy("no_such_bike");
    let why = missing.problem().expect("no model");
    let path = super::model_path("no_such_bike");
    assert!(why.contains(&format!("{path} is missing")), "{why}");
    assert!(why.contains("make train BIKE="), "{why}");
    let reference = super::project_policy(crate::bike::REFERENCE_BIKE);
    assert!(reference.network().is_some(), "{:?}", reference.problem());
}

#[test]
fn a_policy_is_not_a_cost_to_go_nor_a_cost_to_go_a_policy() {
    let policy = PolicyNetwork::new(pass_through()).unwrap().to_bytes();
    let error = ValueNetwork::parse(&policy).err().unwrap().to_string();
    assert!(
        error.contains("not a Counter-Steer cost-to-go")
            && error.contains("its format is 'counter-steer-policy'"),
        "{error}"
    );
    let value = ValueNetwork::new(NetworkParts {
        input_mean: vec![0.0; VALUE_INPUT_COUNT],
        input_std: vec![1.0; VALUE_INPUT_COUNT],
        layers: vec![(vec![0.1; VALUE_INPUT_COUNT], vec![0.0])],
        output_mean: vec![0.0],
        output_std: vec![1.0],
        training: "by hand".into(),
        bike: crate::bike::BikeParams::default().identity(),
    })
    .unwrap();
    let error = PolicyNetwork::parse(&value.to_bytes())
        .err()
        .unwrap()
        .to_string();
    assert!(error.contains("not a Counter-Steer policy"), "{error}");
    let back = ValueNetwork::parse(&value.to_bytes()).unwrap();
    assert_eq!(back.parts(), value.parts());
    // A state it cannot read is reported, not answered.
    let mut features = [0.0; FEATURE_COUNT];
    features[2] = f64::NAN;
    assert_eq!(value.cost_to_go(&features, 0.6), Err(NonFiniteFeature(2)));
}
