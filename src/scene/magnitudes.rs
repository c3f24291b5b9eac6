//! Bounds on the size of every number a scene gives, checked before anything else reads them: a
//! number far outside what a rock-engineering model can mean (1e300 Pa, a bolt spacing of
//! 1e-300 m, a coordinate of 1e19 m) is refused naming its field, rather than built into a model
//! whose arithmetic overflows, or whose geometry loses every digit, somewhere later.
//!
//! Three kinds of bound, each documented in `docs/scene-format.md` (Limits):
//! - every real number: zero, or between [`SMALLEST`] and [`LARGEST`] in size;
//! - every coordinate (the numbers under a field named in [`COORDINATE_FIELDS`]): within
//!   [`MAX_COORDINATE`] of the origin;
//! - the stress the scene puts into the rock: the in-situ stress anywhere in the region's box, and
//!   the weight of the region's height of its densest material, within [`MAX_STRESS`].

use adit_meshing::Polygon;
use serde_json::Value;

use super::limits::beyond;
use super::validate::{Num, SceneError, invalid};
use super::{Scene, Shape};

/// The smallest size of a non-zero real number, and the largest: no SI quantity of a rock model
/// lies outside them, and within them products of a few fields stay finite and normal.
pub const SMALLEST: f64 = 1e-30;
pub const LARGEST: f64 = 1e30;

/// The farthest a coordinate may lie from the origin, m: 10 000 km. Within it a double keeps
/// positions to 2e-9 m, far below any merge tolerance.
pub const MAX_COORDINATE: f64 = 1e7;

/// The largest stress a scene may put into the rock, Pa (1 TPa: ten times the pressure at the
/// centre of the Earth's mantle).
pub const MAX_STRESS: f64 = 1e12;

/// The smallest excavation or inclusion (its radius, or a polygon's shortest edge), as a share
/// of the region's size: the cutter's merge tolerance follows the walls' shortest edges, and a
/// hole of 1e-18 of a 50 m model took 20 s to refuse as a crossing (1e-12 builds at once).
pub const MIN_FEATURE: f64 = 1e-6;

/// Fields whose numbers are coordinates, m.
pub const COORDINATE_FIELDS: [&str; 8] = [
    "polygon", "center", "origin", "from", "to", "at", "y_ref", "surface",
];

/// Refuse the first number of `scene` (its JSON) outside the bounds on every number and on
/// coordinates, naming its field as the scene's paths do (`bolts[0].out_of_plane_spacing`).
/// Integers (counts, seeds) are the typed fields' own to bound.
pub(super) fn check_numbers(scene: &Value) -> Result<(), SceneError> {
    walk(scene, &mut String::new(), false)
}

fn walk(v: &Value, path: &mut String, coordinate: bool) -> Result<(), SceneError> {
    match v {
        Value::Number(n) if n.is_f64() => {
            let x = n.as_f64().unwrap_or(f64::NAN);
            let size = x.abs();
            if !(x == 0.0 || (SMALLEST..=LARGEST).contains(&size)) {
                return Err(invalid(
                    path.clone(),
                    format!(
                        "{} is outside the sizes a scene's numbers may have (zero, or \
                         {SMALLEST:e} to {LARGEST:e})",
                        Num(x)
                    ),
                ));
            }
            within_coordinates(path, x, coordinate)
        }
        Value::Number(n) => within_coordinates(path, n.as_f64().unwrap_or(f64::NAN), coordinate),
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                let len = path.len();
                path.push_str(&format!("[{i}]"));
                walk(item, path, coordinate)?;
                path.truncate(len);
            }
            Ok(())
        }
        Value::Object(fields) => {
            for (key, item) in fields {
                let len = path.len();
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(key);
                walk(
                    item,
                    path,
                    coordinate || COORDINATE_FIELDS.contains(&key.as_str()),
                )?;
                path.truncate(len);
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// A coordinate `x` (m) at `path` within [`MAX_COORDINATE`] of the origin.
fn within_coordinates(path: &str, x: f64, coordinate: bool) -> Result<(), SceneError> {
    if coordinate && beyond(x.abs(), MAX_COORDINATE) {
        return Err(invalid(
            path,
            format!(
                "a coordinate of {} m lies beyond {MAX_COORDINATE:e} m of the origin: move the \
                 model's origin near it",
                Num(x)
            ),
        ));
    }
    Ok(())
}

impl Scene {
    /// Refuse an excavation or inclusion smaller than [`MIN_FEATURE`] of the region's size,
    /// naming its size field.
    pub(super) fn validate_feature_sizes(&self) -> Result<(), SceneError> {
        if self.region.polygon.len() < 3 {
            return Ok(()); // the meshing's to refuse, naming region.polygon
        }
        let least = MIN_FEATURE * Polygon::new(self.region.polygon.clone()).size();
        let shortest_edge = |v: &[[f64; 2]]| {
            (0..v.len())
                .map(|i| {
                    let (a, b) = (v[i], v[(i + 1) % v.len()]);
                    (b[0] - a[0]).hypot(b[1] - a[1])
                })
                .fold(f64::INFINITY, f64::min)
        };
        let holes = (self.excavations.iter().enumerate())
            .map(|(i, e)| (format!("excavations[{i}]"), e.shape("")))
            .chain(
                (self.inclusions.iter().enumerate())
                    .map(|(i, e)| (format!("inclusions[{i}]"), e.shape(""))),
            );
        for (path, shape) in holes {
            let (field, size) = match shape {
                Ok(Shape::Circle(c)) => ("circle.radius", c.radius),
                Ok(Shape::Horseshoe(h)) => ("horseshoe.radius", h.radius),
                Ok(Shape::Polygon(v)) => ("polygon", shortest_edge(v)),
                Err(_) => continue, // validated with its shape
            };
            if beyond(least, size) {
                return Err(invalid(
                    format!("{path}.{field}"),
                    format!(
                        "{} m is below {MIN_FEATURE:e} of the region's size ({} m): the cutter \
                         and the zoning cannot resolve it",
                        Num(size),
                        Num(least / MIN_FEATURE)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Refuse an in-situ stress that exceeds [`MAX_STRESS`] anywhere in the region's box (it is
    /// linear in y, so at the box's top or bottom), and gravity whose weight of the box's height
    /// of the densest material does.
    pub(super) fn validate_stress_magnitudes(&self) -> Result<(), SceneError> {
        if self.region.polygon.len() < 3 {
            return Ok(()); // the meshing's to refuse, naming region.polygon
        }
        let (lo, hi) = Polygon::new(self.region.polygon.clone()).bounds();
        let s = &self.in_situ;
        let g = &s.gradient;
        for y in [lo[1], hi[1]] {
            let dy = y - s.y_ref;
            let components = [
                ("sxx", s.sxx + g.sxx * dy),
                ("syy", s.syy + g.syy * dy),
                ("sxy", s.sxy),
                ("szz", s.szz.unwrap_or(0.0) + g.szz * dy),
            ];
            for (name, value) in components {
                if beyond(value.abs(), MAX_STRESS) {
                    return Err(invalid(
                        format!("in_situ.{name}"),
                        format!(
                            "reaches {} Pa at y = {} m (from its value at y_ref = {} m and its \
                             gradient), beyond the {MAX_STRESS:e} Pa a scene may put into rock",
                            Num(value),
                            Num(y),
                            Num(s.y_ref)
                        ),
                    ));
                }
            }
        }
        let densest = self
            .materials
            .values()
            .map(|m| m.density)
            .fold(0.0, f64::max);
        let span = (hi[1] - lo[1]).max(hi[0] - lo[0]);
        let gravities = std::iter::once(("gravity".to_string(), self.gravity)).chain(
            (self.stages.iter().enumerate())
                .filter_map(|(i, st)| Some((format!("stages[{i}].gravity"), st.gravity?))),
        );
        for (path, gravity) in gravities {
            let g = gravity[0].hypot(gravity[1]);
            let weight = densest * g * span;
            if beyond(weight, MAX_STRESS) {
                return Err(invalid(
                    path,
                    format!(
                        "{} m/s² on rock of {} kg/m³ over the region's {} m weighs {} Pa, beyond \
                         the {MAX_STRESS:e} Pa a scene may put into rock",
                        Num(g),
                        Num(densest),
                        Num(span),
                        Num(weight)
                    ),
                ));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(json: &str) -> Option<String> {
        let v: Value = serde_json::from_str(json).unwrap();
        check_numbers(&v).err().map(|e| e.to_string())
    }

    #[test]
    fn numbers_outside_the_sizes_are_named() {
        let e = refused(r#"{"bolts": [{"out_of_plane_spacing": 1e-300}]}"#).unwrap();
        assert!(
            e.starts_with("bolts[0].out_of_plane_spacing: 1.0000e-300"),
            "{e}"
        );
        let e = refused(r#"{"materials": {"rock": {"young": -1e31}}}"#).unwrap();
        assert!(e.starts_with("materials.rock.young:"), "{e}");
        assert!(refused(r#"{"a": 5e-324}"#).is_some(), "a subnormal");
        assert!(refused(r#"{"a": [0, -0.0, 1e-30, 1e30, 2.5e10]}"#).is_none());
        // Integers (counts, seeds) are the typed fields' to bound.
        assert!(refused(r#"{"seed": 18446744073709551615}"#).is_none());
    }

    #[test]
    fn coordinates_beyond_the_bound_are_named() {
        let e = refused(r#"{"joint_sets": [{"origin": [1e8, 0]}]}"#).unwrap();
        assert!(e.starts_with("joint_sets[0].origin[0]:"), "{e}");
        let e = refused(r#"{"in_situ": {"y_ref": 18000000000000000000}}"#).unwrap();
        assert!(e.starts_with("in_situ.y_ref:"), "{e}");
        assert!(refused(r#"{"region": {"polygon": [[-9e6, 0], [9e6, 1]]}}"#).is_none());
        // Not a coordinate: a large stress.
        assert!(refused(r#"{"in_situ": {"sxx": 1e8}}"#).is_none());
    }
}
