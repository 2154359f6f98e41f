//! A world's feet (`crate::feet`): adding them, putting them down and lifting them, their
//! legs, and their part of a snapshot.

use super::{GeomId, World};
use crate::feet::{Foot, FootSurface, Leg};
use crate::{ffi, BodyId, DVec3, Vec3};

impl World {
    /// Adds a foot: a sphere of `radius` on `body`, standing on the terrain as `surface`
    /// says (`FootSurface`), up (not colliding) until `set_foot_down`.
    pub fn add_foot(&mut self, radius: f64, body: BodyId, surface: FootSurface) -> GeomId {
        let geom = self.add_sphere(radius, Some(body));
        let id = self.geoms[geom.0];
        // SAFETY: the geom belongs to this world.
        unsafe { ffi::dGeomDisable(id) };
        self.feet.push(Foot {
            geom: id,
            surface,
            touching: false,
            leg: None,
        });
        geom
    }

    /// Gives a foot a leg: its sole built at `sole` on its body (the body's frame) and
    /// moved along the unit `direction` by `set_foot_extension`, from 0 now. Panics if
    /// `foot` is not a foot of this world.
    pub fn set_foot_leg(&mut self, foot: GeomId, sole: DVec3, direction: DVec3) {
        let leg = Leg {
            sole,
            direction: direction.normalize(),
            extension: 0.0,
        };
        self.foot_mut(foot).leg = Some(leg);
        self.place_sole(foot);
    }

    /// Stretches a foot's leg to `extension` metres from where its sole was built (a foot
    /// without a leg is left where it is).
    pub fn set_foot_extension(&mut self, foot: GeomId, extension: f64) {
        if let Some(leg) = self.foot_mut(foot).leg.as_mut() {
            leg.extension = extension;
            self.place_sole(foot);
        }
    }

    /// Turns the way a foot's leg stretches to the unit `direction` in its body's frame,
    /// moving the sole with it (a foot without a leg is left where it is).
    pub fn set_foot_leg_direction(&mut self, foot: GeomId, direction: DVec3) {
        if let Some(leg) = self.foot_mut(foot).leg.as_mut() {
            leg.direction = direction.normalize();
            self.place_sole(foot);
        }
    }

    /// Where a leg's sole sits on its body now (its body's frame): where it was built,
    /// moved along the leg by its stretch; none for a foot without a leg.
    pub fn foot_sole(&self, foot: GeomId) -> Option<DVec3> {
        self.foot(foot).leg.map(|leg| leg.sole_offset())
    }

    /// The way a foot's leg stretches now (a unit vector in its body's frame; none for a
    /// foot without a leg).
    pub fn foot_leg_direction(&self, foot: GeomId) -> Option<DVec3> {
        self.foot(foot).leg.map(|leg| leg.direction)
    }

    /// How far a foot's leg is stretched (0 without a leg).
    pub fn foot_extension(&self, foot: GeomId) -> f64 {
        self.foot(foot).leg.map_or(0.0, |leg| leg.extension)
    }

    /// Puts a foot down (it collides with the terrain from the next step) or lifts it.
    /// Panics if `foot` is not a foot of this world.
    pub fn set_foot_down(&mut self, foot: GeomId, down: bool) {
        set_enabled(self.foot(foot).geom, down);
    }

    /// Whether a foot is down (see `set_foot_down`).
    pub fn is_foot_down(&self, foot: GeomId) -> bool {
        // SAFETY: the geom belongs to this world.
        unsafe { ffi::dGeomIsEnabled(self.foot(foot).geom) != 0 }
    }

    /// Whether a foot stood on the terrain in the last step.
    pub fn foot_touches_ground(&self, foot: GeomId) -> bool {
        self.foot(foot).touching
    }

    /// The feet's part of a snapshot: per foot, whether it is down, its leg's stretch and
    /// the way it stretches.
    pub(super) fn feet_state(&self) -> (Vec<bool>, Vec<f64>, Vec<Vec3>) {
        let down = self
            .feet
            .iter()
            // SAFETY: the geom belongs to this world.
            .map(|f| unsafe { ffi::dGeomIsEnabled(f.geom) != 0 })
            .collect();
        let extension = self
            .feet
            .iter()
            .map(|f| f.leg.map_or(0.0, |leg| leg.extension))
            .collect();
        let direction = self
            .feet
            .iter()
            .map(|f| f.leg.map_or([0.0; 3], |leg| leg.direction.to_array()))
            .collect();
        (down, extension, direction)
    }

    /// Puts the feet back as a snapshot has them (the caller checked the lengths).
    pub(super) fn restore_feet(
        &mut self,
        touching: &[bool],
        down: &[bool],
        extension: &[f64],
        direction: &[Vec3],
    ) {
        for (i, foot) in self.feet.iter_mut().enumerate() {
            foot.touching = touching[i];
            set_enabled(foot.geom, down[i]);
            if let Some(leg) = foot.leg.as_mut() {
                leg.extension = extension[i];
                leg.direction = DVec3::from_array(direction[i]);
                let at = leg.sole_offset();
                // SAFETY: the geom belongs to this world and is attached to a body.
                unsafe { ffi::dGeomSetOffsetPosition(foot.geom, at.x, at.y, at.z) };
            }
        }
    }

    fn place_sole(&mut self, foot: GeomId) {
        let f = self.foot(foot);
        if let Some(leg) = f.leg {
            let at = leg.sole_offset();
            // SAFETY: the geom belongs to this world and is attached to a body.
            unsafe { ffi::dGeomSetOffsetPosition(f.geom, at.x, at.y, at.z) };
        }
    }

    fn foot(&self, foot: GeomId) -> &Foot {
        let id = self.geoms[foot.0];
        self.feet
            .iter()
            .find(|f| f.geom == id)
            .expect("add_foot made this geom")
    }

    fn foot_mut(&mut self, foot: GeomId) -> &mut Foot {
        let id = self.geoms[foot.0];
        self.feet
            .iter_mut()
            .find(|f| f.geom == id)
            .expect("add_foot made this geom")
    }
}

fn set_enabled(geom: ffi::dGeomID, enabled: bool) {
    // SAFETY: callers pass a geom of their world.
    unsafe {
        if enabled {
            ffi::dGeomEnable(geom);
        } else {
            ffi::dGeomDisable(geom);
        }
    }
}
