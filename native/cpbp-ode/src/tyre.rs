//! A torus tyre on a sphere geom (see `World::add_tyre`): where the torus touches what
//! ODE found the bounding sphere touching.
//!
//! ODE reports two kinds of contact for a sphere. On a face (a plane, a mesh triangle, a
//! log's side) the contact lies at the sphere's deepest point along the face's normal;
//! there the torus touches the same surface a little way round, in the wheel's plane (a
//! leaning wheel touches under its tread, not under its centre). At an edge or corner of a
//! mesh ODE reports the edge point itself, once per face meeting there, each with that
//! face's normal: a kerb's edge comes with the kerb's top normal and its front normal. The
//! surface argument would put those contacts under the wheel's centre and in front of
//! it, on surfaces that are not there, and a wheel could never climb the kerb. There the
//! torus touches the edge point itself, along the line from the point to the tube.

/// Above this distance (m) across the normal between ODE's contact point and the sphere's
/// deepest point, the contact is an edge or corner, not a face.
const FACE_TOLERANCE: f64 = 0.005;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tyre {
    pub(crate) radius: f64,
    pub(crate) crown: f64,
    /// Whether its contacts' friction acts along and across the wheel (`rolling_direction`)
    /// rather than along the two axes ODE derives from the contact normal alone.
    pub(crate) friction_follows_wheel: bool,
}

/// Where a torus touches: the point, the normal from the ground towards the wheel, and
/// how deep it reaches in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TyreContact {
    pub(crate) position: [f64; 3],
    pub(crate) normal: [f64; 3],
    pub(crate) depth: f64,
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn add(a: [f64; 3], b: [f64; 3], k: f64) -> [f64; 3] {
    [a[0] + b[0] * k, a[1] + b[1] * k, a[2] + b[2] * k]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The direction a wheel with this `axle` rolls over ground with this contact `normal`: in
/// the ground's plane and square to the axle. `None` when the wheel lies flat (its axle
/// along the normal), where no direction is the wheel's own.
///
/// ODE's friction is a pyramid bounded along two directions: left to itself it takes them
/// from the normal alone, so on level ground they are fixed world axes and a tyre heading
/// diagonally to them grips up to √2 times harder than one heading along one. Given this
/// direction (`dContactFDir1`), the bounds are the tyre's own, along it and across it, and
/// grip is the same at every heading.
pub(crate) fn rolling_direction(axle: [f64; 3], normal: [f64; 3]) -> Option<[f64; 3]> {
    let along = cross(axle, normal);
    let length = dot(along, along).sqrt();
    (length > 1e-6).then(|| add([0.0; 3], along, 1.0 / length))
}

impl Tyre {
    /// The torus contact for a contact ODE found for the bounding sphere: `centre` and
    /// `axle` of the wheel, `normal` from the ground towards the wheel, the sphere's
    /// penetration `depth` and ODE's contact `position`. `None` when the torus does not
    /// reach the ground there.
    pub(crate) fn contact(
        &self,
        centre: [f64; 3],
        axle: [f64; 3],
        normal: [f64; 3],
        depth: f64,
        position: [f64; 3],
    ) -> Option<TyreContact> {
        let deepest = add(centre, normal, -self.radius);
        let off = add(position, deepest, -1.0);
        let across = add(off, normal, -dot(off, normal));
        if dot(across, across).sqrt() > FACE_TOLERANCE {
            if let Some(touch) = self.at_point(centre, axle, position) {
                return Some(touch);
            }
        }
        self.on_face(centre, axle, normal, depth)
            .map(|(position, depth)| TyreContact {
                position,
                normal,
                depth,
            })
    }

    /// On a face: the plane through the sphere's deepest point, raised by the
    /// penetration, and the torus's lowest point towards it within the wheel's plane.
    fn on_face(
        &self,
        centre: [f64; 3],
        axle: [f64; 3],
        normal: [f64; 3],
        depth: f64,
    ) -> Option<([f64; 3], f64)> {
        let surface = add(add(centre, normal, -self.radius), normal, depth);
        // Towards the ground within the wheel's plane.
        let down = add(
            [-normal[0], -normal[1], -normal[2]],
            axle,
            dot(normal, axle),
        );
        let length = dot(down, down).sqrt();
        let tube = if length < 1e-9 {
            centre // lying flat: the tube circle is level, use the centre
        } else {
            add(centre, down, (self.radius - self.crown) / length)
        };
        let height = dot(add(tube, surface, -1.0), normal);
        let torus_depth = self.crown - height;
        (torus_depth > 0.0).then(|| (add(tube, normal, -self.crown), torus_depth))
    }

    /// At an edge or corner `point`: the nearest point of the tube's centre circle, and
    /// the tube's surface reaching past the point by the crown less that distance.
    fn at_point(&self, centre: [f64; 3], axle: [f64; 3], point: [f64; 3]) -> Option<TyreContact> {
        let from_centre = add(point, centre, -1.0);
        let in_plane = add(from_centre, axle, -dot(from_centre, axle));
        let length = dot(in_plane, in_plane).sqrt();
        if length < 1e-9 {
            return None; // on the axle's line: the face reasoning covers it
        }
        let tube = add(centre, in_plane, (self.radius - self.crown) / length);
        let towards_tube = add(tube, point, -1.0);
        let distance = dot(towards_tube, towards_tube).sqrt();
        let depth = self.crown - distance;
        (depth > 0.0 && distance > 1e-9).then(|| TyreContact {
            position: point,
            normal: add([0.0; 3], towards_tube, 1.0 / distance),
            depth,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A face contact as ODE reports it: at the sphere's deepest point along the normal.
    fn on_plane(
        tyre: &Tyre,
        centre: [f64; 3],
        axle: [f64; 3],
        depth: f64,
    ) -> Option<([f64; 3], f64)> {
        let normal = [0.0, 1.0, 0.0];
        let deepest = add(centre, normal, -tyre.radius);
        tyre.contact(centre, axle, normal, depth, deepest)
            .map(|touch| (touch.position, touch.depth))
    }

    #[test]
    fn an_upright_tyre_touches_like_a_sphere() {
        let tyre = Tyre {
            radius: 0.3,
            crown: 0.06,
            friction_follows_wheel: false,
        };
        let (pos, depth) = on_plane(&tyre, [0.0, 0.29, 0.0], [0.0, 0.0, 1.0], 0.01).unwrap();
        assert!((depth - 0.01).abs() < 1e-12);
        assert!((pos[1] - (-0.01)).abs() < 1e-12 && pos[2].abs() < 1e-12);
    }

    #[test]
    fn a_leaning_tyre_touches_in_its_own_plane() {
        // Leaning 30° to +z (top towards +z): the contact stays in the wheel's plane, so it
        // lies (r − ρ) sin 30° to the −z side of the centre, which leans out beyond it; a
        // sphere would touch right under the centre.
        let (r, crown, lean) = (0.3, 0.06, 30f64.to_radians());
        let tyre = Tyre {
            radius: r,
            crown,
            friction_follows_wheel: false,
        };
        let axle = [0.0, -lean.sin(), lean.cos()];
        let resting = (r - crown) * lean.cos() + crown;
        let centre = [0.0, resting - 0.002, 0.0];
        let sphere_depth = r - centre[1];
        let (pos, depth) = on_plane(&tyre, centre, axle, sphere_depth).unwrap();
        assert!((depth - 0.002).abs() < 1e-12, "depth {depth}");
        assert!(
            (pos[2] + (r - crown) * lean.sin()).abs() < 1e-12,
            "contact at z = {}",
            pos[2]
        );
    }

    #[test]
    fn a_tyre_lying_flat_rests_on_its_crown() {
        let tyre = Tyre {
            radius: 0.3,
            crown: 0.06,
            friction_follows_wheel: false,
        };
        let (_, depth) = on_plane(&tyre, [0.0, 0.05, 0.0], [0.0, 1.0, 0.0], 0.25).unwrap();
        assert!((depth - 0.01).abs() < 1e-12);
        assert_eq!(
            on_plane(&tyre, [0.0, 0.07, 0.0], [0.0, 1.0, 0.0], 0.23),
            None
        );
    }

    #[test]
    fn at_a_kerbs_edge_the_tyre_touches_the_edge_whatever_face_odes_normal_is() {
        // A 0.12 m kerb whose edge is 0.233 m ahead of and 0.18 m below the centre of an
        // upright wheel: 0.294 m away, 0.006 m inside the 0.30 m tyre. ODE reports the edge
        // twice, with the kerb top's normal and with its front's.
        let tyre = Tyre {
            radius: 0.3,
            crown: 0.06,
            friction_follows_wheel: false,
        };
        let (centre, axle) = ([0.0, 0.3, 0.0], [0.0, 0.0, 1.0]);
        let edge = [0.233, 0.12, 0.0];
        let reach = ((0.233f64).powi(2) + (0.18f64).powi(2)).sqrt();
        for face in [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]] {
            let touch = tyre.contact(centre, axle, face, 0.3 - reach, edge).unwrap();
            assert_eq!(touch.position, edge);
            assert!((touch.depth - (0.3 - reach)).abs() < 1e-12, "{touch:?}");
            // From the edge towards the wheel's centre: back and up, so rolling into the
            // kerb lifts the wheel onto it.
            let n = touch.normal;
            assert!((n[0] + 0.233 / reach).abs() < 1e-12 && (n[1] - 0.18 / reach).abs() < 1e-12);
        }
        // An edge the tyre does not reach is no contact.
        assert!(tyre
            .contact(centre, axle, [0.0, 1.0, 0.0], 0.0, [0.31, 0.12, 0.0])
            .is_none());
    }

    #[test]
    fn a_wheel_rolls_square_to_its_axle_within_the_ground() {
        let up = [0.0, 1.0, 0.0];
        // Upright, axle along +z: rolls along ±x.
        let d = rolling_direction([0.0, 0.0, 1.0], up).unwrap();
        assert!((d[0].abs() - 1.0).abs() < 1e-12 && d[1].abs() < 1e-12 && d[2].abs() < 1e-12);
        // Heading 45° and leaning 40°: still level and square to the axle's level part.
        let (h, lean) = (45f64.to_radians(), 40f64.to_radians());
        let axle = [-h.sin() * lean.cos(), -lean.sin(), h.cos() * lean.cos()];
        let d = rolling_direction(axle, up).unwrap();
        assert!(d[1].abs() < 1e-12 && dot(d, axle).abs() < 1e-12);
        assert!((dot(d, d) - 1.0).abs() < 1e-12);
        // Lying flat: no direction of its own.
        assert_eq!(rolling_direction(up, up), None);
    }
}
