//! Zone results as a binary XML unstructured grid (`.vtu`, vtkio): one triangle cell per zone (and
//! per outline triangle of a rigid or simple block) of the blocks not excavated, at its original
//! position, with stress, principal stresses, block, material, state and the recovery's error
//! indicator per cell, and displacement, velocity and the recovered nodal stress per point (the
//! output contract of `design.md`); each file's field data names its stage and the materials.

use vtkio::IOBuffer;
use vtkio::model::{
    Attribute, Attributes, ByteOrder, CellType, Cells, DataSet, UnstructuredGridPiece, Version,
    VertexNumbers, Vtk,
};

use super::{recovery, xml_attribute};
use crate::model::{Model, Stress};

/// What every grid file of a step says in its field data: its stage, and the names the integer
/// `material` columns stand for.
#[derive(Debug, Clone, Copy)]
pub struct Labels<'a> {
    /// The stage the step ends or belongs to, with its number in the run's order (`None`
    /// before the first).
    pub stage: Option<(usize, &'a str)>,
    /// Zone material names, indexed by the `material` cell data.
    pub materials: &'a [String],
    /// Joint material names, indexed by the joints' and contacts' `material` data.
    pub joint_materials: &'a [String],
}

impl<'a> Labels<'a> {
    /// The labels of `model` at stage `stage`.
    pub fn of(model: &'a Model, stage: Option<(usize, &'a str)>) -> Labels<'a> {
        Labels {
            stage,
            materials: &model.materials.zone_names,
            joint_materials: &model.materials.joint_names,
        }
    }
}

/// Principal stresses (Pa, tension positive) as (σ1, σ3): σ1 the most compressive (algebraically
/// smallest) and σ3 the least, among the in-plane pair (c ∓ r, c = (σxx+σyy)/2,
/// r = √(((σxx−σyy)/2)² + σxy²)) and σzz, as FLAC and UDEC order them.
pub fn principal(s: &Stress) -> (f64, f64) {
    let c = 0.5 * (s[0] + s[1]);
    let r = (0.25 * (s[0] - s[1]).powi(2) + s[3] * s[3]).sqrt();
    ((c - r).min(s[2]), (c + r).max(s[2]))
}

/// One cell of the zone grid: a zone of a deformable block, or an outline triangle of a rigid or
/// simple block (carrying its block's uniform stress; zero for a rigid block).
struct Cell {
    nodes: [u32; 3],
    stress: Stress,
    block: u32,
    material: u32,
    state: u8,
    /// The recovery's error indicator, Pa (0 for an outline triangle, whose stress is uniform).
    error: f64,
}

/// The zones, then the rigid and simple blocks' outline triangles, of the blocks not excavated;
/// `error`: each zone's indicator.
fn cells<'a>(model: &'a Model, error: &'a [f64]) -> impl Iterator<Item = Cell> + 'a {
    let (z, b) = (&model.zones, &model.bodies);
    let live = |block: u32| !model.blocks.is_removed(block as usize);
    let zones = (0..z.len())
        .filter(move |&i| live(z.block[i]))
        .map(move |i| Cell {
            nodes: z.nodes[i],
            stress: z.stress[i],
            block: z.block[i],
            material: z.material[i].0,
            state: z.state[i],
            error: error[i],
        });
    let outlines = b
        .outline
        .iter()
        .zip(&b.outline_body)
        .filter(move |(_, k)| live(b.block[**k as usize]))
        .map(move |(t, &k)| {
            let k = k as usize;
            Cell {
                nodes: *t,
                stress: b.stress[k],
                block: b.block[k],
                material: b.material[k].0,
                state: b.state[k],
                error: 0.0,
            }
        });
    zones.chain(outlines)
}

/// The full 3×3 tensor (9 components, row by row) of an in-plane stress with its σzz.
fn tensor(s: &Stress) -> [f64; 9] {
    [s[0], s[3], 0.0, s[3], s[1], 0.0, 0.0, 0.0, s[2]]
}

/// The zone grid of `model` as XML text.
pub fn zones_vtu(model: &Model, labels: &Labels) -> Result<Vec<u8>, vtkio::Error> {
    let nodes = &model.nodes;
    let nodal = recovery::nodal_stress(model);
    let error = recovery::indicator(model, &nodal);
    let cells: Vec<Cell> = cells(model, &error).collect();
    let points: Vec<f64> = nodes.pos.iter().flat_map(|p| [p[0], p[1], 0.0]).collect();
    let connectivity: Vec<u64> = cells
        .iter()
        .flat_map(|c| c.nodes)
        .map(|n| n as u64)
        .collect();
    let offsets: Vec<u64> = (1..=cells.len() as u64).map(|k| 3 * k).collect();
    let stress: Vec<f64> = cells.iter().flat_map(|c| tensor(&c.stress)).collect();
    let (sigma1, sigma3): (Vec<f64>, Vec<f64>) = cells.iter().map(|c| principal(&c.stress)).unzip();
    let (sigma1_nodal, sigma3_nodal): (Vec<f64>, Vec<f64>) = nodal.iter().map(principal).unzip();
    let int = |f: &dyn Fn(&Cell) -> i32| -> Vec<i32> { cells.iter().map(f).collect() };
    let vec3 = |v: &[[f64; 2]]| -> Vec<f64> { v.iter().flat_map(|p| [p[0], p[1], 0.0]).collect() };
    let mut point = vec![
        Attribute::generic("displacement", 3).with_data(
            nodes
                .disp
                .iter()
                .zip(&nodes.origin)
                .flat_map(|(u, o)| [u[0] - o[0], u[1] - o[1], 0.0])
                .collect::<Vec<f64>>(),
        ),
        Attribute::generic("velocity", 3).with_data(vec3(&nodes.vel)),
        Attribute::generic("stress_nodal", 9)
            .with_data(nodal.iter().flat_map(tensor).collect::<Vec<f64>>()),
        Attribute::generic("sigma1_nodal", 1).with_data(sigma1_nodal),
        Attribute::generic("sigma3_nodal", 1).with_data(sigma3_nodal),
    ];
    if let Some(peaks) = &model.peaks {
        point.push(Attribute::generic("ppv", 1).with_data(peaks.speed.clone()));
    }
    let piece = UnstructuredGridPiece {
        points: points.into(),
        cells: Cells {
            cell_verts: VertexNumbers::XML {
                connectivity,
                offsets,
            },
            types: vec![CellType::Triangle; cells.len()],
        },
        data: Attributes {
            point,
            cell: vec![
                Attribute::generic("stress", 9).with_data(stress),
                Attribute::generic("sigma1", 1).with_data(sigma1),
                Attribute::generic("sigma3", 1).with_data(sigma3),
                Attribute::generic("block", 1).with_data(int(&|c| c.block as i32)),
                Attribute::generic("material", 1).with_data(int(&|c| c.material as i32)),
                Attribute::generic("state", 1).with_data(int(&|c| c.state as i32)),
                Attribute::generic("recovery_error", 1)
                    .with_data(cells.iter().map(|c| c.error).collect::<Vec<f64>>()),
            ],
        },
    };
    xml_of(piece, labels)
}

/// Contacts as vertex cells at their points (original positions), with joint stresses and
/// displacements and the state (0 elastic, 1 slipping, 2 open) as point data.
pub fn contacts_vtu(model: &Model, labels: &Labels) -> Result<Vec<u8>, vtkio::Error> {
    let (c, pos) = (&model.contacts, &model.nodes.pos);
    let n = c.len();
    let points: Vec<f64> = (0..n)
        .flat_map(|k| {
            let [a, b] = model.blocks.edges[c.edge[k] as usize].map(|v| pos[v as usize]);
            let xi = c.xi[k];
            [
                (1.0 - xi) * a[0] + xi * b[0],
                (1.0 - xi) * a[1] + xi * b[1],
                0.0,
            ]
        })
        .collect();
    let column = |f: &dyn Fn(&crate::joint::JointState) -> f64| -> Vec<f64> {
        c.state.iter().map(f).collect()
    };
    let state: Vec<i32> = c.state.iter().map(state_code).collect();
    let piece = UnstructuredGridPiece {
        points: points.into(),
        cells: Cells {
            cell_verts: VertexNumbers::XML {
                connectivity: (0..n as u64).collect(),
                offsets: (1..=n as u64).collect(),
            },
            types: vec![CellType::Vertex; n],
        },
        data: Attributes {
            point: vec![
                Attribute::generic("normal_stress", 1).with_data(column(&|s| s.normal)),
                Attribute::generic("shear_stress", 1).with_data(column(&|s| s.shear)),
                Attribute::generic("normal_displacement", 1)
                    .with_data(column(&|s| s.normal_displacement)),
                Attribute::generic("shear_displacement", 1)
                    .with_data(column(&|s| s.shear_displacement)),
                Attribute::generic("state", 1).with_data(state),
            ],
            cell: vec![],
        },
    };
    xml_of(piece, labels)
}

/// A joint state as the output's code: 0 elastic, 1 slipping, 2 open (open wins).
pub(super) fn state_code(s: &crate::joint::JointState) -> i32 {
    if s.flags & crate::joint::OPEN != 0 {
        2
    } else if s.flags & crate::joint::SLIPPING != 0 {
        1
    } else {
        0
    }
}

/// One piece as binary XML text, with the positions note and `labels` in its field data.
pub(super) fn xml_of(
    piece: UnstructuredGridPiece,
    labels: &Labels,
) -> Result<Vec<u8>, vtkio::Error> {
    all_finite(&piece)?;
    let vtk = Vtk {
        version: Version::new((1, 0)),
        title: String::new(),
        byte_order: ByteOrder::LittleEndian,
        data: DataSet::inline(piece),
        file_path: None,
    };
    let mut xml = Vec::new();
    vtk.write_xml(&mut xml)?;
    Ok(with_cell_count(with_field_data(xml, labels)))
}

/// An error naming the first array of `piece` (its points' positions, or a point or cell field)
/// with a value that is not finite: a grid file never holds one, and a run whose state gives one
/// fails, naming it, rather than report that state (an in-situ σzz of 1e308 Pa had converged, its
/// nodal stress infinite).
fn all_finite(piece: &UnstructuredGridPiece) -> Result<(), vtkio::Error> {
    let arrays = std::iter::once(("positions", &piece.points)).chain(
        (piece.data.point.iter().chain(&piece.data.cell)).filter_map(|a| match a {
            Attribute::DataArray(d) => Some((d.name.as_str(), &d.data)),
            Attribute::Field { .. } => None,
        }),
    );
    for (name, data) in arrays {
        if let IOBuffer::F64(values) = data
            && let Some(i) = values.iter().position(|v| !v.is_finite())
        {
            return Err(vtkio::Error::IO(std::io::Error::other(format!(
                "the state is not finite: value {i} of the output field '{name}' is {}",
                values[i]
            ))));
        }
    }
    Ok(())
}

/// vtkio writes a piece without cells with the polydata counts (`NumberOfVerts`, `NumberOfLines`,
/// …) instead of `NumberOfCells`, which VTK's reader requires of an unstructured grid and meshio
/// looks up: write that piece's header as `NumberOfPoints`, `NumberOfCells="0"`.
fn with_cell_count(xml: Vec<u8>) -> Vec<u8> {
    const OPEN: &[u8] = b"<Piece ";
    let Some(at) = xml.windows(OPEN.len()).position(|w| w == OPEN) else {
        return xml;
    };
    let Some(len) = xml[at..].iter().position(|&b| b == b'>') else {
        return xml;
    };
    let header = String::from_utf8_lossy(&xml[at..at + len]).into_owned();
    if header.contains("NumberOfCells") {
        return xml;
    }
    let points = header
        .split("NumberOfPoints=\"")
        .nth(1)
        .and_then(|rest| rest.split('"').next())
        .unwrap_or("0");
    let fixed = format!("<Piece NumberOfPoints=\"{points}\" NumberOfCells=\"0\"");
    [&xml[..at], fixed.as_bytes(), &xml[at + len..]].concat()
}

/// vtkio writes no field data; add it right after the `<UnstructuredGrid>` tag, as one-value
/// Int32 arrays: `deformed_positions = 0` (cells are drawn at original positions), and the names
/// the integer columns stand for, each an array named after it holding its number:
/// `stage: <name>` (the stage's number in the run's order, as `stage_index`; no stage before the
/// first), `material: <name>` and `joint_material: <name>` (each material's id). Names go in the
/// arrays' names because meshio reads no string arrays (`type="String"`, which ParaView reads):
/// ParaView's spreadsheet of the field data shows them as its column heads.
fn with_field_data(xml: Vec<u8>, labels: &Labels) -> Vec<u8> {
    const TAG: &[u8] = b"<UnstructuredGrid>";
    let mut field = String::from("<FieldData>");
    field += &int_array("deformed_positions", 0);
    if let Some((i, name)) = labels.stage {
        field += &int_array("stage_index", i as i32);
        field += &int_array(&format!("stage: {name}"), i as i32);
    }
    for (kind, names) in [
        ("material", labels.materials),
        ("joint_material", labels.joint_materials),
    ] {
        for (id, name) in names.iter().enumerate() {
            field += &int_array(&format!("{kind}: {name}"), id as i32);
        }
    }
    field += "</FieldData>";
    match xml.windows(TAG.len()).position(|w| w == TAG) {
        Some(at) => {
            let cut = at + TAG.len();
            [&xml[..cut], field.as_bytes(), &xml[cut..]].concat()
        }
        None => xml,
    }
}

/// A field data array of one Int32 `value` named `name`.
fn int_array(name: &str, value: i32) -> String {
    format!(
        "<DataArray type=\"Int32\" Name=\"{}\" NumberOfTuples=\"1\" format=\"ascii\">{value}</DataArray>",
        xml_attribute(name)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid without cells (a contacts file once every contact is gone) still says
    /// `NumberOfCells="0"`, which VTK's reader and meshio require.
    #[test]
    fn a_piece_without_cells_names_its_cell_count() {
        let piece = UnstructuredGridPiece {
            points: Vec::<f64>::new().into(),
            cells: Cells {
                cell_verts: VertexNumbers::XML {
                    connectivity: vec![],
                    offsets: vec![],
                },
                types: vec![],
            },
            data: Attributes {
                point: vec![Attribute::generic("state", 1).with_data(Vec::<i32>::new())],
                cell: vec![],
            },
        };
        let labels = Labels {
            stage: None,
            materials: &[],
            joint_materials: &[],
        };
        let xml = String::from_utf8(xml_of(piece, &labels).unwrap()).unwrap();
        assert!(
            xml.contains("<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\">"),
            "{xml}"
        );
        assert!(!xml.contains("NumberOfVerts"), "{xml}");
    }

    #[test]
    fn principal_stresses_order_compression_first() {
        let (s1, s3) = principal(&[-10.0, -20.0, -7.5, 0.0]);
        assert_eq!((s1, s3), (-20.0, -7.5));
        let (s1, s3) = principal(&[0.0, 0.0, 0.0, 5.0]);
        assert_eq!((s1, s3), (-5.0, 5.0));
    }
}
