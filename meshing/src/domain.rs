//! A meshing domain: an outer region polygon with named edges and excavation holes, validated
//! before any triangulation (orientation fixed, self-intersections and misplaced holes rejected).

use crate::error::MeshError;
use crate::geometry::{Point, Polygon};
use crate::polygon_index::PolygonIndex;

/// An excavation (hole) in the region.
#[derive(Debug, Clone, PartialEq)]
pub struct Hole {
    /// Name used in messages and as the boundary part of the hole wall.
    pub name: String,
    pub polygon: Polygon,
}

/// Region polygon (counter-clockwise after validation) with holes (clockwise after validation).
#[derive(Debug, Clone, PartialEq)]
pub struct Domain {
    pub outer: Polygon,
    /// Name of each outer edge (edge i runs from vertex i to vertex i+1 of `outer` as given).
    pub outer_edge_names: Vec<String>,
    pub holes: Vec<Hole>,
}

fn check_polygon(shape: &str, poly: &Polygon) -> Result<(), MeshError> {
    if poly.len() < 3 {
        return Err(MeshError::Degenerate {
            shape: shape.into(),
            reason: format!("{} vertices, at least 3 needed", poly.len()),
        });
    }
    if poly.vertices.iter().flatten().any(|c| !c.is_finite()) {
        return Err(MeshError::Degenerate {
            shape: shape.into(),
            reason: "a coordinate is not finite".into(),
        });
    }
    let size = poly.size();
    for i in 0..poly.len() {
        let (a, b) = poly.edge(i);
        if crate::geometry::distance(a, b) <= 1e-9 * size {
            return Err(MeshError::Degenerate {
                shape: shape.into(),
                reason: format!("vertices {i} and {} coincide", (i + 1) % poly.len()),
            });
        }
    }
    if let Some((a, b)) = poly.self_intersection() {
        return Err(MeshError::SelfIntersecting {
            shape: shape.into(),
            a,
            b,
        });
    }
    if poly.signed_area().abs() <= 1e-12 * size * size {
        return Err(MeshError::Degenerate {
            shape: shape.into(),
            reason: "zero area".into(),
        });
    }
    Ok(())
}

impl Domain {
    /// Validate and normalise orientation. `outer_edge_names` must have one name per outer edge.
    pub fn new(
        outer: Polygon,
        outer_edge_names: Vec<String>,
        holes: Vec<Hole>,
    ) -> Result<Self, MeshError> {
        check_polygon("region", &outer)?;
        if outer_edge_names.len() != outer.len() {
            return Err(MeshError::Degenerate {
                shape: "region".into(),
                reason: format!(
                    "{} edge names for {} edges",
                    outer_edge_names.len(),
                    outer.len()
                ),
            });
        }
        let region = PolygonIndex::new(&outer, 0.0);
        for hole in &holes {
            check_polygon(&hole.name, &hole.polygon)?;
            if let Some(v) = hole
                .polygon
                .vertices
                .iter()
                .position(|&p| !region.contains(p))
            {
                let p: Point = hole.polygon.vertices[v];
                return Err(MeshError::HoleOutside {
                    shape: hole.name.clone(),
                    reason: format!("vertex {v} at ({}, {}) is outside the region", p[0], p[1]),
                });
            }
            if hole.polygon.touches(&outer) {
                return Err(MeshError::HoleOutside {
                    shape: hole.name.clone(),
                    reason: "its boundary crosses or touches the region boundary".into(),
                });
            }
        }
        for (i, a) in holes.iter().enumerate() {
            for b in &holes[i + 1..] {
                if a.polygon.touches(&b.polygon)
                    || a.polygon.contains(b.polygon.vertices[0])
                    || b.polygon.contains(a.polygon.vertices[0])
                {
                    return Err(MeshError::HolesOverlap {
                        a: a.name.clone(),
                        b: b.name.clone(),
                    });
                }
            }
        }
        let mut outer = outer;
        let mut outer_edge_names = outer_edge_names;
        if outer.signed_area() < 0.0 {
            // Reverse the vertex order; edge i (v_i → v_i+1) becomes edge n−2−i, the last stays last.
            outer.vertices.reverse();
            let n = outer_edge_names.len();
            let last = outer_edge_names.pop().expect("n >= 3");
            outer_edge_names.reverse();
            outer_edge_names.push(last);
            debug_assert_eq!(outer_edge_names.len(), n);
        }
        let holes = holes
            .into_iter()
            .map(|mut h| {
                if h.polygon.signed_area() > 0.0 {
                    h.polygon.vertices.reverse();
                }
                h
            })
            .collect();
        Ok(Domain {
            outer,
            outer_edge_names,
            holes,
        })
    }

    /// Net area of the domain (region minus holes), m².
    pub fn area(&self) -> f64 {
        self.outer.signed_area()
            + self
                .holes
                .iter()
                .map(|h| h.polygon.signed_area())
                .sum::<f64>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(h: f64) -> Polygon {
        Polygon::new(vec![[-h, -h], [h, -h], [h, h], [-h, h]])
    }

    fn names(n: usize) -> Vec<String> {
        (0..n).map(|i| format!("e{i}")).collect()
    }

    #[test]
    fn clockwise_region_is_reversed_keeping_edge_names() {
        let cw = Polygon::new(vec![[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]);
        let d = Domain::new(
            cw,
            vec!["left".into(), "top".into(), "right".into(), "bottom".into()],
            vec![],
        )
        .unwrap();
        assert!(d.outer.signed_area() > 0.0);
        for i in 0..4 {
            let (a, b) = d.outer.edge(i);
            let name = &d.outer_edge_names[i];
            let expect = match name.as_str() {
                "left" => a[0] == 0.0 && b[0] == 0.0,
                "top" => a[1] == 1.0 && b[1] == 1.0,
                "right" => a[0] == 1.0 && b[0] == 1.0,
                "bottom" => a[1] == 0.0 && b[1] == 0.0,
                _ => false,
            };
            assert!(expect, "edge {i} named {name} runs {a:?}→{b:?}");
        }
    }

    #[test]
    fn hole_outside_region_is_rejected() {
        let hole = Hole {
            name: "tunnel".into(),
            polygon: Polygon::circle([30.0, 0.0], 1.0, 16),
        };
        let err = Domain::new(square(20.0), names(4), vec![hole]).unwrap_err();
        assert!(
            matches!(err, MeshError::HoleOutside { ref shape, .. } if shape == "tunnel"),
            "{err}"
        );
    }

    #[test]
    fn hole_crossing_region_is_rejected() {
        let hole = Hole {
            name: "adit".into(),
            polygon: Polygon::circle([19.5, 0.0], 1.0, 16),
        };
        assert!(Domain::new(square(20.0), names(4), vec![hole]).is_err());
    }

    #[test]
    fn overlapping_holes_are_rejected() {
        let a = Hole {
            name: "a".into(),
            polygon: Polygon::circle([0.0, 0.0], 1.0, 16),
        };
        let b = Hole {
            name: "b".into(),
            polygon: Polygon::circle([1.5, 0.0], 1.0, 16),
        };
        let err = Domain::new(square(20.0), names(4), vec![a, b]).unwrap_err();
        assert_eq!(
            err,
            MeshError::HolesOverlap {
                a: "a".into(),
                b: "b".into()
            }
        );
    }

    #[test]
    fn degenerate_polygons_are_rejected() {
        let line = Polygon::new(vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]);
        assert!(matches!(
            Domain::new(line, names(3), vec![]),
            Err(MeshError::Degenerate { .. })
        ));
        let two = Polygon::new(vec![[0.0, 0.0], [1.0, 0.0]]);
        assert!(matches!(
            Domain::new(two, names(2), vec![]),
            Err(MeshError::Degenerate { .. })
        ));
    }
}
