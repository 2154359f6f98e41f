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
}
