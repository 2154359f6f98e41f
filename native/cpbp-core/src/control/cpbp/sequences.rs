//! Control sequences as flat arrays of K control vectors of D values each.

/// Drops the first control vector (it was executed) and repeats the last one at the end,
/// so step k of the result is step k + 1 of the input. Whole vectors move, never single
/// values (shifting by one value misaligns every dimension: a bug of public ports).
pub fn shift_one_step(sequence: &mut [f64], dim: usize) {
    let len = sequence.len();
    if len <= dim {
        return;
    }
    sequence.copy_within(dim.., 0);
    let (head, tail) = sequence.split_at_mut(len - dim);
    tail.copy_from_slice(&head[len - 2 * dim..]);
}

/// Rebuilds each final particle's control sequence by following its parents back:
/// `parents[k][i]` is the parent (at step k − 1) of particle i at step k, and
/// `controls[k][i]` the control particle i applied at step k.
pub fn lineages(parents: &[Vec<usize>], controls: &[Vec<Vec<f64>>]) -> Vec<Vec<f64>> {
    let steps = controls.len();
    let count = controls.last().map_or(0, Vec::len);
    (0..count)
        .map(|last| {
            let mut indices = vec![0; steps];
            let mut i = last;
            for k in (0..steps).rev() {
                indices[k] = i;
                i = parents[k][i];
            }
            indices
                .iter()
                .enumerate()
                .flat_map(|(k, &i)| controls[k][i].iter().copied())
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shift_moves_whole_control_vectors() {
        // Three steps of 2-D controls: (1,2) (3,4) (5,6) → (3,4) (5,6) (5,6).
        let mut sequence = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        shift_one_step(&mut sequence, 2);
        assert_eq!(sequence, [3.0, 4.0, 5.0, 6.0, 5.0, 6.0]);
    }

    #[test]
    fn lineages_follow_parents_back() {
        // Step 0: particles 0, 1 applied [10], [11]. Step 1: both children of particle 1.
        let parents = vec![vec![0, 1], vec![1, 1]];
        let controls = vec![vec![vec![10.0], vec![11.0]], vec![vec![20.0], vec![21.0]]];
        assert_eq!(
            lineages(&parents, &controls),
            vec![vec![11.0, 20.0], vec![11.0, 21.0]]
        );
    }
}
