//! safetensors files whose bytes depend on their contents alone. The format's writer
//! keeps the metadata in a `HashMap`, so the header's key order (and with it the file's
//! bytes) changes from run to run; sorting it lets a rerun of `make train` be compared
//! with `cmp`, shard by shard and model against model.

use std::collections::HashMap;

use safetensors::tensor::View;
use safetensors::SafeTensorError;

/// `safetensors::serialize`, with the header's keys sorted at every level.
pub fn serialize_sorted<S, V, I>(
    data: I,
    metadata: HashMap<String, String>,
) -> Result<Vec<u8>, SafeTensorError>
where
    S: AsRef<str> + Ord + std::fmt::Display,
    V: View,
    I: IntoIterator<Item = (S, V)>,
{
    let bytes = safetensors::serialize(data, Some(metadata))?;
    Ok(sort_header(bytes))
}

/// The same file with its JSON header's keys in order; anything that is not a
/// well-formed header is returned as it came.
pub fn sort_header(mut bytes: Vec<u8>) -> Vec<u8> {
    let Some(length) = bytes
        .get(..8)
        .map(|b| u64::from_le_bytes(b.try_into().unwrap()))
    else {
        return bytes;
    };
    let Some(end) = usize::try_from(length).ok().and_then(|n| n.checked_add(8)) else {
        return bytes;
    };
    let Some(Ok(mut header)) = bytes
        .get(8..end)
        .map(serde_json::from_slice::<serde_json::Value>)
    else {
        return bytes;
    };
    sort_keys(&mut header);
    let sorted = serde_json::to_vec(&header).expect("a parsed header serialises");
    // The same pairs in another order have the same length; the format pads with spaces.
    if sorted.len() <= end - 8 {
        bytes[8..8 + sorted.len()].copy_from_slice(&sorted);
        bytes[8 + sorted.len()..end].fill(b' ');
    }
    bytes
}

fn sort_keys(value: &mut serde_json::Value) {
    if let serde_json::Value::Object(map) = value {
        map.sort_keys();
        map.values_mut().for_each(sort_keys);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use safetensors::tensor::TensorView;
    use safetensors::{Dtype, SafeTensors};

    #[test]
    fn a_file_is_the_same_bytes_whatever_order_its_metadata_was_kept_in() {
        let data = [0u8; 16];
        let file = |keys: &[&str]| {
            let view = TensorView::new(Dtype::F32, vec![2, 2], &data).unwrap();
            let meta = keys
                .iter()
                .map(|k| (k.to_string(), format!("value of {k}")));
            serialize_sorted([("weights", view)], meta.collect()).unwrap()
        };
        let keys = [
            "format", "seed", "features", "a", "zeta", "outputs", "layers",
        ];
        let first = file(&keys);
        let mut reversed = keys;
        reversed.reverse();
        // HashMaps of the same keys iterate in different orders from one map to the next.
        for _ in 0..8 {
            assert_eq!(file(&reversed), first);
        }
        let read = SafeTensors::deserialize(&first).unwrap();
        assert_eq!(read.tensor("weights").unwrap().shape(), &[2, 2]);
        let (_, header) = SafeTensors::read_metadata(&first).unwrap();
        assert_eq!(header.metadata().as_ref().unwrap()["zeta"], "value of zeta");
        assert_eq!(sort_header(b"not a file".to_vec()), b"not a file");
    }
}
