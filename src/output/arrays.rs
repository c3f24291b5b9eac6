//! A model's results as plain columns, flat and row-major, for the Python package's NumPy arrays
//! (and any other caller that wants numbers rather than files): the same values the output files
//! hold, bit for bit, with names that say their units.

use crate::model::Model;

/// One named column: its values (row-major) and the number of components per row.
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    Float(Vec<f64>),
    Int(Vec<i64>),
}

/// A column of a table.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    pub name: &'static str,
    /// Components per row (1 for a scalar, 2 for a point, 4 for a stress).
    pub width: usize,
    pub values: Values,
}

/// The tables of a model: `nodes`, `zones`, `contacts`, `bolts` (one row per segment), `liners`
/// (one row per element), each a list of columns of equal row counts.
#[derive(Debug, Clone, Default)]
pub struct Tables {
    pub tables: Vec<(&'static str, Vec<Column>)>,
}

fn float(name: &'static str, width: usize, values: Vec<f64>) -> Column {
    Column {
        name,
        width,
        values: Values::Float(values),
    }
}

fn int(name: &'static str, width: usize, values: impl IntoIterator<Item = i64>) -> Column {
    Column {
        name,
        width,
        values: Values::Int(values.into_iter().collect()),
    }
}

fn pairs(v: &[[f64; 2]]) -> Vec<f64> {
    v.iter().flatten().copied().collect()
}

impl Tables {
    /// The tables of `model` as it is now.
    pub fn of(model: &Model) -> Tables {
        let (n, z, c, b) = (&model.nodes, &model.zones, &model.contacts, &model.blocks);
        let nodal = super::recovery::nodal_stress(model);
        let indicator = super::recovery::indicator(model, &nodal);
        let displacement: Vec<f64> = n
            .disp
            .iter()
            .zip(&n.origin)
            .flat_map(|(u, o)| [u[0] - o[0], u[1] - o[1]])
            .collect();
        let nodes = vec![
            float("position_m", 2, pairs(&n.pos)),
            float("displacement_m", 2, displacement),
            float("velocity_m_per_s", 2, pairs(&n.vel)),
            float(
                "stress_nodal_pa",
                4,
                nodal.iter().flatten().copied().collect(),
            ),
            int(
                "block",
                1,
                (0..n.len()).map(|i| b.block_of_node(i as u32) as i64),
            ),
            int("fixed", 1, n.fixed.iter().map(|&f| i64::from(f))),
        ];
        let zones = vec![
            int("nodes", 3, z.nodes.iter().flatten().map(|&i| i64::from(i))),
            float("stress_pa", 4, z.stress.iter().flatten().copied().collect()),
            int("state", 1, z.state.iter().map(|&s| i64::from(s))),
            int("block", 1, z.block.iter().map(|&i| i64::from(i))),
            int("material", 1, z.material.iter().map(|m| i64::from(m.0))),
            float("area_m2", 1, z.area.clone()),
            float("plastic_strain", 1, z.plastic.clone()),
            float("recovery_error_pa", 1, indicator),
            int(
                "excavated",
                1,
                z.block.iter().map(|&k| i64::from(b.is_removed(k as usize))),
            ),
        ];
        let pos = &n.pos;
        let point: Vec<f64> = (0..c.len())
            .flat_map(|k| {
                let [p, q] = b.edges[c.edge[k] as usize].map(|v| pos[v as usize]);
                let xi = c.xi[k];
                [(1.0 - xi) * p[0] + xi * q[0], (1.0 - xi) * p[1] + xi * q[1]]
            })
            .collect();
        let state = |f: fn(&crate::joint::JointState) -> f64| c.state.iter().map(f).collect();
        let contacts = vec![
            int("node", 1, c.node.iter().map(|&i| i64::from(i))),
            int(
                "edge_nodes",
                2,
                c.edge
                    .iter()
                    .flat_map(|&e| b.edges[e as usize].map(i64::from)),
            ),
            int("block", 1, c.block.iter().map(|&i| i64::from(i))),
            float("position_m", 2, point),
            float("length_m", 1, c.length.clone()),
            float("normal_stress_pa", 1, state(|s| s.normal)),
            float("shear_stress_pa", 1, state(|s| s.shear)),
            float("normal_displacement_m", 1, state(|s| s.normal_displacement)),
            float("shear_displacement_m", 1, state(|s| s.shear_displacement)),
            float("jrc_mobilized", 1, state(|s| s.jrc_mobilized)),
            int(
                "state",
                1,
                c.state.iter().map(|s| i64::from(super::vtu::state_code(s))),
            ),
            int("material", 1, c.material.iter().map(|&m| i64::from(m))),
        ];
        let (cables, liners) = (&model.supports.cables, &model.supports.liners);
        let mut bolts = support_columns(
            &cables.segment,
            &cables.pos,
            &cables.segment_group,
            &cables.active,
            &cables.axial,
        );
        bolts.push(int(
            "yielded",
            1,
            cables.plastic.iter().map(|&p| i64::from(p != 0.0)),
        ));
        let mut liner_rows = support_columns(
            &liners.element,
            &liners.pos,
            &liners.element_group,
            &liners.active,
            &liners.axial,
        );
        liner_rows.push(float(
            "moment_n_m_per_m",
            2,
            liners.moment.iter().flatten().copied().collect(),
        ));
        liner_rows.push(float(
            "shear_force_n_per_m",
            1,
            (0..liners.element.len()).map(|e| liners.shear(e)).collect(),
        ));
        liner_rows.push(float(
            "utilization",
            1,
            (0..liners.element.len())
                .map(|e| liners.utilization(e))
                .collect(),
        ));
        Tables {
            tables: vec![
                ("nodes", nodes),
                ("zones", zones),
                ("contacts", contacts),
                ("bolts", bolts),
                ("liners", liner_rows),
            ],
        }
    }
}

/// The columns bolts and liners share, one row per segment or element: its `ends_m` (x0, y0, x1,
/// y1 from `pos`), its `group`, whether that group is `installed`, its `axial_force_n_per_m`.
fn support_columns(
    elements: &[[u32; 2]],
    pos: &[[f64; 2]],
    groups: &[u32],
    active: &[bool],
    axial: &[f64],
) -> Vec<Column> {
    let ends = elements
        .iter()
        .flat_map(|e| {
            let (p, q) = (pos[e[0] as usize], pos[e[1] as usize]);
            [p[0], p[1], q[0], q[1]]
        })
        .collect();
    vec![
        float("ends_m", 4, ends),
        int("group", 1, groups.iter().map(|&g| i64::from(g))),
        int(
            "installed",
            1,
            groups.iter().map(|&g| i64::from(active[g as usize])),
        ),
        float("axial_force_n_per_m", 1, axial.to_vec()),
    ]
}

/// The names the integer columns stand for: zone materials, joint materials, bolt groups and
/// liner groups, each indexed by its number.
pub fn names(model: &Model) -> Vec<(&'static str, Vec<String>)> {
    vec![
        ("materials", model.materials.zone_names.clone()),
        ("joint_materials", model.materials.joint_names.clone()),
        ("bolt_groups", model.supports.cables.names.clone()),
        ("liner_groups", model.supports.liners.names.clone()),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every column of a table has as many rows as its table, and the zone stresses are the
    /// model's own values.
    #[test]
    fn the_tables_hold_the_models_values_in_rows_of_equal_count() {
        let scene = crate::scene::Scene::load(
            &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/jointed_tunnel.json"),
        )
        .unwrap();
        let built = crate::setup::setup(&scene).unwrap();
        let m = &built.model;
        let t = Tables::of(m);
        let rows = |name: &str| match name {
            "nodes" => m.nodes.len(),
            "zones" => m.zones.len(),
            "contacts" => m.contacts.len(),
            "bolts" => m.supports.cables.segment.len(),
            _ => m.supports.liners.element.len(),
        };
        for (table, columns) in &t.tables {
            for c in columns {
                let len = match &c.values {
                    Values::Float(v) => v.len(),
                    Values::Int(v) => v.len(),
                };
                assert_eq!(len, c.width * rows(table), "{table}.{}", c.name);
            }
        }
        let zones = &t.tables[1].1;
        let Values::Float(stress) = &zones[1].values else {
            panic!("stress is a float column")
        };
        assert_eq!(stress[4..8], m.zones.stress[1]);
        assert!(m.contacts.len() > 100);
    }
}
