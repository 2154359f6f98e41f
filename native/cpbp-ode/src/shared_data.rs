//! Collision data shared by every world of a level (trimesh and heightfield), built once.
//!
//! ODE reads trimesh vertices and indices from the caller's arrays without copying them,
//! so the arrays live here, next to the ODE handle, for as long as any world holds an
//! `Arc` to them. In an OU build collision reads them from several threads at once.

use crate::ffi;
use crate::runtime::ensure_thread_data;

/// Triangle mesh data: vertices and counter-clockwise triangles (seen from outside).
pub struct TriMeshData {
    pub(crate) id: ffi::dTriMeshDataID,
    vertices: Vec<[f64; 3]>,
    triangles: Vec<[u32; 3]>,
}

// SAFETY: after construction the data is only read (by collision), which ODE allows from
// several threads in an OU build; the arrays it points to are owned and never mutated.
unsafe impl Send for TriMeshData {}
// SAFETY: as above.
unsafe impl Sync for TriMeshData {}

impl TriMeshData {
    /// Builds mesh data. Indices must be below the vertex count (checked).
    pub fn new(vertices: Vec<[f64; 3]>, triangles: Vec<[u32; 3]>) -> Result<Self, String> {
        if triangles.is_empty() {
            return Err("a triangle mesh needs at least one triangle".into());
        }
        if let Some(bad) = triangles
            .iter()
            .flatten()
            .find(|&&i| i as usize >= vertices.len())
        {
            return Err(format!(
                "triangle index {bad} out of {} vertices",
                vertices.len()
            ));
        }
        ensure_thread_data();
        // SAFETY: the arrays are owned by the returned value, which outlives the data id
        // (destroyed in Drop); the strides match the element types.
        let id = unsafe {
            let id = ffi::dGeomTriMeshDataCreate();
            ffi::dGeomTriMeshDataBuildDouble(
                id,
                vertices.as_ptr().cast(),
                std::mem::size_of::<[f64; 3]>() as i32,
                vertices.len() as i32,
                triangles.as_ptr().cast(),
                (triangles.len() * 3) as i32,
                std::mem::size_of::<[u32; 3]>() as i32,
            );
            id
        };
        Ok(Self {
            id,
            vertices,
            triangles,
        })
    }

    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }
}

impl Drop for TriMeshData {
    fn drop(&mut self) {
        // SAFETY: every geom using this data holds an Arc to it, so none is left.
        unsafe { ffi::dGeomTriMeshDataDestroy(self.id) };
    }
}

/// Regular-grid height field, Y up, centred on its origin; ODE copies the heights.
pub struct HeightFieldData {
    pub(crate) id: ffi::dHeightfieldDataID,
}

// SAFETY: read-only after construction, as for TriMeshData.
unsafe impl Send for HeightFieldData {}
// SAFETY: as above.
unsafe impl Sync for HeightFieldData {}

impl HeightFieldData {
    /// `heights[x + z * width_samples]`, samples `spacing` apart along x and z.
    pub fn new(
        heights: &[f64],
        width_samples: usize,
        depth_samples: usize,
        spacing: [f64; 2],
    ) -> Result<Self, String> {
        if width_samples < 2 || depth_samples < 2 {
            return Err(format!(
                "a height map needs 2×2 samples or more, got {width_samples}×{depth_samples}"
            ));
        }
        if heights.len() != width_samples * depth_samples {
            return Err(format!(
                "a {width_samples}×{depth_samples} height map needs {} heights, got {}",
                width_samples * depth_samples,
                heights.len()
            ));
        }
        let lowest = heights.iter().cloned().fold(f64::INFINITY, f64::min);
        let highest = heights.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        ensure_thread_data();
        // SAFETY: ODE copies the heights (copy flag 1); the id is destroyed in Drop.
        let id = unsafe {
            let id = ffi::dGeomHeightfieldDataCreate();
            ffi::dGeomHeightfieldDataBuildDouble(
                id,
                heights.as_ptr(),
                1,
                spacing[0] * (width_samples - 1) as f64,
                spacing[1] * (depth_samples - 1) as f64,
                width_samples as i32,
                depth_samples as i32,
                1.0,
                0.0,
                1.0,
                0,
            );
            ffi::dGeomHeightfieldDataSetBounds(id, lowest, highest);
            id
        };
        Ok(Self { id })
    }
}

impl Drop for HeightFieldData {
    fn drop(&mut self) {
        // SAFETY: every geom using this data holds an Arc to it, so none is left.
        unsafe { ffi::dGeomHeightfieldDataDestroy(self.id) };
    }
}
